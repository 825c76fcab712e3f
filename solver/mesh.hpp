// Structured P1 mesh of the rectangle (0, W) x (0, H) (docs/contract.md, "The model").
#pragma once

#include <array>
#include <cstddef>
#include <vector>

namespace contactbody {

struct Point {
    double x, y;
};

struct Mesh {
    double width = 0, height = 0;
    int nx = 0, ny = 0;
    std::vector<std::array<int, 3>> triangles;  // counter-clockwise node triples
    std::vector<int> contact_nodes;             // y = 0, ordered by i (corners included)
    std::vector<int> top_nodes;                 // y = H, ordered by i

    int num_nodes() const { return (nx + 1) * (ny + 1); }
    int num_dofs() const { return 2 * num_nodes(); }
    int node(int i, int j) const { return j * (nx + 1) + i; }
    Point point(int n) const {
        return {(n % (nx + 1)) * width / nx, (n / (nx + 1)) * height / ny};
    }
    double hx() const { return width / nx; }
    // Length of the bottom edge carried by contact node i (half a cell at the corners): nodal
    // contact forces divided by it are pressures.
    double edge_share(size_t i) const {
        return (i == 0 || i + 1 == contact_nodes.size() ? 0.5 : 1.0) * hx();
    }
};

// dof numbering: 2*node + component (0 = x, 1 = y)
inline int dof_x(int node) { return 2 * node; }
inline int dof_y(int node) { return 2 * node + 1; }

// Cells split as GetFEM's "regular simplices": diagonal (i,j)-(i+1,j+1) when i+j is even,
// (i+1,j)-(i,j+1) when odd, so that uniformly refined meshes nest.
Mesh make_structured_mesh(double width, double height, int nx, int ny);

}  // namespace contactbody
