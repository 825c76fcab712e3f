// One midpoint substep of the reduced body (docs/decisions.md, "The reduced body"): the same
// scheme and contact problem as Stepper, on the coordinates z = (q, r) of the basis
// T = [modes, residual] plus the clamp's lift, u_free = T z + lift * top, with the residual
// massless. The step matrix is diagonal; the contact problem's Delassus operator is dense
// 2 n_c square. With every finite mode it is the full body in other coordinates.
// Under force control the basis is the clamped body's, and the lift (the body's rigid vertical
// translation, since A annihilates translations) carries the plate: its coordinate is then an
// unknown with the plate's and the body's mass, coupled to the modes through the mass only,
// and the step matrix is the diagonal bordered by that one row.
// The tangential-mass edge (reduced_edge) appends the contact x dofs X to z as coordinates of
// their own (the basis' constraint modes): M_hat and A_hat gain a dense X block, coupled to
// the modes through the mass only, and the step matrix is solved through its Schur
// complement on X (n_c square, inverted once per substep size).
#pragma once

#include <array>
#include <memory>
#include <optional>

#include "body/body.hpp"
#include "body/stepper.hpp"
#include "contact/contact_solver.hpp"
#include "reduced/clamp_rows.hpp"
#include "reduced/modal_basis.hpp"

namespace contactbody {

// A reduced state is a State in the basis' coordinates (Body): u = (z, lift_at, top) and
// v = (zdot, lift_rate, top_rate), where z holds the m modal, the k residual and (the
// tangential-mass edge) the n_c tangential coordinates,
// top and top_rate are the clamp's displacement and velocity, and lift_at the lift's
// coordinate in the free dofs, u_free = T z + lift * lift_at. The lift moves with the clamp's
// midpoint increments, as the full body's free dofs do, so it differs from top after a jump
// of a held input (set_clamp), and its rate from top_rate. Under force control lift_at and
// top are both the plate's displacement (and their rates its velocity). lambda and sticking
// are as in the full body.
using ReducedState = State;

class ReducedStepper : public Body {
public:
    ReducedStepper(const SceneParameters& params, int modes);

    const Discretization& discretization() const override { return disc_; }
    const SceneParameters& parameters() const override { return params_; }
    const ModalBasis& basis() const { return basis_; }
    Eigen::Index size() const { return static_cast<Eigen::Index>(omega2_.size()); }  // m + k + n_X
    bool tangential_mass() const { return nx_ > 0; }
    int modes() const override { return static_cast<int>(basis_.modes.cols()); }
    // Keeps the basis (it depends on the discretization and the mode count only).
    void restart(const SceneParameters& params) override;

    // The A-orthogonal projection of a full state (exact when it lies in the basis' span, as
    // every state does with every finite mode), and back.
    State from_full(const State& full) const override;
    void to_full(const State& s, State& full) const override;
    State initial_state(double top_displacement) const override;
    // E = 1/2 v^T M v + 1/2 u^T A u of u = (T z + S lift_at, e top), v likewise, with the
    // residual massless, plus the plate's 1/2 m_p v_top^2: the reduced body's own energy.
    double energy(const ReducedState& s) const;
    std::pair<double, double> kinetic_and_strain_energy(const State& s) override;
    double top_position(const State& s) const override { return s.u[size() + 1]; }
    double top_velocity(const State& s) const override { return s.v[size() + 1]; }
    double contact_height(const State& s, int node) const override;
    void contact_heights(const State& s, Eigen::Ref<Eigen::VectorXd> out) const override;
    bool set_clamp(State& s, double top, double rate) const override;
    bool fits(const State& s) const override;

    void set_friction_coefficient(double friction) override;
    SubstepReport substep(ReducedState& s, double dt, const SubstepLoad& load) override;
    const ContactSnapshot& last_contact() const override { return snapshot_; }
    const ContactProblem& last_contact_problem() const override { return problem_; }

