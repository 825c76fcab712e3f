// One midpoint substep of the reduced body (docs/decisions.md, "The reduced body"): the same
// scheme and contact problem as Stepper, on the coordinates z = (q, r) of the basis
// T = [modes, residual] plus the clamp's lift, u_free = T z + lift * top, with the residual
// massless. The step matrix is diagonal; the contact problem's Delassus operator is dense
// 2 n_c square. With every finite mode it is the full body in other coordinates.
// Displacement control only (the basis refuses force control).
#pragma once

#include <array>
#include <memory>

#include "contact_solver.hpp"
#include "modal_basis.hpp"
#include "stepper.hpp"

namespace contactbody {

struct ReducedState {
    Eigen::VectorXd z, zdot;   // m modal then k residual coordinates, and their rates
    Eigen::VectorXd lambda;    // as State::lambda
    Eigen::VectorXd sticking;  // as State::sticking
    double top = 0, top_rate = 0;  // the clamp's displacement and velocity
    // The lift's coordinate and rate in the free dofs: u_free = T z + lift * lift_at. It moves
    // with the clamp's midpoint increments, as the full body's free dofs do, so it differs
    // from `top` after a jump of a held input, and its rate from top_rate.
    double lift_at = 0, lift_rate = 0;
    double time = 0;
};

class ReducedStepper {
public:
    ReducedStepper(const SceneParameters& params, int modes);

    const Discretization& discretization() const { return disc_; }
    const ModalBasis& basis() const { return basis_; }
    int num_contact_nodes() const { return static_cast<int>(disc_.contact_x.size()); }
    Eigen::Index size() const { return static_cast<Eigen::Index>(omega2_.size()); }

    // The A-orthogonal projection of a full state (exact when it lies in the basis' span, as
    // every state does with every finite mode), and back.
    ReducedState reduce(const State& full) const;
    void expand(const ReducedState& s, State& full) const;
    // E = 1/2 v^T M v + 1/2 u^T A u of u = (T z + S lift_at, e top), v likewise, with the
    // residual massless: the reduced body's own energy.
    double energy(const ReducedState& s) const;

    void set_friction_coefficient(double friction);
    SubstepReport substep(ReducedState& s, double dt, const SubstepLoad& load);

private:
    struct StepOperators {
        double dt = 0;
        Eigen::VectorXd inverse_stiffness;  // 1 / diag(4/dt^2 M + 2/dt C + A)
        Eigen::MatrixXd delassus;           // B T K^-1 T^T B^T, (N, T) x (N, T)
    };
    const StepOperators& operators_for(double dt);

    SceneParameters params_;
    Discretization disc_;
    ModalBasis basis_;
    Eigen::VectorXd omega2_;   // diag(A_hat): modal omega^2, then 1 for the residual
    Eigen::VectorXd mass_;     // diag(M_hat): 1 for the modes, 0 for the residual
    Eigen::MatrixXd Bhat_;     // B T: signed rows of the basis at the contact unknowns (N, T)
    Eigen::VectorXd Blift_;    // B lift
    // The lift S and the clamp e against the basis and each other (residual rows of the mass
    // terms zero: massless): m_s = T^T M_ff S, m_c = T^T M_fc e, a_s = T^T A_ff S, and the
    // scalars S^T M_ff S, e^T M_cf S, e^T M_cc e, S^T A_ff S, e^T A_cc e.
    Eigen::VectorXd m_s_, m_c_, a_s_;
    Eigen::VectorXd m_t_;      // m_s + m_c: the clamp and the lift moving together
    Eigen::VectorXd damping_;  // diag(C_hat) = alpha diag(M_hat) + beta diag(A_hat)
    double mu_ss_ = 0, mu_cs_ = 0, mu_cc_ = 0, s_ss_ = 0, e_cc_ = 0;
    std::array<std::unique_ptr<StepOperators>, 2> cache_;
    ContactSolverOptions options_;
    ContactSolver solver_;
    ContactProblem problem_;
    double problem_dt_ = -1;
    bool problem_friction_ = false;
    // Workspace, sized once: the substep allocates nothing.
    Eigen::VectorXd rhs_, w_, contact_u_, contact_v_, bw_, du_, contact_force_;
};

}  // namespace contactbody
