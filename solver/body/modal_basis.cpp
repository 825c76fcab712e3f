#include "modal_basis.hpp"

#include <Spectra/SymEigsSolver.h>

#include <chrono>
#include <functional>
#include <memory>
#include <stdexcept>
#include <string>

#include "trailing_cholesky.hpp"

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
        factor_.backward(t_);                                  // P^T L^-T x
        r_.noalias() = M_ * t_;
        Eigen::Map<Eigen::VectorXd>(y_out, n) = factor_.forward(r_);
    }

private:
    TrailingCholesky& factor_;
    const SparseMatrix& M_;
    mutable Eigen::VectorXd t_, r_;
};

// The contact unknowns as signed free positions: N_i = -e_y(i), T_i = +e_x(i) (the stepper's B).
struct ContactRows {
    std::vector<int> position;
    std::vector<double> sign;
};
ContactRows contact_rows(const Discretization& d) {
    ContactRows b;
    for (int y : d.contact_y) b.position.push_back(y), b.sign.push_back(-1);
    for (int x : d.contact_x) b.position.push_back(x), b.sign.push_back(1);
    return b;
}

}  // namespace

int finite_mode_count(const Discretization& d) {
    int massless = 0;
    for (Eigen::Index k = 0; k < d.M_free.rows(); ++k) massless += d.M_free.coeff(k, k) == 0;
    return static_cast<int>(d.M_free.rows()) - massless;
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
    if (!(n <= dense_limit || (most && n <= max_dense_modes_dofs)) &&
        (most || modes > max_lanczos_modes))
        throw std::invalid_argument(
            "modes = " + std::to_string(modes) + " of a body of " + std::to_string(n) +
            " dofs: the reduced body computes at most " + std::to_string(max_lanczos_modes) +
            " modes, and at most a quarter of a body's modes, of bodies above " +
            std::to_string(max_dense_modes_dofs) + " dofs (the eigensolver would take minutes); "
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

ModalBasis build_modal_basis(const Discretization& d, int modes, int dense_limit) {
    const auto start = std::chrono::steady_clock::now();
    if (d.plate_index >= 0)
        throw std::invalid_argument(
            "build_modal_basis needs a clamped top: under force control the body and the plate "
            "translate freely (the reduced body builds its basis on the clamped body and adds "
            "the translation)");
    const int finite = finite_mode_count(d);
    if (modes < 1 || modes > finite)
        throw std::invalid_argument("modes = " + std::to_string(modes) + " is out of range: the body has " +
                                    std::to_string(finite) + " finite modes");
    const Eigen::Index n = d.A_free.rows();
    ModalBasis basis;
    LowestModes lowest = lowest_modes(d.A_free, d.M_free, modes, dense_limit);
    basis.dense = lowest.dense;
    basis.eigensolver_iterations = lowest.iterations;
    basis.operator_applications = lowest.applications;
    basis.omega2 = std::move(lowest.omega2);
    basis.modes = std::move(lowest.modes);
    const auto& solve = lowest.solve;

    // Residual attachment modes of the contact unknowns.
    const ContactRows b = contact_rows(d);
    const Eigen::Index nb = static_cast<Eigen::Index>(b.position.size());
    Eigen::MatrixXd Bt = Eigen::MatrixXd::Zero(n, nb);
    for (Eigen::Index j = 0; j < nb; ++j) Bt(b.position[static_cast<size_t>(j)], j) = b.sign[static_cast<size_t>(j)];
    // B X for a dense X: its signed rows at the contact positions (B is a signed selection).
    const auto rows_of = [&](const Eigen::MatrixXd& X) {
        Eigen::MatrixXd out(nb, X.cols());
        for (Eigen::Index r = 0; r < nb; ++r)
            out.row(r) = b.sign[static_cast<size_t>(r)] * X.row(b.position[static_cast<size_t>(r)]);
        return out;
    };
    const Eigen::MatrixXd modal_part = rows_of(basis.modes).transpose();  // modes^T B^T
    Eigen::MatrixXd psi = solve(Bt);
    // The contact dofs' static flexibility, B A^-1 B^T: the scale below which G is round-off.
    const double flexibility = rows_of(psi).diagonal().maxCoeff();
    psi.noalias() -= basis.modes * (basis.omega2.cwiseInverse().asDiagonal() * modal_part);
    Eigen::MatrixXd G = rows_of(psi);
    G = 0.5 * (G + G.transpose()).eval();
    Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> g(G);
    std::vector<Eigen::Index> kept;
    for (Eigen::Index j = 0; j < g.eigenvalues().size(); ++j)
        if (g.eigenvalues()[j] > 1e-9 * flexibility) kept.push_back(j);
    basis.residual.resize(n, static_cast<Eigen::Index>(kept.size()));
    for (size_t j = 0; j < kept.size(); ++j)
        basis.residual.col(static_cast<Eigen::Index>(j)) =
            psi * g.eigenvectors().col(kept[j]) / std::sqrt(g.eigenvalues()[kept[j]]);

    // The clamp's static lift.
    Eigen::VectorXd e = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(d.clamped_dofs.size()));
    for (size_t k = 0; k < d.clamped_dofs.size(); ++k) e[static_cast<Eigen::Index>(k)] = d.clamped_dofs[k] % 2 == 1;
    basis.lift = -solve(Eigen::MatrixXd(d.A_free_clamped * e)).col(0);
    basis.setup_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return basis;
}

}  // namespace contactbody
