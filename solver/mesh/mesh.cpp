#include "mesh/mesh.hpp"

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
    m.cells.reserve(6 * static_cast<size_t>(nx) * ny);
    for (int j = 0; j < ny; ++j) {
        for (int i = 0; i < nx; ++i) {
            const int n00 = node(i, j), n10 = node(i + 1, j);
            const int n01 = node(i, j + 1), n11 = node(i + 1, j + 1);
            if ((i + j) % 2 == 0) {
                m.cells.insert(m.cells.end(), {n00, n10, n11, n00, n11, n01});
            } else {
                m.cells.insert(m.cells.end(), {n00, n10, n01, n10, n11, n01});
            }
        }
    }
    std::vector<int> bottom;
    for (int i = 0; i <= nx; ++i) {
        m.contact_nodes.push_back(node(i, 0));
        m.top_nodes.push_back(node(i, ny));
        if (i < nx) bottom.insert(bottom.end(), {node(i, 0), node(i + 1, 0)});
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

void finish_mesh(Mesh& m, const std::vector<int>& contact_facets) {
    if (m.points.empty() || m.contact_nodes.empty() || m.top_nodes.empty())
        throw std::invalid_argument("a mesh needs points, contact nodes and clamp nodes");
    const auto range = [&](double Point::* c, double& low, double& high) {
        const auto [lo, hi] = std::minmax_element(
            m.points.begin(), m.points.end(), [c](const Point& a, const Point& b) { return a.*c < b.*c; });
        low = (*lo).*c;
        high = (*hi).*c;
    };
    range(&Point::x, m.x_min, m.x_max);
    range(&Point::y, m.y_min, m.y_max);
    range(&Point::z, m.z_min, m.z_max);
    // Contact nodes by x, then z (3D), then y (a piece of the contact boundary perpendicular to
    // the foundation).
    std::stable_sort(m.contact_nodes.begin(), m.contact_nodes.end(), [&](int a, int b) {
        const Point &p = m.point(a), &q = m.point(b);
        if (p.x != q.x) return p.x < q.x;
        if (p.z != q.z) return p.z < q.z;
        return p.y < q.y;
    });
    std::sort(m.top_nodes.begin(), m.top_nodes.end());
    m.contact_y = m.point(m.contact_nodes.front()).y;
    for (int n : m.contact_nodes) m.contact_y = std::min(m.contact_y, m.point(n).y);
    m.clamp_y = m.point(m.top_nodes.front()).y;
    for (int n : m.top_nodes) m.clamp_y = std::max(m.clamp_y, m.point(n).y);
    m.contact_heights.clear();
    for (int n : m.contact_nodes) m.contact_heights.push_back(m.point(n).y - m.contact_y);
    if (m.contact_shares.empty()) {
        // An equal share (1/dim) of each contact facet's extent projected on the foundation's
        // plane to each of its nodes: half a segment's x extent, a third of a triangle's x-z area.
        std::vector<double> share(m.points.size(), 0.0);
        const size_t per = static_cast<size_t>(m.dim);
        for (size_t f = 0; f + per <= contact_facets.size(); f += per) {
            const int* n = contact_facets.data() + f;
            const Point &a = m.point(n[0]), &b = m.point(n[1]);
            double part;
            if (m.dim == 2) {
                part = 0.5 * std::abs(b.x - a.x);
            } else {
                const Point& c = m.point(n[2]);
                part = std::abs((b.x - a.x) * (c.z - a.z) - (c.x - a.x) * (b.z - a.z)) / 6;
            }
            for (size_t k = 0; k < per; ++k) share[static_cast<size_t>(n[k])] += part;
        }
        for (int n : m.contact_nodes) m.contact_shares.push_back(share[static_cast<size_t>(n)]);
    }
}

}  // namespace contactbody
