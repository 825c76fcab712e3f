// A body's mesh from a Gmsh file: MSH 4.1 or 2.2, ASCII (the format is Gmsh's documented one;
// Gmsh itself is not linked in: its licence does not fit an FMU). The file holds first-order
// triangles in the x-y plane, in metres, and two physical groups of boundary lines by name:
// "contact" (may touch the foundation) and "clamp" (driven as the rectangle's top edge). A
// node in both is the clamp's.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "mesh/mesh.hpp"

namespace contactbody {

// Throws std::invalid_argument "mesh FILE, line N: what is wrong" (line 0: the file as a
// whole) for anything it cannot take: no file, no regular file (a folder, a device, a pipe),
// a file larger than a mesh of max_nodes nodes needs, a binary or unknown version, an element other
// than points, lines and first-order triangles, a missing group, a degenerate or inverted
// triangle, a node of no triangle, a part not connected to the clamp, a non-finite or
// out-of-plane coordinate, more than max_nodes nodes, a contact node that carries no length of
// the foundation. `notes` receives what was done that the user should know (for the log).
Mesh read_gmsh_mesh(const std::string& path, long max_nodes, std::vector<std::string>& notes);

// A digest of the file's bytes (FNV-1a), the one read_gmsh_mesh keeps in Mesh::file_digest: a
// body built from the file is reused over a reset only while the file is unchanged. 0 if the
// file cannot be read (as read_gmsh_mesh with max_nodes would refuse it).
uint64_t gmsh_file_digest(const std::string& path, long max_nodes);

}  // namespace contactbody
