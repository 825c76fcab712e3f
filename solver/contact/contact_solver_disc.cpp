// The contact solve of a 3D body's isotropic friction (ContactProblem::tangents == 2): the
// Coulomb condition |lambda_T| <= F lambda_N with a two-dimensional slip, the subdifferential of
// a -> F lambda_N |a| (the paper's Remark 4.4). The same Alart-Curnier residual as in 2D, with
// the tangential projection onto a disc instead of an interval, and a semi-smooth Newton on its
// full generalized Jacobian (open nodes eliminated). In 2D the disc is the interval and this
// Jacobian the reduced system's; the 2D solve keeps its own path (its bits). With a slip-rate
// law F depends on the slip speed |s| / slip_time, s = u_T - origin the node's slip vector, taken
// implicitly as in 2D: its derivative enters a slipping node's rows.
#include <cmath>
#include <limits>

#include "contact_solver.hpp"
#include "text.hpp"

namespace contactbody {

double ContactSolver::residual_disc(const ContactProblem& p, const Eigen::VectorXd& lambda,
                                    Eigen::VectorXd& phi) {
    const Eigen::Index n = p.gap_limit.size();
    ++residual_evaluations_;
    u_hat_.noalias() = p.W * lambda;
    u_hat_ += p.a;
    phi.resize(lambda.size());
    status_.resize(n);
    pattern_.resize(n);
    disc_direction_.resize(2 * n);
    disc_ratio_.resize(n);
    disc_F_.resize(n);
    disc_trial_.resize(n);
    disc_dF_.setZero(n);
    disc_slip_direction_.setZero(2 * n);
    for (Eigen::Index i = 0; i < n; ++i) {
        const double l[3] = {lambda[i], lambda[n + i], lambda[2 * n + i]};
        const double u[3] = {u_hat_[i], u_hat_[n + i], u_hat_[2 * n + i]};
        const double origin[2] = {p.slip_origin[i], p.slip_origin[n + i]};
        double F = p.friction[i];
        if (p.rate_dependent()) {
            const double slip[2] = {u[1] - origin[0], u[2] - origin[1]};
            const double size = std::sqrt(slip[0] * slip[0] + slip[1] * slip[1]);
            double dF = 0;
            F = p.coefficient(i, size, &dF);
            disc_dF_[i] = size > 0 ? dF : 0.0;  // |s| has no derivative at 0
            disc_slip_direction_[i] = size > 0 ? slip[0] / size : 0.0;
            disc_slip_direction_[n + i] = size > 0 ? slip[1] / size : 0.0;
        }
        const DiscNode d = disc_node(l, u, r_[i], disc_rT_[i], p.gap_limit[i], origin, F);
        disc_F_[i] = F;
        disc_trial_[i] = -l[0] - r_[i] * (p.gap_limit[i] - u[0]);
        for (int c = 0; c < 3; ++c) phi[c * n + i] = d.phi[c];
        status_[i] = d.status;
        pattern_[i] = static_cast<signed char>(d.status == NodeStatus::open ? 0 : d.status == NodeStatus::stick ? 1 : 2);
        disc_direction_[i] = d.direction[0];
        disc_direction_[n + i] = d.direction[1];
        disc_ratio_[i] = d.ratio;
    }
    const double scale = lambda.lpNorm<Eigen::Infinity>();
    const double size = phi.lpNorm<Eigen::Infinity>();
    if (size == 0) return 0;
    return scale > 0 ? size / scale : std::numeric_limits<double>::infinity();
}

// J delta = -phi, J the generalized Jacobian at the node states of the last residual:
//   open:   phi_N = -l_N, phi_T = l_T                       (delta = -lambda: explicit)
//   active: phi_N = r_N (gap - u_N)                         -> -r_N W_N
//   stick:  phi_T = r_T (u_T - origin)                      -> r_T W_T
//   slip:   phi_T = l_T - F trial t, t = z / |z|, z = l_T - r_T (u_T - origin),
//           trial = -l_N - r_N (gap - u_N)
//           -> E_T - F t (-e_N + r_N W_N) - (F trial / |z|) (I - t t^T) (E_T - r_T W_T)
//              - trial t F'(|s|) (s / |s|)^T W_T     (a slip-rate law, s = u_T - origin)
// The open nodes' steps are known; the rest is a dense system on the active nodes' unknowns.
void ContactSolver::disc_newton_direction(const ContactProblem& p, const Eigen::VectorXd& lambda) {
    const Eigen::Index n = p.gap_limit.size(), m = 3 * n;
    step_.setZero(m);
    reduced_.clear();
    for (Eigen::Index i = 0; i < n; ++i) {
        if (pattern_[i] == 0) {
            for (int c = 0; c < 3; ++c) step_[c * n + i] = -lambda[c * n + i];
            continue;
        }
        for (int c = 0; c < 3; ++c) reduced_.push_back(static_cast<int>(c * n + i));
    }
    const Eigen::Index k = static_cast<Eigen::Index>(reduced_.size());
    if (k == 0) return;
    // Rows of the active nodes' unknowns over all columns, then the known columns moved right.
    Eigen::MatrixXd J = Eigen::MatrixXd::Zero(k, m);
    for (Eigen::Index a = 0; a < k; ++a) {
        const Eigen::Index row = reduced_[static_cast<size_t>(a)];
        const Eigen::Index i = row % n, c = row / n;
        const double rN = r_[i], rT = disc_rT_[i];
        if (c == 0) {
            J.row(a) = -rN * p.W.row(i);
            continue;
        }
        if (pattern_[i] == 1) {
            J.row(a) = rT * p.W.row(row);
            continue;
        }
        const double t[2] = {disc_direction_[i], disc_direction_[n + i]};
        const double F = disc_F_[i], kappa = disc_ratio_[i];
        // Component c - 1 of: E_T - F t (-e_N + r_N W_N) - kappa (I - t t^T)(E_T - r_T W_T)
        const int q = static_cast<int>(c - 1);
        J.row(a) = -F * t[q] * rN * p.W.row(i);
        J(a, i) += F * t[q];
        for (int s = 0; s < 2; ++s) {
            const double projector = (q == s ? 1.0 : 0.0) - t[q] * t[s];
            if (projector == 0) continue;
            const Eigen::Index col = (s + 1) * n + i;
            J.row(a) += kappa * projector * rT * p.W.row(col);
            J(a, col) -= kappa * projector;
        }
        if (disc_dF_[i] != 0)
            J.row(a) -= disc_trial_[i] * t[q] * disc_dF_[i] *
                        (disc_slip_direction_[i] * p.W.row(n + i) + disc_slip_direction_[n + i] * p.W.row(2 * n + i));
        J(a, row) += 1;
    }
    Eigen::VectorXd rhs(k);
    Eigen::MatrixXd reduced(k, k);
    for (Eigen::Index a = 0; a < k; ++a) {
        double known = 0;
        for (Eigen::Index j = 0; j < m; ++j)
            if (step_[j] != 0) known += J(a, j) * step_[j];
        rhs[a] = -phi_[reduced_[static_cast<size_t>(a)]] - known;
        for (Eigen::Index b = 0; b < k; ++b) reduced(a, b) = J(a, reduced_[static_cast<size_t>(b)]);
    }
    const Eigen::PartialPivLU<Eigen::MatrixXd> lu(reduced);
    if ((lu.matrixLU().diagonal().array() == 0).any())
        throw ContactSolveError("contact solver: singular Newton matrix (isotropic friction)");
    const Eigen::VectorXd x = lu.solve(rhs);
    for (Eigen::Index a = 0; a < k; ++a) step_[reduced_[static_cast<size_t>(a)]] = x[a];
}

ContactSolveInfo ContactSolver::solve_disc(const ContactProblem& p, const ContactSolverOptions& options,
                                           Eigen::VectorXd& lambda) {
    const Eigen::Index n = p.gap_limit.size();
    // One augmentation parameter for both tangential directions (isotropy: their mean
    // diagonal, invariant under a turn about the normal).
    disc_rT_.resize(n);
    for (Eigen::Index i = 0; i < n; ++i) disc_rT_[i] = 2 / (p.W(n + i, n + i) + p.W(2 * n + i, 2 * n + i));
    ContactSolveInfo info;
    info.residual = residual_disc(p, lambda, phi_);
    while (!(info.residual <= options.tolerance)) {
        if (info.iterations >= options.max_iterations) {
            Text msg;
            msg << "contact solver did not converge in " << options.max_iterations
                << " iterations (isotropic friction; relative residual " << info.residual
                << ", tolerance " << options.tolerance << ")";
            throw ContactSolveError(msg.str());
        }
        ++info.iterations;
        ++newton_iterations_;
        ++factorizations_;
        disc_newton_direction(p, lambda);
        if (!step_.allFinite()) throw ContactSolveError("contact solver: singular Newton matrix (isotropic friction)");
        // Backtracking on |phi|^2, the full step where none decreases it (as in 2D).
        const double merit = phi_.squaredNorm();
        double alpha = 1;
        bool decreased = false;
        for (int k = 0; k < 8 && !decreased; ++k) {
            trial_ = lambda + alpha * step_;
            residual_disc(p, trial_, trial_phi_);
            decreased = trial_phi_.squaredNorm() < merit;
            if (!decreased) alpha *= 0.5;
        }
        lambda += (decreased ? alpha : 1.0) * step_;
        info.residual = residual_disc(p, lambda, phi_);
    }
    return info;
}

}  // namespace contactbody