    std::vector<double> cached_substeps() const override;
    void set_cached_substeps(const std::vector<double>& sizes) override;
    size_t operator_cache_size() const override { return 2; }
    int factorizations() const override { return operator_builds_; }
    const char* operator_name() const override {
        return "built the reduced step operators 4/dt^2 M_hat + A_hat and the Delassus operator";
    }
    // The basis' sizes and set-up time, and whether a restart kept it.
    std::string summary() const override;
    ContactSolverOptions& contact_options() override { return options_; }
    const ContactSolver& contact_solver() const override { return solver_; }
    ContactFactorization contact_factorization() const override;
    void set_contact_factorization(const ContactFactorization& f) override { saved_factorization_ = f; }

private:
    struct StepOperators {
        double dt = 0;
        Eigen::VectorXd inverse_stiffness;  // 1 / diag(4/dt^2 M + 2/dt C + A); 0 on X
        // The tangential-mass edge: K = [D, c M_dX; c M_Xd, K_XX] (c = 4/dt^2 + 2/dt alpha),
        // solved through D^-1 c M_dX and the Schur complement K_XX - c^2 M_Xd D^-1 M_dX.
        Eigen::MatrixXd tail_coupling;  // D^-1 c M_dX on the modes' rows (m x n_X)
        // The Schur complement's inverse (n_c square), formed once a substep size: a
        // matrix-vector product in place of two triangular solves with its Cholesky factor,
        // which read the same entries at a lower rate (benchmarks/results/contact_ab.md).
        Eigen::MatrixXd tail_schur_inverse;
        Eigen::MatrixXd delassus;  // B T K^-1 T^T B^T, (N, T) x (N, T)
        // Force control, the plate's bordered row: K = [D, c m_t; c m_t^T, k_pp] with
        // c = 4/dt^2 + 2/dt alpha, h = D^-1 m_t, and its Schur complement k_pp - c^2 m_t^T h.
        Eigen::VectorXd plate_coupling;  // h
        double plate_schur = 0;
    };
    const StepOperators& operators_for(double dt);
    // x <- K^-1 x for the step matrix K of ops (x holds the right-hand side).
    void solve_step(const StepOperators& ops, Eigen::Ref<Eigen::VectorXd> x) const;
    // The X block's products at a state: M_mX^T zdot_m, M_XX zdot_X and A_XX z_X. A step's
    // energies at its end and the next substep's right-hand side both need them (with outputs
    // read every step of one substep, each once a substep): formed once, kept with the zdot
    // and z_X they are of.
    struct TailProducts {
        Eigen::VectorXd zdot, z_x;
        Eigen::VectorXd mass_modes, mass_x, stiffness;
    };
    mutable TailProducts tail_products_;
    const TailProducts& tail_products(const Eigen::Ref<const Eigen::VectorXd>& z,
                                      const Eigen::Ref<const Eigen::VectorXd>& zdot) const;
    // x^T C_hat x's X block terms, C_hat = alpha M_hat + beta A_hat: one product with
    // damping_xx_ where the damping work read M_XX and A_XX each.
    double tail_damping_form(const Eigen::Ref<const Eigen::VectorXd>& x) const;

