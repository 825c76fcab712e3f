// Standard mass-carrying Craig-Bampton reduction of the body, for comparison with the
// massless-boundary reduced body (docs/decisions.md, "Massless against mass-carrying"): the
// contact edge's dofs kept physical, the interior reduced to its m lowest fixed-interface
// modes plus the constraint modes (the interior's static response to a unit displacement of
// each edge dof), and the clamp's lift with the edge held. The constraint modes carry the
// interior's mass onto the edge: M_hat = T^T M T is dense and the edge has inertia in every
// variant, which is what the paper's redistribution takes away. Benchmark path (not in the
// FMU): the same scheme and contact problem as the other bodies, with dense step operators.
#pragma once

#include <array>
#include <memory>

#include "body/body.hpp"
#include "body/stepper.hpp"
#include "contact/contact_solver.hpp"
#include "reduced/clamp_rows.hpp"

namespace contactbody {

class CraigBamptonStepper : public Body {
public:
    // State layout as the reduced body's: u = (q, u_edge, lift_at, top), v their rates.
    CraigBamptonStepper(const SceneParameters& params, int modes);

    const Discretization& discretization() const override { return disc_; }
    const SceneParameters& parameters() const override { return params_; }
    Eigen::Index size() const { return mass_.rows(); }  // m + 2 n_c
    int modes() const override { return modes_; }
    void restart(const SceneParameters& params) override;

    State initial_state(double top_displacement) const override;
    State from_full(const State& full) const override;
    void to_full(const State& s, State& full) const override;

    void set_friction_coefficient(double friction) override;
    SubstepReport substep(State& s, double dt, const SubstepLoad& load) override;
    const ContactSnapshot& last_contact() const override { return snapshot_; }
    const ContactProblem& last_contact_problem() const override { return problem_; }

    std::pair<double, double> kinetic_and_strain_energy(const State& s) override;
    double top_position(const State& s) const override { return s.u[size() + 1]; }
    double top_velocity(const State& s) const override { return s.v[size() + 1]; }
    double contact_height(const State& s, int node) const override;
    bool set_clamp(State& s, double top, double rate) const override;
    bool fits(const State& s) const override;

    std::vector<double> cached_substeps() const override;
    void set_cached_substeps(const std::vector<double>& sizes) override;
    size_t operator_cache_size() const override { return 2; }
    int factorizations() const override { return operator_builds_; }
    ContactSolverOptions& contact_options() override { return options_; }
    const ContactSolver& contact_solver() const override { return solver_; }
    const char* operator_name() const override {
        return "factorized the Craig-Bampton step matrix 4/dt^2 M_hat + A_hat";
    }
    double setup_seconds() const { return setup_seconds_; }
    double highest_frequency_hz() const { return highest_hz_; }  // of the kept interior modes

private:
    struct StepOperators {
        double dt = 0;
        Eigen::LLT<Eigen::MatrixXd> stiffness;  // 4/dt^2 M_hat + 2/dt C_hat + A_hat
        Eigen::MatrixXd delassus;               // B_hat K_hat^-1 B_hat^T
    };
    const StepOperators& operators_for(double dt);
    StepOperators& build_operators(double dt);
    void start_run();

    SceneParameters params_;
    Discretization disc_;
    int modes_ = 0;
    Eigen::MatrixXd T_;                             // free dofs x (m + 2 n_c)
    Eigen::VectorXd lift_;                          // free dofs: the clamp's static response, the edge held
    Eigen::MatrixXd mass_, stiffness_, damping_;    // M_hat, A_hat, C_hat (dense)
    Eigen::LLT<Eigen::MatrixXd> stiffness_factor_;  // of A_hat: the A-orthogonal projection
    Eigen::MatrixXd Bhat_;                          // B T
    Eigen::VectorXd Blift_;                         // B lift (zero: the lift holds the edge)
    // Couplings with the lift S and the clamp e: m_s = T^T M_ff S, m_c = T^T M_fc e,
    // a_s = T^T A_ff S, a_c = T^T A_fc e, and their scalars.
    Eigen::VectorXd m_s_, m_c_, a_s_, a_c_, m_t_, a_t_;
    Eigen::VectorXd damping_coupling_;  // C's (y, lift + clamp) column: alpha m_t + beta a_t
    double mu_ss_ = 0, mu_cs_ = 0, mu_cc_ = 0, s_ss_ = 0, s_cs_ = 0, e_cc_ = 0;
    ClampRows clamp_x_;
    std::array<std::unique_ptr<StepOperators>, 2> cache_;
    int operator_builds_ = 0;
    double setup_seconds_ = 0, highest_hz_ = 0;
    ContactSolverOptions options_;
    ContactSolver solver_;
    ContactSnapshot snapshot_;
    ContactProblem problem_;
    double problem_dt_ = -1;
    bool problem_friction_ = false;
    Eigen::VectorXd rhs_, w_, contact_u_, bw_, du_;
};

}  // namespace contactbody
