#include "assembly.hpp"

#include "text.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include <Eigen/Dense>
#include <Eigen/SparseCholesky>
#include <stdexcept>
#include <vector>

namespace contactbody {

using Triplets = std::vector<Eigen::Triplet<double>>;

namespace {

double signed_area(const Point& a, const Point& b, const Point& c) {
    return 0.5 * ((b.x - a.x) * (c.y - a.y) - (c.x - a.x) * (b.y - a.y));
}

SparseMatrix from_triplets(int n, const Triplets& t) {
    SparseMatrix m(n, n);
    m.setFromTriplets(t.begin(), t.end());
    m.makeCompressed();
    return m;
}

// Coordinates centred and scaled to O(1): the six moment constraints span the same space
// under any affine change of coordinates, and C C^T is far better conditioned this way.
std::vector<Point> normalized_points(const Mesh& mesh) {
    std::vector<Point> p(mesh.num_nodes());
    for (int n = 0; n < mesh.num_nodes(); ++n) {
        const Point q = mesh.point(n);
        p[n] = {2 * (q.x - mesh.x_min) / mesh.width() - 1, 2 * (q.y - mesh.y_min) / mesh.height() - 1};
    }
    return p;
}

std::string mesh_name(const Mesh& mesh) {
    return mesh.is_rectangle() ? "the rectangle" : "the mesh " + mesh.source;
}

// Row of the symmetric-form constraint matrix for entry (i, j).
Eigen::Matrix<double, 6, 1> moment_row(const Point& pi, const Point& pj) {
    Eigen::Matrix<double, 6, 1> c;
    c << 1, 0.5 * (pi.x + pj.x), 0.5 * (pi.y + pj.y), pi.x * pj.x,
        0.5 * (pi.x * pj.y + pj.x * pi.y), pi.y * pj.y;
    return c;
}

}  // namespace

SparseMatrix stiffness_matrix(const Mesh& mesh, double lambda, double mu) {
    Eigen::Matrix3d D;
    D << lambda + 2 * mu, lambda, 0, lambda, lambda + 2 * mu, 0, 0, 0, mu;
    Triplets t;
    t.reserve(mesh.triangles.size() * 36);
    for (const auto& tri : mesh.triangles) {
        const Point p[3] = {mesh.point(tri[0]), mesh.point(tri[1]), mesh.point(tri[2])};
        const double area = signed_area(p[0], p[1], p[2]);
        Eigen::Matrix<double, 3, 6> B = Eigen::Matrix<double, 3, 6>::Zero();
        for (int a = 0; a < 3; ++a) {
            const Point& q1 = p[(a + 1) % 3];
            const Point& q2 = p[(a + 2) % 3];
            const double dNdx = (q1.y - q2.y) / (2 * area);
            const double dNdy = (q2.x - q1.x) / (2 * area);
            B(0, 2 * a) = dNdx;
            B(1, 2 * a + 1) = dNdy;
            B(2, 2 * a) = dNdy;
            B(2, 2 * a + 1) = dNdx;
        }
        const Eigen::Matrix<double, 6, 6> Ke = area * B.transpose() * D * B;
        for (int a = 0; a < 6; ++a)
            for (int b = 0; b < 6; ++b)
                t.emplace_back(2 * tri[a / 2] + a % 2, 2 * tri[b / 2] + b % 2, Ke(a, b));
    }
    return from_triplets(mesh.num_dofs(), t);
}

StrainEnergy::StrainEnergy(const Mesh& mesh, double lambda, double mu) : lambda_(lambda), mu_(mu) {
    elements_.reserve(mesh.triangles.size());
    for (const auto& tri : mesh.triangles) {
        const Point p[3] = {mesh.point(tri[0]), mesh.point(tri[1]), mesh.point(tri[2])};
        const double area = signed_area(p[0], p[1], p[2]);
        // dN_a/dx = (y_{a+1} - y_{a+2}) / 2 area, dN_a/dy = (x_{a+2} - x_{a+1}) / 2 area
        elements_.push_back({tri, (p[2].y - p[0].y) / (2 * area), (p[0].x - p[2].x) / (2 * area),
                             (p[0].y - p[1].y) / (2 * area), (p[1].x - p[0].x) / (2 * area), area});
    }
}

double StrainEnergy::operator()(const Eigen::VectorXd& u) const {
    double energy = 0;
    for (const Element& e : elements_) {
        const int n0 = e.nodes[0], n1 = e.nodes[1], n2 = e.nodes[2];
        const double ux1 = u[dof_x(n1)] - u[dof_x(n0)], uy1 = u[dof_y(n1)] - u[dof_y(n0)];
        const double ux2 = u[dof_x(n2)] - u[dof_x(n0)], uy2 = u[dof_y(n2)] - u[dof_y(n0)];
        const double exx = e.dx1 * ux1 + e.dx2 * ux2, eyy = e.dy1 * uy1 + e.dy2 * uy2;
        const double gamma = e.dy1 * ux1 + e.dy2 * ux2 + e.dx1 * uy1 + e.dx2 * uy2;
        const double trace = exx + eyy, shear = exx - eyy;
        energy += e.area * (0.5 * (lambda_ + mu_) * trace * trace +
                            0.5 * mu_ * (shear * shear + gamma * gamma));
    }
    return energy;
}

SparseMatrix scalar_mass_matrix(const Mesh& mesh, double rho) {
    Triplets t;
    t.reserve(mesh.triangles.size() * 9);
    for (const auto& tri : mesh.triangles) {
        const double area =
            signed_area(mesh.point(tri[0]), mesh.point(tri[1]), mesh.point(tri[2]));
        for (int a = 0; a < 3; ++a)
            for (int b = 0; b < 3; ++b)
                t.emplace_back(tri[a], tri[b], rho * area / 12.0 * (a == b ? 2.0 : 1.0));
    }
    return from_triplets(mesh.num_nodes(), t);
}

std::array<double, 6> mass_moments(const Mesh& mesh, const SparseMatrix& m) {
    Eigen::Matrix<double, 6, 1> s = Eigen::Matrix<double, 6, 1>::Zero();
    for (int j = 0; j < m.outerSize(); ++j)
        for (SparseMatrix::InnerIterator it(m, j); it; ++it)
            s += it.value() * moment_row(mesh.point(it.row()), mesh.point(it.col()));
    return {s[0], s[1], s[2], s[3], s[4], s[5]};
}

namespace {

// The kept entries corrected to the target moments: m <- m - W C^T (C W C^T)^{-1} (C m - d),
// the least change in sum (change_e^2 / w_e). w_e = 1 is the least change in the Frobenius
// norm (KLR's); w_e = m_e the least change relative to each entry, which changes entry e by
// the fraction c_e . y of itself, whatever its size. `largest_fraction`: max |c_e . y|.
Triplets corrected_entries(const Triplets& kept, const std::vector<Point>& p,
                           const Eigen::Matrix<double, 6, 1>& target, bool relative,
                           double& largest_fraction) {
    Eigen::Matrix<double, 6, 6> CWCt = Eigen::Matrix<double, 6, 6>::Zero();
    Eigen::Matrix<double, 6, 1> Cm = Eigen::Matrix<double, 6, 1>::Zero();
    for (const auto& e : kept) {
        const auto c = moment_row(p[e.row()], p[e.col()]);
        CWCt += (relative ? e.value() : 1.0) * c * c.transpose();
        Cm += e.value() * c;
    }
    const Eigen::Matrix<double, 6, 1> y = CWCt.ldlt().solve(Cm - target);
    Triplets corrected;
    corrected.reserve(kept.size());
    largest_fraction = 0;
    for (const auto& e : kept) {
        const double cy = moment_row(p[e.row()], p[e.col()]).dot(y);
        corrected.emplace_back(e.row(), e.col(), e.value() - (relative ? e.value() : 1.0) * cy);
        largest_fraction = std::max(largest_fraction, std::abs(relative ? cy : cy / e.value()));
    }
    return corrected;
}

// Whether the entries (which hold no contact node) are positive definite on the other nodes.
bool positive_definite_off_contact(const Triplets& entries, const std::vector<char>& is_contact) {
    std::vector<int> position(is_contact.size(), -1);
    int n = 0;
    for (size_t k = 0; k < is_contact.size(); ++k)
        if (!is_contact[k]) position[k] = n++;
    Triplets restricted;
    restricted.reserve(entries.size());
    for (const auto& e : entries)
        restricted.emplace_back(position[e.row()], position[e.col()], e.value());
    Eigen::SimplicialLLT<SparseMatrix> llt(from_triplets(n, restricted));
    return llt.info() == Eigen::Success;
}

}  // namespace

SparseMatrix redistributed_mass(const Mesh& mesh, const SparseMatrix& scalar_mass,
                                std::vector<std::string>& notes) {
    const std::vector<Point> p = normalized_points(mesh);
    std::vector<char> is_contact(mesh.num_nodes(), 0);
    for (int n : mesh.contact_nodes) is_contact[n] = 1;

    // Target moments (of the consistent mass) and the kept entries.
    Eigen::Matrix<double, 6, 1> target = Eigen::Matrix<double, 6, 1>::Zero();
    Triplets kept;
    Eigen::Matrix<double, 6, 6> CCt = Eigen::Matrix<double, 6, 6>::Zero();
    for (int j = 0; j < scalar_mass.outerSize(); ++j)
        for (SparseMatrix::InnerIterator it(scalar_mass, j); it; ++it) {
            const auto c = moment_row(p[it.row()], p[it.col()]);
            target += it.value() * c;
            if (!is_contact[it.row()] && !is_contact[it.col()]) {
                kept.emplace_back(it.row(), it.col(), it.value());
                CCt += c * c.transpose();
            }
        }
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix<double, 6, 6>> eig(CCt);
    if (eig.eigenvalues()(0) <= 1e-12 * eig.eigenvalues()(5))
        throw std::invalid_argument(
            "mass redistribution: " + mesh_name(mesh) + " is too coarse to keep the six moments "
            "without its contact nodes (the rectangle needs ny >= 2); use mass_matrix = 0 or 3");

    // The least change in the Frobenius norm, where it is positive definite (every rectangle
    // of ny >= 5, and the paper's: its bits are those before). It spreads its correction over
    // every entry alike, and the small cells of a mesh graded along its contact boundary
    // cannot carry their part; there the least relative change, which changes each entry by a
    // fraction of itself: the P1 mass is at least a quarter of its lumped form (an element's
    // is area/12 [2 1 1; 1 2 1; 1 1 2], eigenvalues area/12 {4, 1, 1}), so changes of less than
    // a quarter of every entry keep it positive definite, whatever the grading.
    double fraction = 0;
    Triplets corrected = corrected_entries(kept, p, target, false, fraction);
    if (!positive_definite_off_contact(corrected, is_contact)) {
        corrected = corrected_entries(kept, p, target, true, fraction);
        if (!positive_definite_off_contact(corrected, is_contact) && mesh.is_rectangle())
            throw std::invalid_argument(
                "mass redistribution: M_r is not positive definite on this mesh (nx = " +
                std::to_string(mesh.nx) + ", ny = " + std::to_string(mesh.ny) + "). On the "
                "rectangle it depends on nx and ny only (measured for any width and height): ny = "
                "3 fails for nx >= 3, every other ny >= 2 is carried (checked up to nx = 1000); a "
                "larger nx does not help. Use ny = 2, 4 or more, or mass_matrix = 0 or 3 "
                "(consistent mass)");
        if (!positive_definite_off_contact(corrected, is_contact)) {
            Text msg;
            msg << "mass redistribution: " << mesh_name(mesh) << " cannot carry M_r. Removing "
                << "the contact nodes' normal mass and restoring the six moments changes the other "
                << "entries by up to " << format_number(fraction) << " of themselves here, and the "
                << "result is not positive definite (changes below 1/4 of every entry would keep it "
                << "so). Use a mesh with more cells between the contact group and the rest of the "
                << "body, or mass_matrix = 0 or 3 (consistent mass)";
            throw std::invalid_argument(msg.str());
        }
        Text msg;
        msg << "mass redistribution: the least change in the Frobenius norm is not positive "
            << "definite on " << mesh_name(mesh) << "; M_r is the least relative change (each "
            << "entry changed by at most " << format_number(fraction) << " of itself)";
        notes.push_back(msg.str());
    }
    return from_triplets(mesh.num_nodes(), corrected);
}

SparseMatrix vector_mass_matrix(const SparseMatrix& mass_x, const SparseMatrix& mass_y) {
    Triplets t;
    t.reserve(mass_x.nonZeros() + mass_y.nonZeros());
    for (int c = 0; c < 2; ++c) {
        const SparseMatrix& m = c == 0 ? mass_x : mass_y;
        for (int j = 0; j < m.outerSize(); ++j)
            for (SparseMatrix::InnerIterator it(m, j); it; ++it)
                t.emplace_back(2 * it.row() + c, 2 * it.col() + c, it.value());
    }
    return from_triplets(2 * mass_x.rows(), t);
}

}  // namespace contactbody
