// The contact solve on the full generalized Jacobian, for any number of tangents: a 3D body's
// isotropic friction (ContactProblem::tangents == 2: the Coulomb condition |lambda_T| <= F
// lambda_N with a two-dimensional slip, the subdifferential of a -> F lambda_N |a|, the paper's
// Remark 4.4), and a 2D body's when asked (ContactSolverOptions::reduced_newton false; in 2D the
// reduced system is faster: docs/decisions.md, "The 2D contact solve's reduced Newton"). The
// Alart-Curnier residual of friction_law.hpp, and a semi-smooth Newton on its generalized Jacobian
// with the open nodes eliminated. With a slip-rate law F depends on the slip speed |s| /
// slip_time, s = u_T - origin the node's slip vector, taken implicitly: its derivative enters a
// slipping node's rows.
#include <algorithm>
#include <cmath>
#include <limits>

#include <Eigen/Dense>

#include "contact/contact_solver.hpp"
#include "util/tangents.hpp"
#include "util/text.hpp"

namespace contactbody {

double ContactSolver::full_residual(const ContactProblem& p, const Eigen::VectorXd& lambda,
                                    Eigen::VectorXd& phi) {
    ++residual_evaluations_;
    u_hat_.noalias() = p.W * lambda;
    u_hat_ += p.a;
    return apply_law(p, lambda, tangential_augmentation_, phi);
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
void ContactSolver::full_newton_direction(const ContactProblem& p, const Eigen::VectorXd& lambda) {
    const Eigen::Index n = p.gap_limit.size();
    const int T = p.tangents, components = 1 + T;
    const Eigen::Index m = components * n;
    step_.setZero(m);
    reduced_.clear();
    reduced_.reserve(static_cast<size_t>(m));
    for (Eigen::Index i = 0; i < n; ++i) {
        if (pattern_[i] == 0) {
            for (int c = 0; c < components; ++c) step_[c * n + i] = -lambda[c * n + i];
            continue;
        }
        for (int c = 0; c < components; ++c) reduced_.push_back(static_cast<int>(c * n + i));
    }
    const Eigen::Index k = static_cast<Eigen::Index>(reduced_.size());
    if (k == 0) return;
    // Rows of the active nodes' unknowns over all columns, then the known columns moved right.
    // Buffers sized once for all m unknowns: no allocation while the active set changes.
    if (jacobian_rows_.rows() != m || jacobian_rows_.cols() != m) jacobian_rows_.resize(m, m);
    auto J = jacobian_rows_.topRows(k);
    J.setZero();
    for (Eigen::Index a = 0; a < k; ++a) {
        const Eigen::Index row = reduced_[static_cast<size_t>(a)];
        const Eigen::Index i = row % n, c = row / n;
        const double rN = r_[i], rT = tangential_augmentation_[i];
        if (c == 0) {
            J.row(a) = -rN * p.W.row(i);
            continue;
        }
        if (pattern_[i] == 1) {
            J.row(a) = rT * p.W.row(row);
            continue;
        }
        double t[max_tangents] = {0, 0};
        for (int s = 0; s < T; ++s) t[s] = law_direction_[s * n + i];
        const double F = law_F_[i], kappa = law_ratio_[i];
        // Component q of: E_T - F t (-e_N + r_N W_N) - kappa (I - t t^T)(E_T - r_T W_T)
        const int q = static_cast<int>(c - 1);
        J.row(a) = -F * t[q] * rN * p.W.row(i);
        J(a, i) += F * t[q];
        for (int s = 0; s < T; ++s) {
            const double projector = (q == s ? 1.0 : 0.0) - t[q] * t[s];
            if (projector == 0) continue;
            const Eigen::Index col = (s + 1) * n + i;
            J.row(a) += kappa * projector * rT * p.W.row(col);
            J(a, col) -= kappa * projector;
        }
        if (p.rate_dependent() && law_dF_[i] != 0) {  // W_T^T (s / |s|), then its multiple
            slip_row_ = law_slip_direction_[i] * p.W.row(n + i);
            for (int s = 1; s < T; ++s)
                slip_row_ += law_slip_direction_[s * n + i] * p.W.row((s + 1) * n + i);
            J.row(a) -= law_trial_[i] * t[q] * law_dF_[i] * slip_row_;
        }
        J(a, row) += 1;
    }
    newton_lu_.reserve(m);
    auto A = newton_lu_.matrix(k);
    reduced_rhs_.resize(m);
    auto rhs = reduced_rhs_.head(k);
    for (Eigen::Index a = 0; a < k; ++a) {
        double known = 0;
        for (Eigen::Index j = 0; j < m; ++j)
            if (step_[j] != 0) known += J(a, j) * step_[j];
        rhs[a] = -phi_[reduced_[static_cast<size_t>(a)]] - known;
        for (Eigen::Index b = 0; b < k; ++b) A(a, b) = J(a, reduced_[static_cast<size_t>(b)]);
    }
    if (!newton_lu_.factor(k))
        throw ContactSolveError("contact solver: singular Newton matrix (full Jacobian)");
    newton_lu_.solve_in_place(rhs);
    for (Eigen::Index a = 0; a < k; ++a) step_[reduced_[static_cast<size_t>(a)]] = rhs[a];
}

ContactSolveInfo ContactSolver::solve_full_jacobian(const ContactProblem& p,
                                                    const ContactSolverOptions& options,
                                                    Eigen::VectorXd& lambda) {
    const Eigen::Index n = p.gap_limit.size();
    // One augmentation parameter for all tangential directions (isotropy: their mean
    // diagonal, invariant under a turn about the normal).
    tangential_augmentation_.resize(n);
    for (Eigen::Index i = 0; i < n; ++i) {
        double sum = 0;
        for (int t = 1; t <= p.tangents; ++t) sum += p.W(t * n + i, t * n + i);
        tangential_augmentation_[i] = p.tangents / sum;
    }
    ContactSolveInfo info;
    info.residual = full_residual(p, lambda, phi_);
    while (!(info.residual <= options.tolerance)) {
        if (info.iterations >= options.max_iterations) {
            Text msg;
            msg << "contact solver did not converge in " << options.max_iterations
                << " iterations (full Jacobian; relative residual " << info.residual << ", tolerance "
                << options.tolerance << ")";
            throw ContactSolveError(msg.str());
        }
        ++info.iterations;
        ++newton_iterations_;
        ++factorizations_;
        full_newton_direction(p, lambda);
        if (!step_.allFinite())
            throw ContactSolveError("contact solver: singular Newton matrix (full Jacobian)");
        // Backtracking on |phi|^2, the full step where none decreases it (as in 2D).
        const double merit = phi_.squaredNorm();
        double alpha = 1;
        bool decreased = false;
        for (int k = 0; k < 8 && !decreased; ++k) {
            trial_ = lambda + alpha * step_;
            full_residual(p, trial_, trial_phi_);
            decreased = trial_phi_.squaredNorm() < merit;
            if (!decreased) alpha *= 0.5;
        }
        lambda += (decreased ? alpha : 1.0) * step_;
        info.residual = full_residual(p, lambda, phi_);
    }
    return info;
}

namespace {

// One node's problem with the other nodes' multipliers fixed: u = q + A l (A the node's 3x3
// block of W; rows N, T_x, T_z), u_N <= gap, the disc |l_T| <= -F l_N with a slip s = u_T -
// origin opposite l_T. `coefficient(|s|)` is F (constant, or the slip-rate law's). Open,
// stick, or slip: l_T = F(|s|) l_N s / |s| with u_N = gap, two equations in s solved by
// Newton from the sticking solution's direction. False where no slip solution was found.
template <class Coefficient>
bool solve_disc_node(const double q[3], const Eigen::Matrix3d& A, double gap, const double origin[2],
                     Coefficient&& coefficient, double l[3]) {
    l[0] = l[1] = l[2] = 0;
    if (q[0] <= gap) return true;  // open
    const Eigen::Vector3d stick =
        A.partialPivLu().solve(Eigen::Vector3d(gap - q[0], origin[0] - q[1], origin[1] - q[2]));
    const double F0 = coefficient(0.0);
    if (stick[0] <= 0 && std::sqrt(stick[1] * stick[1] + stick[2] * stick[2]) <= -F0 * stick[0]) {
        for (int c = 0; c < 3; ++c) l[c] = stick[c];
        return true;
    }
    // The slip s gives F, its direction d, l_N from u_N = gap, l_T, and the slip u_T - origin
    // those make: the residual R(s) is that slip less s.
    const auto residual = [&](const Eigen::Vector2d& s, double out[3]) {
        const double size = s.norm();
        const Eigen::Vector2d d = s / size;
        const double F = coefficient(size);
        const double lN = (gap - q[0]) / (A(0, 0) + F * (A(0, 1) * d[0] + A(0, 2) * d[1]));
        out[0] = lN;
        const Eigen::Vector2d lT = F * lN * d;
        const Eigen::Vector2d slip(q[1] - origin[0] + A(1, 0) * lN + A(1, 1) * lT[0] + A(1, 2) * lT[1],
                                   q[2] - origin[1] + A(2, 0) * lN + A(2, 1) * lT[0] + A(2, 2) * lT[1]);
        out[1] = lT[0];
        out[2] = lT[1];
        return Eigen::Vector2d(slip - s);
    };
    // Start: along -l_T of the sticking solution, as far as the cone's edge leaves it to slip.
    const double tangential = std::sqrt(stick[1] * stick[1] + stick[2] * stick[2]);
    Eigen::Vector2d d = tangential > 0 ? Eigen::Vector2d(-stick[1] / tangential, -stick[2] / tangential)
                                       : Eigen::Vector2d(1, 0);
    const double scale = std::abs(q[1] - origin[0]) + std::abs(q[2] - origin[1]) +
                         A.cwiseAbs().maxCoeff() * stick.cwiseAbs().maxCoeff();
    if (!(scale > 0)) return false;
    double trial[3];
    Eigen::Vector2d s = 1e-6 * scale * d;
    s += residual(s, trial);  // one fixed-point step
    if (!(s.norm() > 0)) s = 1e-6 * scale * d;
    Eigen::Vector2d R = residual(s, trial);
    for (int iteration = 0; iteration < 60; ++iteration) {
        if (R.norm() <= 1e-15 * scale) {
            if (!(trial[0] < 0)) return false;
            for (int c = 0; c < 3; ++c) l[c] = trial[c];
            return true;
        }
        // The Jacobian by differences (two more residuals), then a step halved while it
        // does not decrease |R| or would turn the slip through zero.
        Eigen::Matrix2d J;
        const double h = 1e-7 * std::max(s.norm(), 1e-9 * scale);
        double unused[3];
        for (int c = 0; c < 2; ++c) {
            Eigen::Vector2d e = s;
            e[c] += h;
            J.col(c) = (residual(e, unused) - R) / h;
        }
        const Eigen::Vector2d step = J.partialPivLu().solve(-R);
        if (!step.allFinite()) return false;
        double alpha = 1;
        bool decreased = false;
        for (int k = 0; k < 30 && !decreased; ++k, alpha *= 0.5) {
            const Eigen::Vector2d next = s + alpha * step;
            if (!(next.norm() > 0)) continue;
            const Eigen::Vector2d Rn = residual(next, unused);
            if (Rn.norm() < R.norm()) {
                s = next;
                R = Rn;
                decreased = true;
            }
        }
        if (!decreased) return false;
        residual(s, trial);
    }
    return false;
}

}  // namespace

// Node by node (nonsmooth Gauss-Seidel): each node's own problem solved exactly with the
// others fixed, sweep after sweep, until the residual reaches the tolerance; false when it
// gives up (max_sweeps, or 50 sweeps that do not halve the best residual). With the slip-rate
// law F is taken at the node's own slip (exact_rate), else lagged at the sweep's last.
bool ContactSolver::gauss_seidel_disc(const ContactProblem& p, const ContactSolverOptions& options,
                                      Eigen::VectorXd& lambda, ContactSolveInfo& info, bool exact_rate) {
    const Eigen::Index n = p.gap_limit.size();
    const auto sweep = [&] {
        for (Eigen::Index i = 0; i < n; ++i) {
            const Eigen::Index rows[3] = {i, n + i, 2 * n + i};
            Eigen::Matrix3d A;
            for (int r = 0; r < 3; ++r)
                for (int c = 0; c < 3; ++c) A(r, c) = p.W(rows[r], rows[c]);
            double q[3];
            for (int r = 0; r < 3; ++r) {
                q[r] = u_hat_[rows[r]];
                for (int c = 0; c < 3; ++c) q[r] -= A(r, c) * lambda[rows[c]];
            }
            const double origin[2] = {p.slip_origin[i], p.slip_origin[n + i]};
            const double sx = u_hat_[rows[1]] - origin[0], sz = u_hat_[rows[2]] - origin[1];
            const double lagged = std::sqrt(sx * sx + sz * sz);  // (not hypot: no libm in the FMUs)
            const auto coefficient = [&](double slip) {
                if (!p.rate_dependent()) return p.friction[i];
                return p.coefficient(i, exact_rate ? slip : lagged);
            };
            double l[3];
            if (!solve_disc_node(q, A, p.gap_limit[i], origin, coefficient, l)) continue;  // kept
            for (int r = 0; r < 3; ++r) {
                const double change = l[r] - lambda[rows[r]];
                if (change == 0) continue;
                u_hat_.noalias() += change * p.W.col(rows[r]);
                lambda[rows[r]] = l[r];
            }
        }
    };
    // (the residual also sets u_hat_ = a + W lambda)
    return sweep_until(options, info, sweep, [&] { return full_residual(p, lambda, phi_); });
}

}  // namespace contactbody
