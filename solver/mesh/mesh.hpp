// The body's P1 mesh: points, positively oriented simplices (triangles in 2D, tetrahedra in 3D:
// the dimension is data, as in GetFEM), the contact nodes (ordered by x) and the clamp's nodes
// (docs/contract.md, "The model"). Two sources make it: the structured rectangle (0, W) x (0, H)
// of the paper (make_structured_mesh) and a Gmsh file (gmsh_mesh.hpp). y is the foundation's
// normal in both dimensions; x (and z in 3D) lie in its plane.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace contactbody {

struct Point {
    double x, y, z = 0;  // z: 0 in 2D
};

struct Mesh {
    int dim = 2;  // 2: triangles, plane strain; 3: tetrahedra
    std::vector<Point> points;
    // dim + 1 nodes per cell, cell after cell: counter-clockwise triangles, or tetrahedra of
    // positive volume (det[p1 - p0, p2 - p0, p3 - p0] > 0).
    std::vector<int> cells;
    std::vector<int> contact_nodes;  // may touch the foundation, ordered by x (z, y)
    std::vector<int> top_nodes;      // the clamp (the rectangle's top edge), ascending
    // Measure of the foundation each contact node carries: a share of its contact facets'
    // extent projected on the foundation's plane (length along x in 2D, area in x-z in 3D).
    // Nodal contact forces divided by it are pressures. Zero for a contact node whose facets
    // all stand perpendicular to the foundation.
    std::vector<double> contact_shares;
    // Each contact node's height above the lowest one (0 on a flat contact boundary).
    std::vector<double> contact_heights;
    // The bounding box, the lowest contact node's height (where the foundation is, less
    // initial_gap) and the clamp's (its highest node's).
    double x_min = 0, x_max = 0, y_min = 0, y_max = 0, z_min = 0, z_max = 0, contact_y = 0, clamp_y = 0;
    // The rectangle's cells (0 for a mesh read from a file): where the rectangle is meant (its
    // error messages, the stability map's look-up).
    int nx = 0, ny = 0;
    std::string source;        // "the rectangle", or the file it was read from
    uint64_t file_digest = 0;  // of the file's bytes (gmsh_file_digest): a changed file is another mesh

    int num_nodes() const { return static_cast<int>(points.size()); }
    int num_dofs() const { return dim * num_nodes(); }
    int nodes_per_cell() const { return dim + 1; }
    size_t num_cells() const { return cells.size() / static_cast<size_t>(dim + 1); }
    const int* cell(size_t e) const { return cells.data() + e * static_cast<size_t>(dim + 1); }
    // dof numbering: dim * node + component (0 = x, 1 = y, 2 = z).
    int dof(int node, int component) const { return dim * node + component; }
    int component(int dof) const { return dof % dim; }
    // Tangents of the foundation's plane: x (and z in 3D); tangent t's dof is tangent_component(t)'s.
    int tangents() const { return dim - 1; }
    static constexpr int normal = 1;  // the component normal to the foundation (y)
    const Point& point(int n) const { return points[static_cast<size_t>(n)]; }
    double width() const { return x_max - x_min; }
    double height() const { return y_max - y_min; }
    // From the foundation's height to the clamp's: the paper's initial profile's span.
    double clamp_height() const { return clamp_y - contact_y; }
    double edge_share(size_t i) const { return contact_shares[i]; }
    bool is_rectangle() const { return nx > 0; }
    // Messages' units: a 2D body's energies and forces are per metre of thickness.
    const char* energy_unit() const { return dim == 2 ? "J/m" : "J"; }
    const char* force_unit() const { return dim == 2 ? "N/m" : "N"; }
};

// Cells split as GetFEM's "regular simplices": diagonal (i,j)-(i+1,j+1) when i+j is even,
// (i+1,j)-(i,j+1) when odd, so that uniformly refined meshes nest. Node (i, j) is j (nx+1) + i.
Mesh make_structured_mesh(double width, double height, int nx, int ny);

// What follows from points, cells and the two node lists (both sources call it): orders the
// contact nodes by x (then z, then y), computes their shares and heights, the bounding box and
// the clamp's height. `contact_facets` are the contact boundary's facets, dim nodes each, one
// after the other (segments in 2D, triangles in 3D), for the shares.
void finish_mesh(Mesh& mesh, const std::vector<int>& contact_facets);

}  // namespace contactbody
