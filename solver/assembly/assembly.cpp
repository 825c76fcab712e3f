#include "assembly/assembly.hpp"

#include "linalg/trailing_cholesky.hpp"
#include "util/build_features.hpp"
#include "util/text.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <type_traits>

#include <Eigen/Dense>
#include <stdexcept>
#include <vector>

namespace contactbody {

using Triplets = std::vector<Eigen::Triplet<double>>;

namespace {

// A P1 simplex's shape function gradients (grad[a] of node a's) and its measure (area or
// volume), from its positively oriented nodes. The triangle's are formed as they always were
// (the 2D body's bits); the tetrahedron's from the cofactors of its edge matrix.
template <int D>
struct Simplex {
    std::array<Eigen::Matrix<double, D, 1>, D + 1> grad;
    double measure;
};

template <int D>
Simplex<D> simplex(const Mesh& mesh, const int* cell) {
    Simplex<D> s;
    if constexpr (D == 2) {
        const Point p[3] = {mesh.point(cell[0]), mesh.point(cell[1]), mesh.point(cell[2])};
        const double area =
            0.5 * ((p[1].x - p[0].x) * (p[2].y - p[0].y) - (p[2].x - p[0].x) * (p[1].y - p[0].y));
        for (int a = 0; a < 3; ++a) {
            const Point& q1 = p[(a + 1) % 3];
            const Point& q2 = p[(a + 2) % 3];
            s.grad[a] << (q1.y - q2.y) / (2 * area), (q2.x - q1.x) / (2 * area);
        }
        s.measure = area;
    } else {
        Eigen::Matrix3d J;  // columns: the edges from node 0
        const Point& o = mesh.point(cell[0]);
        for (int a = 1; a <= 3; ++a) {
            const Point& q = mesh.point(cell[a]);
            J.col(a - 1) << q.x - o.x, q.y - o.y, q.z - o.z;
        }
        const double det = J.determinant();
        // grad N_a (a = 1..3) are the rows of J^-1: cofactors over the determinant.
        const Eigen::Matrix3d inverse = J.inverse();
        s.grad[0].setZero();
        for (int a = 1; a <= 3; ++a) {
            s.grad[a] = inverse.row(a - 1).transpose();
            s.grad[0] -= s.grad[a];
        }
        s.measure = det / 6;
    }
    return s;
}

// Strain components in Voigt order: xx, yy, (zz,) then the engineering shears xy (, yz, zx).
template <int D>
constexpr int voigt_size = D * (D + 1) / 2;

template <int D>
Eigen::Matrix<double, voigt_size<D>, voigt_size<D>> elasticity(double lambda, double mu) {
    Eigen::Matrix<double, voigt_size<D>, voigt_size<D>> E;
    E.setZero();
    for (int i = 0; i < D; ++i) {
        for (int j = 0; j < D; ++j) E(i, j) = lambda;
        E(i, i) = lambda + 2 * mu;
    }
    for (int i = D; i < voigt_size<D>; ++i) E(i, i) = mu;
    return E;
}

// Shear k (0: xy, 1: yz, 2: zx) couples components shear_pair[k].
constexpr int shear_pair[3][2] = {{0, 1}, {1, 2}, {2, 0}};

template <int D>
SparseMatrix stiffness(const Mesh& mesh, double lambda, double mu) {
    constexpr int S = voigt_size<D>, N = D * (D + 1);
    const auto E = elasticity<D>(lambda, mu);
    std::vector<Eigen::Triplet<double>> t;
    t.reserve(mesh.num_cells() * N * N);
    for (size_t e = 0; e < mesh.num_cells(); ++e) {
        const int* cell = mesh.cell(e);
        const Simplex<D> s = simplex<D>(mesh, cell);
        Eigen::Matrix<double, S, N> B = Eigen::Matrix<double, S, N>::Zero();
        for (int a = 0; a <= D; ++a) {
            for (int i = 0; i < D; ++i) B(i, D * a + i) = s.grad[a][i];
            for (int k = 0; k + D < S; ++k) {
                const int i = shear_pair[k][0], j = shear_pair[k][1];
                B(D + k, D * a + i) = s.grad[a][j];
                B(D + k, D * a + j) = s.grad[a][i];
            }
        }
        const Eigen::Matrix<double, N, N> Ke = s.measure * B.transpose() * E * B;
        for (int a = 0; a < N; ++a)
            for (int b = 0; b < N; ++b)
                t.emplace_back(D * cell[a / D] + a % D, D * cell[b / D] + b % D, Ke(a, b));
    }
    SparseMatrix m(mesh.num_dofs(), mesh.num_dofs());
    m.setFromTriplets(t.begin(), t.end());
    m.makeCompressed();
    return m;
}

// f(std::integral_constant<int, D>) for the mesh's dimension D: the kernels are templates on
// D, and a build without solid bodies (build_features.hpp) instantiates only D = 2.
template <class F>
auto by_dimension(const Mesh& mesh, F&& f) {
    if constexpr (solid_bodies_built) {
        if (mesh.dim == 3) return f(std::integral_constant<int, 3>{});
    } else if (mesh.dim != 2) {
        throw std::logic_error("this build assembles 2D bodies only (CONTACTBODY_SOLID_BODIES=0)");
    }
    return f(std::integral_constant<int, 2>{});
}

SparseMatrix from_triplets(int n, const Triplets& t) {
    SparseMatrix m(n, n);
    m.setFromTriplets(t.begin(), t.end());
    m.makeCompressed();
    return m;
}

// Coordinates centred and scaled to O(1): the moment constraints span the same space under
// any affine change of coordinates, and C C^T is far better conditioned this way.
std::vector<Point> normalized_points(const Mesh& mesh) {
    std::vector<Point> p(mesh.num_nodes());
    for (int n = 0; n < mesh.num_nodes(); ++n) {
        const Point q = mesh.point(n);
        p[n] = {2 * (q.x - mesh.x_min) / mesh.width() - 1, 2 * (q.y - mesh.y_min) / mesh.height() - 1};
        if (mesh.dim == 3) p[n].z = 2 * (q.z - mesh.z_min) / (mesh.z_max - mesh.z_min) - 1;
    }
    return p;
}

std::string mesh_name(const Mesh& mesh) {
    return mesh.is_rectangle() ? "the rectangle" : "the mesh " + mesh.source;
}

// The moments M_r keeps: the total mass, the D first and the D(D+1)/2 second ones.
template <int D>
constexpr int moment_count = 1 + D + D * (D + 1) / 2;
template <int D>
using Moments = Eigen::Matrix<double, moment_count<D>, 1>;
template <int D>
constexpr const char* moment_words = D == 2 ? "six" : "ten";

// Row of the symmetric-form constraint matrix for entry (i, j): 1, the mean of each
// coordinate, then the symmetrized products x_a x_b (a <= b).
template <int D>
Moments<D> moment_row(const Point& pi, const Point& pj) {
    Moments<D> c;
    if constexpr (D == 2) {
        c << 1, 0.5 * (pi.x + pj.x), 0.5 * (pi.y + pj.y), pi.x * pj.x, 0.5 * (pi.x * pj.y + pj.x * pi.y),
            pi.y * pj.y;
    } else {
        c << 1, 0.5 * (pi.x + pj.x), 0.5 * (pi.y + pj.y), 0.5 * (pi.z + pj.z), pi.x * pj.x,
            0.5 * (pi.x * pj.y + pj.x * pi.y), 0.5 * (pi.x * pj.z + pj.x * pi.z), pi.y * pj.y,
            0.5 * (pi.y * pj.z + pj.y * pi.z), pi.z * pj.z;
    }
    return c;
}

}  // namespace

SparseMatrix stiffness_matrix(const Mesh& mesh, double lambda, double mu) {
    return by_dimension(mesh, [&](auto D) { return stiffness<D()>(mesh, lambda, mu); });
}

StrainEnergy::StrainEnergy(const Mesh& mesh, double lambda, double mu)
    : dim_(mesh.dim), lambda_(lambda), mu_(mu) {
    elements_.reserve(mesh.num_cells());
    for (size_t e = 0; e < mesh.num_cells(); ++e) {
        const int* cell = mesh.cell(e);
        Element element{};
        std::copy(cell, cell + mesh.nodes_per_cell(), element.nodes.begin());
        if (mesh.dim == 2) {
            // dN_a/dx = (y_{a+1} - y_{a+2}) / 2 area, dN_a/dy = (x_{a+2} - x_{a+1}) / 2 area
            const Simplex<2> s = simplex<2>(mesh, cell);
            const Point p[3] = {mesh.point(cell[0]), mesh.point(cell[1]), mesh.point(cell[2])};
            const double area = s.measure;
            element.grad[0] = {(p[2].y - p[0].y) / (2 * area), (p[0].x - p[2].x) / (2 * area), 0};
            element.grad[1] = {(p[0].y - p[1].y) / (2 * area), (p[1].x - p[0].x) / (2 * area), 0};
            element.measure = area;
        } else {
            by_dimension(mesh, [&](auto D) {
                const auto s = simplex<D()>(mesh, cell);
                for (int a = 0; a < D(); ++a)
                    for (int j = 0; j < D(); ++j) element.grad[a][j] = s.grad[a + 1][j];
                element.measure = s.measure;
                return 0;
            });
        }
        elements_.push_back(element);
    }
}

double StrainEnergy::operator()(const Eigen::VectorXd& u) const {
    double energy = 0;
    const int D = dim_;
    for (const Element& e : elements_) {
        // The strain from the displacements of nodes 1..D relative to node 0: exact zero for a
        // translation of any size.
        double grad_u[3][3] = {};  // du_i/dx_j
        const int n0 = e.nodes[0];
        for (int a = 0; a < D; ++a) {
            const int n = e.nodes[static_cast<size_t>(a + 1)];
            for (int i = 0; i < D; ++i) {
                const double du = u[D * n + i] - u[D * n0 + i];
                for (int j = 0; j < D; ++j) grad_u[i][j] += e.grad[a][j] * du;
            }
        }
        if (D == 2) {
            // (lambda + mu)/2 (tr e)^2 + mu/2 (e_xx - e_yy)^2 + mu/2 gamma_xy^2
            const double exx = grad_u[0][0], eyy = grad_u[1][1];
            // summed in the order the 2D body's bits were made in
            const int n1 = e.nodes[1], n2 = e.nodes[2];
            const double gamma = e.grad[0][1] * (u[2 * n1] - u[2 * n0]) +
                                 e.grad[1][1] * (u[2 * n2] - u[2 * n0]) +
                                 e.grad[0][0] * (u[2 * n1 + 1] - u[2 * n0 + 1]) +
                                 e.grad[1][0] * (u[2 * n2 + 1] - u[2 * n0 + 1]);
            const double trace = exx + eyy, shear = exx - eyy;
            energy += e.measure *
                      (0.5 * (lambda_ + mu_) * trace * trace + 0.5 * mu_ * (shear * shear + gamma * gamma));
        } else {
            // (lambda + 2 mu/3)/2 (tr e)^2 + mu/3 sum (e_ii - e_jj)^2 + mu/2 sum gamma_ij^2
            const double exx = grad_u[0][0], eyy = grad_u[1][1], ezz = grad_u[2][2];
            const double trace = exx + eyy + ezz;
            const double normal =
                (exx - eyy) * (exx - eyy) + (eyy - ezz) * (eyy - ezz) + (ezz - exx) * (ezz - exx);
            double shear = 0;
            for (const auto& pair : shear_pair) {
                const double gamma = grad_u[pair[0]][pair[1]] + grad_u[pair[1]][pair[0]];
                shear += gamma * gamma;
            }
            energy += e.measure *
                      (0.5 * (lambda_ + 2 * mu_ / 3) * trace * trace + mu_ / 3 * normal + 0.5 * mu_ * shear);
        }
    }
    return energy;
}

SparseMatrix scalar_mass_matrix(const Mesh& mesh, double rho) {
    // A P1 simplex's consistent mass: measure / ((D+1)(D+2)) (1 + delta_ab).
    const int per = mesh.nodes_per_cell();
    const double denominator = static_cast<double>(per * (per + 1));
    Triplets t;
    t.reserve(mesh.num_cells() * static_cast<size_t>(per * per));
    for (size_t e = 0; e < mesh.num_cells(); ++e) {
        const int* cell = mesh.cell(e);
        const double measure = by_dimension(mesh, [&](auto D) { return simplex<D()>(mesh, cell).measure; });
        for (int a = 0; a < per; ++a)
            for (int b = 0; b < per; ++b)
                t.emplace_back(cell[a], cell[b], rho * measure / denominator * (a == b ? 2.0 : 1.0));
    }
    return from_triplets(mesh.num_nodes(), t);
}

template <int D>
std::vector<double> moments_of(const Mesh& mesh, const SparseMatrix& m) {
    Moments<D> s = Moments<D>::Zero();
    for (int j = 0; j < m.outerSize(); ++j)
        for (SparseMatrix::InnerIterator it(m, j); it; ++it)
            s += it.value() * moment_row<D>(mesh.point(it.row()), mesh.point(it.col()));
    return std::vector<double>(s.data(), s.data() + s.size());
}

std::vector<double> mass_moments(const Mesh& mesh, const SparseMatrix& m) {
    return by_dimension(mesh, [&](auto D) { return moments_of<D()>(mesh, m); });
}

namespace {

// The kept entries corrected to the target moments: m <- m - W C^T (C W C^T)^{-1} (C m - d),
// the least change in sum (change_e^2 / w_e). w_e = 1 is the least change in the Frobenius
// norm (KLR's); w_e = m_e the least change relative to each entry, which changes entry e by
// the fraction c_e . y of itself, whatever its size. `largest_fraction`: max |c_e . y|.
template <int D>
Triplets corrected_entries(const Triplets& kept, const std::vector<Point>& p, const Moments<D>& target,
                           bool relative, double& largest_fraction) {
    constexpr int K = moment_count<D>;
    Eigen::Matrix<double, K, K> CWCt = Eigen::Matrix<double, K, K>::Zero();
    Moments<D> Cm = Moments<D>::Zero();
    for (const auto& e : kept) {
        const auto c = moment_row<D>(p[e.row()], p[e.col()]);
        CWCt += (relative ? e.value() : 1.0) * c * c.transpose();
        Cm += e.value() * c;
    }
    const Moments<D> y = CWCt.ldlt().solve(Cm - target);
    Triplets corrected;
    corrected.reserve(kept.size());
    largest_fraction = 0;
    for (const auto& e : kept) {
        const double cy = moment_row<D>(p[e.row()], p[e.col()]).dot(y);
        corrected.emplace_back(e.row(), e.col(), e.value() - (relative ? e.value() : 1.0) * cy);
        largest_fraction = std::max(largest_fraction, std::abs(relative ? cy : cy / e.value()));
    }
    return corrected;
}

// Whether the entries (which hold no contact node) are positive definite on the other nodes,
// changed from the consistent mass's by at most `fraction` of each entry: the certificates
// where they decide, else a sparse Cholesky.
bool positive_definite_off_contact(const Mesh& mesh, const Triplets& entries, const std::vector<char>& is_contact,
                                   double fraction) {
    std::vector<int> position(is_contact.size(), -1);
    int n = 0;
    for (size_t k = 0; k < is_contact.size(); ++k)
        if (!is_contact[k]) position[k] = n++;
    Triplets restricted;
    restricted.reserve(entries.size());
    for (const auto& e : entries) restricted.emplace_back(position[e.row()], position[e.col()], e.value());
    const SparseMatrix m = from_triplets(n, restricted);
    std::vector<std::array<int, 4>> cells(mesh.num_cells());
    for (size_t e = 0; e < cells.size(); ++e) {
        cells[e].fill(-1);
        for (int a = 0; a < mesh.nodes_per_cell(); ++a) cells[e][static_cast<size_t>(a)] = position[mesh.cell(e)[a]];
    }
    const MassCertificate certificate = mass_definiteness_certificate(m, fraction, mesh.dim, cells);
    if (certificate != MassCertificate::undecided) return certificate == MassCertificate::definite;
    // The body's own factor (its fill-reducing order, supernodal where large: Eigen's simplicial
    // Cholesky took 400 s at 111k nodes), on the baseline kernels: the same answer on any CPU.
    try {
        const TrailingCholesky factor(m, {}, true, TrailingCholesky::Kernel::automatic, FactorOptions{true, 1});
        return true;
    } catch (const std::runtime_error& e) {
        if (std::string(e.what()).find("not positive definite") == std::string::npos) throw;
        return false;
    }
}

}  // namespace

namespace {

template <int D>
SparseMatrix redistributed(const Mesh& mesh, const SparseMatrix& scalar_mass,
                           std::vector<std::string>& notes) {
    constexpr int K = moment_count<D>;
    const std::vector<Point> p = normalized_points(mesh);
    std::vector<char> is_contact(mesh.num_nodes(), 0);
    for (int n : mesh.contact_nodes) is_contact[n] = 1;

    // Target moments (of the consistent mass) and the kept entries.
    Moments<D> target = Moments<D>::Zero();
    Triplets kept;
    Eigen::Matrix<double, K, K> CCt = Eigen::Matrix<double, K, K>::Zero();
    for (int j = 0; j < scalar_mass.outerSize(); ++j)
        for (SparseMatrix::InnerIterator it(scalar_mass, j); it; ++it) {
            const auto c = moment_row<D>(p[it.row()], p[it.col()]);
            target += it.value() * c;
            if (!is_contact[it.row()] && !is_contact[it.col()]) {
                kept.emplace_back(it.row(), it.col(), it.value());
                CCt += c * c.transpose();
            }
        }
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix<double, K, K>> eig(CCt);
    if (eig.eigenvalues()(0) <= 1e-12 * eig.eigenvalues()(K - 1))
        throw std::invalid_argument(
            "mass redistribution: " + mesh_name(mesh) + " is too coarse to keep the " + moment_words<D> +
            " moments "
            "without its contact nodes (the rectangle needs ny >= 2); use mass_matrix = 0 or 3");

    // The least change in the Frobenius norm, where it is positive definite (every rectangle
    // of ny >= 5, and the paper's: its bits are those before). It spreads its correction over
    // every entry alike, and the small cells of a mesh graded along its contact boundary
    // cannot carry their part; there the least relative change, which changes each entry by a
    // fraction of itself: the P1 mass is at least 1/(D+2) of its lumped form (a triangle's
    // is area/12 [2 1 1; 1 2 1; 1 1 2], eigenvalues area/12 {4, 1, 1}; a tetrahedron's 1/5),
    // so changes of less than that of every entry keep it positive definite, whatever the grading.
    double fraction = 0;
    Triplets corrected = corrected_entries<D>(kept, p, target, false, fraction);
    if (!positive_definite_off_contact(mesh, corrected, is_contact, fraction)) {
        corrected = corrected_entries<D>(kept, p, target, true, fraction);
        const bool definite = positive_definite_off_contact(mesh, corrected, is_contact, fraction);
        if (!definite && mesh.is_rectangle())
            throw std::invalid_argument(
                "mass redistribution: M_r is not positive definite on this mesh (nx = " +
                std::to_string(mesh.nx) + ", ny = " + std::to_string(mesh.ny) +
                "). On the "
                "rectangle it depends on nx and ny only (measured for any width and height): ny = "
                "3 fails for nx >= 3, every other ny >= 2 is carried (checked up to nx = 1000); a "
                "larger nx does not help. Use ny = 2, 4 or more, or mass_matrix = 0 or 3 "
                "(consistent mass)");
        if (!definite) {
            Text msg;
            msg << "mass redistribution: " << mesh_name(mesh) << " cannot carry M_r. Removing "
                << "the contact nodes' normal mass and restoring the "
                << moment_words<D> << " moments changes the other "
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

}  // namespace

MassCertificate mass_definiteness_certificate(const SparseMatrix& m, double fraction, int dim,
                                              const std::vector<std::array<int, 4>>& cells) {
    const Eigen::VectorXd diagonal = m.diagonal();
    if (!(diagonal.array() > 0).all()) return MassCertificate::indefinite;
    for (int j = 0; j < m.outerSize(); ++j)
        for (SparseMatrix::InnerIterator it(m, j); it; ++it)
            if (it.row() != j && !(it.value() * it.value() < diagonal[it.row()] * diagonal[j]))
                return MassCertificate::indefinite;
    if (fraction < 1.0 / (dim + 2)) return MassCertificate::definite;
    for (const std::array<int, 4>& cell : cells) {
        std::array<int, 4> nodes{};
        int k = 0;
        for (int node : cell)
            if (node >= 0) nodes[static_cast<size_t>(k++)] = node;
        Eigen::Matrix4d block = Eigen::Matrix4d::Identity();
        for (int a = 0; a < k; ++a)
            for (int b = 0; b < k; ++b)
                block(a, b) = m.coeff(nodes[static_cast<size_t>(a)], nodes[static_cast<size_t>(b)]);
        if (block.llt().info() != Eigen::Success) return MassCertificate::indefinite;
    }
    return MassCertificate::undecided;
}

SparseMatrix redistributed_mass(const Mesh& mesh, const SparseMatrix& scalar_mass,
                                std::vector<std::string>& notes) {
    return by_dimension(mesh, [&](auto D) { return redistributed<D()>(mesh, scalar_mass, notes); });
}

SparseMatrix vector_mass_matrix(int dim, const SparseMatrix& tangential, const SparseMatrix& normal) {
    Triplets t;
    t.reserve((dim - 1) * tangential.nonZeros() + normal.nonZeros());
    for (int c = 0; c < dim; ++c) {
        const SparseMatrix& m = c == Mesh::normal ? normal : tangential;
        for (int j = 0; j < m.outerSize(); ++j)
            for (SparseMatrix::InnerIterator it(m, j); it; ++it)
                t.emplace_back(dim * it.row() + c, dim * it.col() + c, it.value());
    }
    return from_triplets(dim * static_cast<int>(tangential.rows()), t);
}

}  // namespace contactbody
