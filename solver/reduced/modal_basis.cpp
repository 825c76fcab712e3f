#include "reduced/modal_basis.hpp"

#include <Spectra/SymEigsSolver.h>

#include <chrono>
#include <functional>
#include <memory>
#include <stdexcept>
#include <string>

#include "linalg/trailing_cholesky.hpp"

namespace contactbody {

namespace {

// y = L^-1 P M P^T L^-T x with P A P^T = L L^T: symmetric, its eigenvalues are 1 / omega^2.
class InverseStiffnessMass {
public:
    using Scalar = double;
    InverseStiffnessMass(TrailingCholesky& factor, const SparseMatrix& M)
        : factor_(factor), M_(M), t_(Eigen::VectorXd::Zero(M.rows())), r_(Eigen::VectorXd::Zero(M.rows())) {}
    Eigen::Index rows() const { return M_.rows(); }
    Eigen::Index cols() const { return M_.rows(); }
    void perform_op(const Scalar* x_in, Scalar* y_out) const {
        const Eigen::Index n = rows();
        // forward() only to reach the factor's buffer (a third solve per application: the
        // set-up's cost, not the substep's).
        Eigen::Map<Eigen::VectorXd> y = factor_.forward(r_);
        y = Eigen::Map<const Eigen::VectorXd>(x_in, n);
        factor_.backward(t_);  // P^T L^-T x
        r_.noalias() = M_ * t_;
        Eigen::Map<Eigen::VectorXd>(y_out, n) = factor_.forward(r_);
    }

private:
    TrailingCholesky& factor_;
    const SparseMatrix& M_;
    mutable Eigen::VectorXd t_, r_;
};

// The contact unknowns as signed free positions: N_i = -e_y(i), T_i = +e_x(i) (the stepper's B),
// then a 3D body's +e_z(i); the tangential ones only where they are not held.
struct ContactRows {
    std::vector<int> position;
    std::vector<double> sign;
};
ContactRows contact_rows(const Discretization& d, bool hold_tangential) {
    ContactRows b;
    for (int y : d.contact_y) b.position.push_back(y), b.sign.push_back(-1);
    if (!hold_tangential)
        for (const std::vector<int>& dofs : d.contact_tangential)
            for (int t : dofs) b.position.push_back(t), b.sign.push_back(1);
    return b;
}

}  // namespace

std::vector<int> tangential_contact_dofs(const Discretization& d) {
    std::vector<int> dofs;
    for (const std::vector<int>& tangent : d.contact_tangential)
        dofs.insert(dofs.end(), tangent.begin(), tangent.end());
    return dofs;
}

SparseMatrix selection(Eigen::Index n, const std::vector<int>& positions) {
    std::vector<Eigen::Triplet<double>> t;
    for (size_t j = 0; j < positions.size(); ++j) t.emplace_back(positions[j], static_cast<int>(j), 1.0);
    SparseMatrix P(n, static_cast<Eigen::Index>(positions.size()));
    P.setFromTriplets(t.begin(), t.end());
    return P;
}

int finite_mode_count(const Discretization& d, bool hold_tangential) {
    int massless = 0;
    for (Eigen::Index k = 0; k < d.M_free.rows(); ++k) massless += d.M_free.coeff(k, k) == 0;
    int held_with_mass = 0;
    if (hold_tangential)
        for (int x : tangential_contact_dofs(d)) held_with_mass += d.M_free.coeff(x, x) != 0;
    return static_cast<int>(d.M_free.rows()) - massless - held_with_mass;
}

LowestModes lowest_modes(const SparseMatrix& A, const SparseMatrix& M, int modes, int dense_limit) {
    const Eigen::Index n = A.rows();
    LowestModes out;
    Eigen::VectorXd mu;      // 1 / omega^2, descending
    Eigen::MatrixXd shapes;  // A-orthonormal: shapes^T A shapes = I
    // Lanczos keeps 2m + 1 vectors and orthogonalizes against them: beyond a quarter of the
    // modes it is a slower dense solve, and its work n (2m + 1)^2 per restart grows past
    // minutes from a few hundred modes of a large body. So: dense for small bodies and for
    // most of a body's modes up to max_dense_modes_dofs, Lanczos for at most
    // max_lanczos_modes, and a clear refusal between.
    const bool most = 4 * static_cast<Eigen::Index>(modes) > n;
    if (!(n <= dense_limit || (most && n <= max_dense_modes_dofs)) && (most || modes > max_lanczos_modes))
        throw std::invalid_argument("modes = " + std::to_string(modes) + " of a body of " +
                                    std::to_string(n) + " dofs: the reduced body computes at most " +
                                    std::to_string(max_lanczos_modes) +
                                    " modes, and at most a quarter of a body's modes, of bodies above " +
                                    std::to_string(max_dense_modes_dofs) +
                                    " dofs (the eigensolver would take minutes); "
                                    "use fewer modes, or modes = 0 for the full body");
    if (n <= dense_limit || most) {
        out.dense = true;
        const Eigen::MatrixXd Ad(A), Md(M);
        Eigen::LLT<Eigen::MatrixXd> llt(Ad);
        if (llt.info() != Eigen::Success)
            throw std::runtime_error("the stiffness of the free dofs is not positive definite");
        const Eigen::MatrixXd Li = llt.matrixL().solve(Eigen::MatrixXd::Identity(n, n));
        Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(Li * Md * Li.transpose());
        // Ascending eigenvalues: the largest mu (lowest omega) last.
        mu = eig.eigenvalues().tail(modes).reverse();
        shapes = Li.transpose() * eig.eigenvectors().rightCols(modes).rowwise().reverse();
        out.solve = [llt](const Eigen::MatrixXd& b) -> Eigen::MatrixXd { return llt.solve(b); };
    } else {
        auto factor = std::make_shared<TrailingCholesky>(A, std::vector<int>{});
        InverseStiffnessMass op(*factor, M);
        const int ncv = static_cast<int>(std::min<Eigen::Index>(n, std::max(2 * modes + 1, modes + 20)));
        Spectra::SymEigsSolver<InverseStiffnessMass> eigs(op, modes, ncv);
        eigs.init();
        eigs.compute(Spectra::SortRule::LargestAlge, 1000, 1e-12, Spectra::SortRule::LargestAlge);
        if (eigs.info() != Spectra::CompInfo::Successful)
            throw std::runtime_error("the eigensolver did not converge to " + std::to_string(modes) +
                                     " modes (" + std::to_string(eigs.num_iterations()) +
                                     " restarts): ask for fewer modes");
        out.iterations = static_cast<int>(eigs.num_iterations());
        out.applications = static_cast<int>(eigs.num_operations());
        mu = eigs.eigenvalues();
        const Eigen::MatrixXd Y = eigs.eigenvectors();
        shapes.resize(n, modes);
        Eigen::VectorXd column = Eigen::VectorXd::Zero(n);
        for (int j = 0; j < modes; ++j) {  // P^T L^-T y
            factor->forward(column) = Y.col(j);
            factor->backward(column);
            shapes.col(j) = column;
        }
        out.solve = [factor](const Eigen::MatrixXd& b) -> Eigen::MatrixXd {
            Eigen::MatrixXd x(b.rows(), b.cols());
            Eigen::VectorXd column(b.rows());
            for (Eigen::Index j = 0; j < b.cols(); ++j) {
                factor->solve(b.col(j), column);
                x.col(j) = column;
            }
            return x;
        };
    }
    for (Eigen::Index j = 0; j < mu.size(); ++j)
        if (!(mu[j] > 0)) throw std::runtime_error("a mode without mass: ask for fewer modes");
    out.omega2 = mu.cwiseInverse();
    out.modes = shapes * mu.cwiseSqrt().cwiseInverse().asDiagonal();  // modes^T M modes = I
    return out;
}

ModalBasis build_modal_basis(const Discretization& d, int modes, bool hold_tangential, int dense_limit) {
    const auto start = std::chrono::steady_clock::now();
    if (d.plate_index >= 0)
        throw std::invalid_argument(
            "build_modal_basis needs a clamped top: under force control the body and the plate "
            "translate freely (the reduced body builds its basis on the clamped body and adds "
            "the translation)");
    const int finite = finite_mode_count(d, hold_tangential);
    if (modes < 1 || modes > finite)
        throw std::invalid_argument(
            "modes = " + std::to_string(modes) + " is out of range: the body has " + std::to_string(finite) +
            " finite modes" +
            (hold_tangential
                 ? " with its contact nodes' tangential dofs held (reduced_edge = tangential_mass)"
                 : ""));
    const Eigen::Index n = d.A_free.rows();
    // The held dofs X and the rest I: the modes, the residual and the static solves are the
    // rest's (with nothing held, the free dofs themselves).
    const std::vector<int> held = hold_tangential ? tangential_contact_dofs(d) : std::vector<int>{};
    std::vector<int> rest, rest_index(static_cast<size_t>(n), -1);
    {
        std::vector<bool> is_held(static_cast<size_t>(n), false);
        for (int x : held) is_held[static_cast<size_t>(x)] = true;
        for (int p = 0; p < n; ++p)
            if (!is_held[static_cast<size_t>(p)])
                rest_index[static_cast<size_t>(p)] = static_cast<int>(rest.size()), rest.push_back(p);
    }
    const SparseMatrix Pi = selection(n, rest), Px = selection(n, held);
    const SparseMatrix A_rest = held.empty() ? SparseMatrix() : SparseMatrix(Pi.transpose() * d.A_free * Pi);
    const SparseMatrix M_rest = held.empty() ? SparseMatrix() : SparseMatrix(Pi.transpose() * d.M_free * Pi);
    const SparseMatrix& A_II = held.empty() ? d.A_free : A_rest;
    const SparseMatrix& M_II = held.empty() ? d.M_free : M_rest;
    const Eigen::Index ni = A_II.rows();
    // A matrix on the rest's rows as one on every free dof (zero on X's rows).
    const auto expand = [&](Eigen::MatrixXd rows) -> Eigen::MatrixXd {
        if (held.empty()) return rows;
        return Pi * rows;
    };

    ModalBasis basis;
    LowestModes lowest = lowest_modes(A_II, M_II, modes, dense_limit);
    basis.dense = lowest.dense;
    basis.eigensolver_iterations = lowest.iterations;
    basis.operator_applications = lowest.applications;
    basis.omega2 = std::move(lowest.omega2);
    const Eigen::MatrixXd modes_rest = std::move(lowest.modes);
    const auto& solve = lowest.solve;

    // Residual attachment modes of the contact unknowns that are not held.
    ContactRows b = contact_rows(d, hold_tangential);
    for (int& p : b.position) p = rest_index[static_cast<size_t>(p)];
    const Eigen::Index nb = static_cast<Eigen::Index>(b.position.size());
    Eigen::MatrixXd Bt = Eigen::MatrixXd::Zero(ni, nb);
    for (Eigen::Index j = 0; j < nb; ++j)
        Bt(b.position[static_cast<size_t>(j)], j) = b.sign[static_cast<size_t>(j)];
    // B X for a dense X: its signed rows at the contact positions (B is a signed selection).
    const auto rows_of = [&](const Eigen::MatrixXd& X) {
        Eigen::MatrixXd out(nb, X.cols());
        for (Eigen::Index r = 0; r < nb; ++r)
            out.row(r) = b.sign[static_cast<size_t>(r)] * X.row(b.position[static_cast<size_t>(r)]);
        return out;
    };
    const Eigen::MatrixXd modal_part = rows_of(modes_rest).transpose();  // modes^T B^T
    Eigen::MatrixXd psi = solve(Bt);
    // The contact dofs' static flexibility, B A^-1 B^T: the scale below which G is round-off.
    const double flexibility = rows_of(psi).diagonal().maxCoeff();
    psi.noalias() -= modes_rest * (basis.omega2.cwiseInverse().asDiagonal() * modal_part);
    Eigen::MatrixXd G = rows_of(psi);
    G = 0.5 * (G + G.transpose()).eval();
    Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> g(G);
    std::vector<Eigen::Index> kept;
    for (Eigen::Index j = 0; j < g.eigenvalues().size(); ++j)
        if (g.eigenvalues()[j] > 1e-9 * flexibility) kept.push_back(j);
    // residual = psi V g^-1/2 (kept columns), rotated (Q orthogonal: still A-orthonormal, still
    // massless) so that its rows at the contact unknowns, B residual, are lower trapezoidal:
    // with (B psi V g^-1/2)^T = Q U, B psi V g^-1/2 Q = U^T. The reduced substep reads these
    // rows at every step, and then only their lower part. Formed as psi (V g^-1/2 Q): one
    // product with the tall psi.
    Eigen::MatrixXd coefficients(nb, static_cast<Eigen::Index>(kept.size()));
    for (size_t j = 0; j < kept.size(); ++j)
        coefficients.col(static_cast<Eigen::Index>(j)) =
            g.eigenvectors().col(kept[j]) / std::sqrt(g.eigenvalues()[kept[j]]);
    if (coefficients.cols() > 0) {
        const Eigen::HouseholderQR<Eigen::MatrixXd> qr((G * coefficients).transpose());
        coefficients = coefficients * qr.householderQ();
    }
    Eigen::MatrixXd residual = psi * coefficients;
    for (Eigen::Index r = 0; r < nb && r + 1 < residual.cols(); ++r)  // round-off above U^T's diagonal
        residual.row(b.position[static_cast<size_t>(r)]).tail(residual.cols() - r - 1).setZero();
    basis.modes = expand(modes_rest);
    basis.residual = expand(residual);

    // The clamp's static lift, and the held dofs' constraint modes.
    Eigen::VectorXd e = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(d.clamped_dofs.size()));
    for (size_t k = 0; k < d.clamped_dofs.size(); ++k)
        e[static_cast<Eigen::Index>(k)] = d.mesh.component(d.clamped_dofs[k]) == Mesh::normal;
    const Eigen::VectorXd Afc_e = d.A_free_clamped * e;
    if (held.empty()) {
        basis.lift = -solve(Eigen::MatrixXd(Afc_e)).col(0);
        basis.constraint.resize(n, 0);
    } else {
        const SparseMatrix A_IX = Pi.transpose() * d.A_free * Px, A_XX = Px.transpose() * d.A_free * Px;
        const Eigen::MatrixXd C = -solve(Eigen::MatrixXd(A_IX));
        basis.constraint = Pi * C + Eigen::MatrixXd(Px);
        // The lift with X held, plus the constraint modes that free X: K_XX s_X = the held
        // dofs' reaction, K_XX = A_XX + A_XI C (Guyan's condensed stiffness).
        const Eigen::VectorXd held_lift = -solve(Eigen::MatrixXd(Pi.transpose() * Afc_e)).col(0);
        const Eigen::VectorXd reaction = -(A_IX.transpose() * held_lift + Px.transpose() * Afc_e);
        Eigen::MatrixXd K_XX = Eigen::MatrixXd(A_XX) + A_IX.transpose() * C;
        K_XX = 0.5 * (K_XX + K_XX.transpose()).eval();
        const Eigen::VectorXd s_X = K_XX.llt().solve(reaction);
        basis.lift = Pi * Eigen::VectorXd(held_lift + C * s_X) + Px * s_X;
    }
    basis.setup_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return basis;
}

}  // namespace contactbody
