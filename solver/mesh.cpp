#include "mesh.hpp"

#include <stdexcept>

namespace contactbody {

Mesh make_structured_mesh(double width, double height, int nx, int ny) {
    if (nx < 1 || ny < 1) throw std::invalid_argument("mesh needs nx >= 1 and ny >= 1");
    Mesh m;
    m.width = width;
    m.height = height;
    m.nx = nx;
    m.ny = ny;
    m.triangles.reserve(2 * static_cast<size_t>(nx) * ny);
    for (int j = 0; j < ny; ++j) {
        for (int i = 0; i < nx; ++i) {
            const int n00 = m.node(i, j), n10 = m.node(i + 1, j);
            const int n01 = m.node(i, j + 1), n11 = m.node(i + 1, j + 1);
            if ((i + j) % 2 == 0) {
                m.triangles.push_back({n00, n10, n11});
                m.triangles.push_back({n00, n11, n01});
            } else {
                m.triangles.push_back({n00, n10, n01});
                m.triangles.push_back({n10, n11, n01});
            }
        }
    }
    for (int i = 0; i <= nx; ++i) {
        m.contact_nodes.push_back(m.node(i, 0));
        m.top_nodes.push_back(m.node(i, ny));
    }
    return m;
}

}  // namespace contactbody