    SceneParameters params_;
    Discretization disc_;
    // Force control: the clamped body (the plate's y dofs held), on which the basis is built;
    // its free dofs are disc_'s. basis_disc() is the one the basis' rows refer to.
    std::optional<Discretization> clamped_;
    const Discretization& basis_disc() const { return clamped_ ? *clamped_ : disc_; }
    ModalBasis basis_;
    double plate_mass_ = 0;   // force control: the plate's own mass (kg/m), else 0
    Eigen::VectorXd omega2_;  // diag(A_hat): modal omega^2, then 1 for the residual, 0 on X
    Eigen::VectorXd mass_;    // diag(M_hat): 1 for the modes, 0 for the residual and on X
    // The tangential-mass edge's X block: M_hat's columns of X, on the modes' rows (M_mX) and
    // X's (M_XX) only, since the residual's rows are zero (massless): the substep's products
    // with them read a fifth of M_dX at nx = 160 with 80 modes. And A_hat's X block (Guyan's
    // condensed stiffness; A_hat has no X coupling).
    Eigen::Index tangents_ = 1;     // tangential contact unknowns per node: 1 in 2D, 2 (x, z) in 3D
    Eigen::Index nd_ = 0, nx_ = 0;  // diagonal coordinates (m + k), tangential ones (0 or n_c)
    Eigen::MatrixXd mass_mx_;       // m x n_X
    Eigen::MatrixXd mass_xx_;       // n_X x n_X
    Eigen::MatrixXd stiffness_xx_;  // n_X x n_X
    Eigen::MatrixXd damping_xx_;    // alpha M_XX + beta A_XX (of the run's parameters)
    Eigen::LLT<Eigen::MatrixXd> stiffness_xx_factor_;
    Eigen::MatrixXd Bhat_;   // B T: signed rows of the basis at the contact unknowns (N, T)
    Eigen::VectorXd Blift_;  // B lift
    // The lift S and the clamp e against the basis and each other (residual rows of the mass
    // terms zero: massless): m_s = T^T M_ff S, m_c = T^T M_fc e, a_s = T^T A_ff S, and the
    // scalars S^T M_ff S, e^T M_cf S, e^T M_cc e, S^T A_ff S, e^T A_cc e.
    Eigen::VectorXd m_s_, m_c_, a_s_;
    Eigen::VectorXd m_t_;      // m_s + m_c: the clamp and the lift moving together
    Eigen::VectorXd damping_;  // diag(C_hat) = alpha diag(M_hat) + beta diag(A_hat)
    // The clamped rows of each tangent (their reaction): against z, the lift and the clamp,
    // mass and stiffness (empty past the body's tangents).
    PerTangent<ClampRows> clamp_tangential_;
    Eigen::Index nf_ = 0;  // free dofs
    double mu_ss_ = 0, mu_cs_ = 0, mu_cc_ = 0, s_ss_ = 0;
    double mass_tt_ = 0;  // mu_ss + 2 mu_cs + mu_cc: the lift and clamp moving together (t^T M t)
    // Their stiffness t^T A t is 0: the lift is the clamp's static response with nothing else
    // holding the body, so with the clamp a rigid translation (e^T A_cc e - s_ss computed
    // rounds |A|, and a far-translated body's strain energy with it: docs/decisions.md, "Far
    // travel and the energy balance").
    std::array<std::unique_ptr<StepOperators>, 2> cache_;
    StepOperators& build_operators(double dt);
    void start_run();
    int operator_builds_ = 0;
    int restarts_ = 0;
    ContactSolverOptions options_;
    ContactSolver solver_;
    ContactSnapshot snapshot_;
    ContactProblem problem_;
    double problem_dt_ = -1;
    ContactFactorization saved_factorization_;  // set_contact_factorization's, until its substep
    bool problem_friction_ = false;
    // Rows [r0, r0 + rows) of B_hat times x, and B_hat's first rows transposed times lambda.
    void edge_product(Eigen::Index r0, Eigen::Index rows, const Eigen::Ref<const Eigen::VectorXd>& x,
                      Eigen::Ref<Eigen::VectorXd> y) const;
    void stored_rows_product(Eigen::Index r0, Eigen::Index rows, const Eigen::Ref<const Eigen::VectorXd>& x,
                             Eigen::Ref<Eigen::VectorXd> y) const;
    // The tangential-mass edge: B_hat's tangential rows are (0, 0, I) (the modes and residual
    // vanish on X's rows, the constraint modes are the identity there), checked exactly at
    // construction; their products are then copies of X's coordinates.
    bool tangential_rows_are_x_ = false;
    void edge_transposed_product(Eigen::Index rows, const Eigen::Ref<const Eigen::VectorXd>& lambda,
                                 Eigen::Ref<Eigen::VectorXd> y) const;
    // B_N u at a state (the normal rows at the contact nodes: minus the heights), kept with
    // the z and lift it was formed at: the substep's start and the step's edge output ask
    // for the same one, and B_hat's rows are a memory-bound read.
    const Eigen::VectorXd& normal_displacements(const State& s) const;
    mutable Eigen::VectorXd normal_u_, normal_u_at_;
    // Workspace, sized once: the substep allocates nothing.
    Eigen::VectorXd rhs_, w_, contact_u_, bw_, du_, contact_force_, dw_;
    mutable Eigen::VectorXd tail_, form_;  // solve_step's, the X block's forms'
};

}  // namespace contactbody
