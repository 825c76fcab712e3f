// The body's P1 mesh: points, counter-clockwise triangles, the contact nodes (ordered by x) and
// the clamp's nodes (docs/contract.md, "The model"). Two sources make it: the structured
// rectangle (0, W) x (0, H) of the paper (make_structured_mesh) and a Gmsh file (gmsh_mesh.hpp).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace contactbody {

struct Point {
    double x, y;
};

struct Mesh {
    std::vector<Point> points;
    std::vector<std::array<int, 3>> triangles;  // counter-clockwise node triples
    std::vector<int> contact_nodes;             // may touch the foundation, ordered by x
    std::vector<int> top_nodes;                 // the clamp (the rectangle's top edge), ascending
    // Length of the foundation each contact node carries (half its neighbours' x spacing along
    // the contact boundary): nodal contact forces divided by it are pressures per unit length
    // of the foundation. Zero for a contact node whose boundary lines are all vertical.
    std::vector<double> contact_shares;
    // Each contact node's height above the lowest one (0 on a flat contact boundary).
    std::vector<double> contact_heights;
    // The bounding box, the lowest contact node's height (where the foundation is, less
    // initial_gap) and the clamp's (its highest node's).
    double x_min = 0, x_max = 0, y_min = 0, y_max = 0, contact_y = 0, clamp_y = 0;
    // The rectangle's cells (0 for a mesh read from a file): where the rectangle is meant (its
    // error messages, the stability map's look-up).
    int nx = 0, ny = 0;
    std::string source;  // "the rectangle", or the file it was read from
    uint64_t file_digest = 0;  // of the file's bytes (gmsh_file_digest): a changed file is another mesh

    int num_nodes() const { return static_cast<int>(points.size()); }
    int num_dofs() const { return 2 * num_nodes(); }
    const Point& point(int n) const { return points[static_cast<size_t>(n)]; }
    double width() const { return x_max - x_min; }
    double height() const { return y_max - y_min; }
    // From the foundation's height to the clamp's: the paper's initial profile's span.
    double clamp_height() const { return clamp_y - contact_y; }
    double edge_share(size_t i) const { return contact_shares[i]; }
    bool is_rectangle() const { return nx > 0; }
};

// dof numbering: 2*node + component (0 = x, 1 = y)
inline int dof_x(int node) { return 2 * node; }
inline int dof_y(int node) { return 2 * node + 1; }

// Cells split as GetFEM's "regular simplices": diagonal (i,j)-(i+1,j+1) when i+j is even,
// (i+1,j)-(i,j+1) when odd, so that uniformly refined meshes nest. Node (i, j) is j (nx+1) + i.
Mesh make_structured_mesh(double width, double height, int nx, int ny);

// What follows from points, triangles and the two node lists (both sources call it): orders
// the contact nodes by x, computes their shares and heights, the bounding box and the clamp's
// height. `lines` are the contact boundary's segments (node pairs), for the shares.
void finish_mesh(Mesh& mesh, const std::vector<std::array<int, 2>>& contact_lines);

}  // namespace contactbody
