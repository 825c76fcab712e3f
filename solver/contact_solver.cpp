#include "contact_solver.hpp"

#include <cmath>
#include <limits>
#include <sstream>

namespace contactbody {

// Alart-Curnier residual phi(lambda), zero exactly at a solution; piecewise linear in lambda,
// so a semi-smooth Newton step lands on the solution once the node states are right.
// The augmentation parameters r = 1 / diag(W) make phi a force in every row.
double ContactSolver::residual(const ContactProblem& p, const Eigen::VectorXd& lambda,
                               Eigen::VectorXd& phi) {
    const Eigen::Index n = p.gap_limit.size();
    const bool friction = p.has_friction();
    u_hat_.noalias() = p.W * lambda;
    u_hat_ += p.a;
    phi.resize(lambda.size());
    status_.resize(n);
    for (Eigen::Index i = 0; i < n; ++i) {
        const double pressure = -lambda[i];
        const double trial = pressure - r_[i] * (p.gap_limit[i] - u_hat_[i]);
        if (trial <= 0) {
            phi[i] = pressure;
            if (friction) phi[n + i] = lambda[n + i];
            status_[i] = NodeStatus::open;
            continue;
        }
        phi[i] = pressure - trial;
        if (!friction) {
            status_[i] = NodeStatus::stick;
            continue;
        }
        const double bound = p.friction * trial;
        const double z = lambda[n + i] - r_[n + i] * (u_hat_[n + i] - p.slip_origin[i]);
        if (std::abs(z) <= bound) {
            phi[n + i] = lambda[n + i] - z;
            status_[i] = NodeStatus::stick;
        } else {
            phi[n + i] = lambda[n + i] - std::copysign(bound, z);
            status_[i] = NodeStatus::slip;
        }
    }
    const double scale = lambda.lpNorm<Eigen::Infinity>();
    const double size = phi.lpNorm<Eigen::Infinity>();
    if (size == 0) return 0;
    return scale > 0 ? size / scale : std::numeric_limits<double>::infinity();
}

// Generalized Jacobian of phi at lambda, for the node states found by residual().
void ContactSolver::jacobian(const ContactProblem& p, const Eigen::VectorXd& lambda) {
    const Eigen::Index n = p.gap_limit.size(), m = lambda.size();
    const bool friction = p.has_friction();
    jacobian_.setZero(m, m);
    for (Eigen::Index i = 0; i < n; ++i) {
        if (status_[i] == NodeStatus::open) {
            jacobian_(i, i) = -1;
            if (friction) jacobian_(n + i, n + i) = 1;
            continue;
        }
        jacobian_.row(i) = -r_[i] * p.W.row(i);
        if (!friction) continue;
        if (status_[i] == NodeStatus::stick) {
            jacobian_.row(n + i) = r_[n + i] * p.W.row(n + i);
        } else {
            const double z = lambda[n + i] - r_[n + i] * (u_hat_[n + i] - p.slip_origin[i]);
            const double sf = std::copysign(p.friction, z);
            // d(trial)/d(lambda) = -e_N + r_N W(N, :)
            jacobian_.row(n + i) = -sf * r_[i] * p.W.row(i);
            jacobian_(n + i, i) += sf;
            jacobian_(n + i, n + i) += 1;
        }
    }
}

ContactSolveInfo ContactSolver::solve(const ContactProblem& p,
                                      const ContactSolverOptions& options,
                                      Eigen::VectorXd& lambda) {
    const Eigen::Index m = p.W.rows();
    if (lambda.size() != m) lambda.setZero(m);
    r_ = p.W.diagonal().cwiseInverse();

    ContactSolveInfo info;
    info.residual = residual(p, lambda, phi_);
    double merit = phi_.squaredNorm();
    while (!(info.residual <= options.tolerance)) {
        if (info.iterations >= options.max_iterations) {
            std::ostringstream msg;
            msg << "contact solver did not converge in " << options.max_iterations
                << " iterations (relative residual " << info.residual << ", tolerance "
                << options.tolerance << ")";
            throw ContactSolveError(msg.str());
        }
        ++info.iterations;
        jacobian(p, lambda);
        lu_.compute(jacobian_);
        step_ = lu_.solve(-phi_);
        if (!step_.allFinite())
            throw ContactSolveError("contact solver: singular Newton matrix");
        // Backtracking on |phi|^2; if no step decreases it, take the full one anyway
        // (phi is piecewise linear: the full step is exact once the states settle).
        double alpha = 1;
        bool decreased = false;
        for (int k = 0; k < 8 && !decreased; ++k) {
            if (k > 0) alpha *= 0.5;
            trial_ = lambda + alpha * step_;
            const double res = residual(p, trial_, trial_phi_);
            decreased = trial_phi_.squaredNorm() <= (1 - 1e-4 * alpha) * merit ||
                        res <= options.tolerance;
        }
        if (!decreased) alpha = 1;
        lambda += alpha * step_;
        info.residual = residual(p, lambda, phi_);
        merit = phi_.squaredNorm();
    }
    return info;
}

}  // namespace contactbody
