#include "mesh.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>

namespace contactbody {

Mesh make_structured_mesh(double width, double height, int nx, int ny) {
    if (nx < 1 || ny < 1) throw std::invalid_argument("mesh needs nx >= 1 and ny >= 1");
    Mesh m;
    m.nx = nx;
    m.ny = ny;
    m.source = "the rectangle";
    const auto node = [nx](int i, int j) { return j * (nx + 1) + i; };
    m.points.reserve(static_cast<size_t>(nx + 1) * (ny + 1));
    for (int j = 0; j <= ny; ++j)
        for (int i = 0; i <= nx; ++i) m.points.push_back({i * width / nx, j * height / ny});
    m.triangles.reserve(2 * static_cast<size_t>(nx) * ny);
    for (int j = 0; j < ny; ++j) {
        for (int i = 0; i < nx; ++i) {
            const int n00 = node(i, j), n10 = node(i + 1, j);
            const int n01 = node(i, j + 1), n11 = node(i + 1, j + 1);
            if ((i + j) % 2 == 0) {
                m.triangles.push_back({n00, n10, n11});
                m.triangles.push_back({n00, n11, n01});
            } else {
                m.triangles.push_back({n00, n10, n01});
                m.triangles.push_back({n10, n11, n01});
            }
        }
    }
    std::vector<std::array<int, 2>> bottom;
    for (int i = 0; i <= nx; ++i) {
        m.contact_nodes.push_back(node(i, 0));
        m.top_nodes.push_back(node(i, ny));
        if (i < nx) bottom.push_back({node(i, 0), node(i + 1, 0)});
    }
    // The cell width, half of it at the corners: the shares as the rectangle always had them.
    const double hx = width / nx;
    for (int i = 0; i <= nx; ++i) m.contact_shares.push_back((i == 0 || i == nx ? 0.5 : 1.0) * hx);
    finish_mesh(m, bottom);
    // The parameters themselves, not nx * (width / nx): the rectangle's sizes as given.
    m.x_max = width;
    m.y_max = m.clamp_y = height;
    return m;
}

void finish_mesh(Mesh& m, const std::vector<std::array<int, 2>>& contact_lines) {
    if (m.points.empty() || m.contact_nodes.empty() || m.top_nodes.empty())
        throw std::invalid_argument("a mesh needs points, contact nodes and clamp nodes");
    const auto [xmin, xmax] = std::minmax_element(m.points.begin(), m.points.end(),
                                                  [](const Point& a, const Point& b) { return a.x < b.x; });
    const auto [ymin, ymax] = std::minmax_element(m.points.begin(), m.points.end(),
                                                  [](const Point& a, const Point& b) { return a.y < b.y; });
    m.x_min = xmin->x;
    m.x_max = xmax->x;
    m.y_min = ymin->y;
    m.y_max = ymax->y;
    // Contact nodes by x (then y, for a vertical piece of the contact boundary).
    std::stable_sort(m.contact_nodes.begin(), m.contact_nodes.end(), [&](int a, int b) {
        const Point &p = m.point(a), &q = m.point(b);
        return p.x < q.x || (p.x == q.x && p.y < q.y);
    });
    std::sort(m.top_nodes.begin(), m.top_nodes.end());
    m.contact_y = m.point(m.contact_nodes.front()).y;
    for (int n : m.contact_nodes) m.contact_y = std::min(m.contact_y, m.point(n).y);
    m.clamp_y = m.point(m.top_nodes.front()).y;
    for (int n : m.top_nodes) m.clamp_y = std::max(m.clamp_y, m.point(n).y);
    m.contact_heights.clear();
    for (int n : m.contact_nodes) m.contact_heights.push_back(m.point(n).y - m.contact_y);
    if (m.contact_shares.empty()) {  // half of each contact line's extent along x to either end
        std::vector<double> share(m.points.size(), 0.0);
        for (const auto& line : contact_lines) {
            const double half = 0.5 * std::abs(m.point(line[1]).x - m.point(line[0]).x);
            share[static_cast<size_t>(line[0])] += half;
            share[static_cast<size_t>(line[1])] += half;
        }
        for (int n : m.contact_nodes) m.contact_shares.push_back(share[static_cast<size_t>(n)]);
    }
}

}  // namespace contactbody
