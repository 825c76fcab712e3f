// One midpoint substep with frictional contact (paper eq. 20-22), with Rayleigh
// damping C v̄ (v̄ = (u^{k+1} - u^k)/dt) when C is not empty.
//
// The unknown is the increment w = u^{k+1/2} - u^k. On the free dofs it solves
//   K w = 2/dt M v^k - A u^k - K_fc w_c + B^T lambda,   K = 4/dt^2 M + 2/dt C + A,
// (the midpoint equation K u^{k+1/2} = M (4/dt^2 u^k + 2/dt v^k) + 2/dt C u^k + ... less K u^k),
// condensed to the contact unknowns: w = w0 + K^-1 B^T lambda with w0 = K^-1 rhs, so that
// B w = B w0 + W lambda with the Delassus operator W = B K^-1 B^T (dense, 2 n_c square),
// evaluated on the trailing block of a factor with the contact dofs ordered last.
#pragma once

#include <Eigen/Dense>
#include <array>
#include <memory>
#include <vector>

#include "assembly/discretization.hpp"
#include "body/body.hpp"
#include "contact/contact_solver.hpp"
#include "contact/friction_law.hpp"
#include "contact/sparse_contact.hpp"

namespace contactbody {

struct State {
    Eigen::VectorXd u, v;      // all dofs (clamped ones carry the top displacement)
    Eigen::VectorXd lambda;    // last multipliers: lambda_N[n_c], then lambda_T[n_c] if F > 0
    Eigen::VectorXd sticking;  // n_c: 1 where the node stuck in the last substep, else 0
    double time = 0;
};

// Loads over one substep: top displacement at its ends (and its rate, for the clamped
// velocity), foundation velocity.
struct SubstepLoad {
    double top_start = 0, top_end = 0, top_rate = 0;
    Tangential foundation_velocity{};  // per tangent (a 3D body's foundation slides in x and z)
    double top_force = 0;              // force control: N/m pressing the plate down, over the substep
};

// Exact discrete work of each force on the body (J/m), so that over any run
//   E - E(0) = clamp + normal_contact + friction - damping,
// and friction = foundation - friction_dissipation.
struct Works {
    double clamp = 0;                 // clamp reaction over the clamped dofs' displacement, or
                                      // the top force over the plate's (force control)
    double normal_contact = 0;        // sum lambda_N (u_N^{k+1} - u_N^k)
    double friction = 0;              // sum lambda_T (u_x^{k+1} - u_x^k)
    double friction_dissipation = 0;  // sum lambda_T (V dt - (u_x^{k+1} - u_x^k)), >= 0
    double foundation = 0;            // sum lambda_T V dt: what the foundation's drive pays
    double damping = 0;               // dt vbar^T C vbar, vbar = (u^{k+1} - u^k)/dt, >= 0

    // Calls f on the matching fields of a and b (either may be const).
    template <class A, class B, class F>
    static void for_each(A& a, B& b, F&& f) {
        f(a.clamp, b.clamp);
        f(a.normal_contact, b.normal_contact);
        f(a.friction, b.friction);
        f(a.friction_dissipation, b.friction_dissipation);
        f(a.foundation, b.foundation);
        f(a.damping, b.damping);
    }
    Works& operator+=(const Works& o) {
        for_each(*this, o, [](double& x, double y) { x += y; });
        return *this;
    }
};

// What one substep contributes to the observables (forces on the body, N/m).
struct SubstepReport {
    double normal_force = 0;      // -sum lambda_N
    Tangential friction_force{};  // sum lambda_T, per tangent
    double corner_lambda_N = 0, corner_lambda_T = 0;
    PerComponent top_reaction{};
    Works work;
    double max_penetration = 0;  // max(0, -gap) at u^{k+1}
    int active_nodes = 0, slipping_nodes = 0;
    int contact_iterations = 0;
    int contact_sweeps = 0;       // Gauss-Seidel fallback sweeps (0: Newton converged)
    bool contact_solved = false;  // false when no node could touch (solve skipped)
};

// The last substep's contact quantities recomputed from the displacement u^{k+1/2}
// (not from the condensed problem), so that tests can check the contact law independently.
struct ContactSnapshot {
    Eigen::VectorXd normal_displacement;  // B_N u^{k+1/2}
    Eigen::VectorXd gap_limit;            // B_N u^{k+1/2} <= gap_limit
    Eigen::VectorXd slip;                 // B_T u^{k+1/2} - slip origin (sign of the slip velocity)
    Eigen::VectorXd lambda_N;
    // Per tangent (empty past the body's tangents): the friction multipliers, and the slip
    // velocity relative to the foundation, (u_T^{k+1} - u_T^k) / dt - V.
    PerTangent<Eigen::VectorXd> lambda_T, slip_velocity;
    Eigen::VectorXd delassus_diagonal;                    // diag(W), (N, T): displacement per unit multiplier
    Eigen::Matrix<signed char, Eigen::Dynamic, 1> state;  // 0 open, 1 stick, 2 slip
};

// Where a substep's time goes, accumulated when timing is enabled (benchmarks).
struct SubstepTimings {
    double solve = 0;    // sparse forward/backward solves
    double contact = 0;  // condensed problem set-up and Newton
    double update = 0;   // right-hand side, state update, reaction, snapshot
    double factor = 0;   // factorization and Delassus operator
};

// What the full and the reduced stepper share around the contact solve.
// The contact conditions of one substep, given each node's gap_old(i) = g - u_N^k: gap limits,
// slip origins, the slip-rate law's slip time and, without a Stribeck velocity, the stick
// memory's coefficients. Returns whether any node can touch.
template <class GapOld>
bool set_contact_conditions(ContactProblem& problem, const SceneParameters& p, bool implicit, double dt,
                            const SubstepLoad& load, const Eigen::VectorXd& sticking, GapOld&& gap_old) {
    const int nc = static_cast<int>(problem.gap_limit.size());
    const bool friction = problem.has_friction();
    bool touching = false;
    for (int i = 0; i < nc; ++i) {
        const double g = gap_old(i);
        problem.gap_limit[i] = implicit ? 0.5 * g : g;
        touching = touching || problem.a[i] > problem.gap_limit[i];
        for (int t = 0; friction && t < problem.tangents; ++t)
            problem.slip_origin[t * nc + i] = 0.5 * dt * load.foundation_velocity[static_cast<size_t>(t)];
    }
    // The slip rate the law sees is the one the friction works on, in every variant: the
    // substep's mean (u_T^{k+1} - u_T^k) / dt - V = slip / (dt/2). Then lambda_T opposes the
    // very motion over which its work lambda_T (u_T^{k+1} - u_T^k - V dt) is counted, and
    // friction dissipates in every substep (docs/decisions.md, "Friction works on the slip
    // rate it sees").
    const bool stribeck = friction && p.stribeck_velocity > 0;
    if (friction) {
        problem.rate = rate_law(p);
        problem.rate.slip_time = 0.5 * dt;
    }
    // Without a Stribeck velocity the static coefficient is a memory: the nodes that stuck in
    // the last substep hold with F_s. With one, F_s is the law's value at zero slip rate.
    if (friction && p.static_friction_ratio != 1 && !stribeck)
        for (int i = 0; i < nc; ++i)
            problem.friction[i] = p.friction_coefficient * (sticking[i] != 0 ? p.static_friction_ratio : 1.0);
    return touching;
}

// One contact node's share of a substep's report, from its multipliers and its motion
// (uN_old = u_N^k, duN and dux its normal and tangential increments over the substep);
// updates its stick memory. `status` is the solver's only when `touching` (else it holds none:
// pass open). Returns the node's state (0 open, 1 stick, 2 slip).
int add_node_contact(SubstepReport& report, double& sticking, double lN, double lT, double uN_old, double duN,
                     double dux, double foundation_step, double initial_gap, bool friction, bool touching,
                     NodeStatus status);

// After a substep, what both steppers report of the edge: the snapshot's multipliers, slip
// velocities and node states, and each node's share of the report (add_node_contact, and the
// further tangents' friction and works), given each node's u_N^k, uN_old(i), and its
// increments over the substep, duN(i) and duT(i, t) along tangent t; node i's gap at rest is
// initial_gap + heights[i] (the mesh's contact_heights).
// The snapshot's vectors are sized once (the substep allocates nothing after the first).
template <class NormalOld, class NormalStep, class TangentialStep>
void record_contact(SubstepReport& report, ContactSnapshot& snapshot, Eigen::VectorXd& sticking,
                    const Eigen::VectorXd& lambda, double dt, const Tangential& foundation_velocity,
                    int tangents, double initial_gap, const std::vector<double>& heights, bool touching,
                    const Eigen::Matrix<NodeStatus, Eigen::Dynamic, 1>& status, NormalOld&& uN_old,
                    NormalStep&& duN, TangentialStep&& duT) {
    const Eigen::Index nc = sticking.size();
    const bool friction = lambda.size() > nc;
    snapshot.state.resize(nc);
    snapshot.lambda_N = lambda.head(nc);
    for (int t = 0; t < tangents; ++t) {
        Eigen::VectorXd& lT = snapshot.lambda_T[static_cast<size_t>(t)];
        lT.resize(nc);
        if (friction)
            lT = lambda.segment((1 + t) * nc, nc);
        else
            lT.setZero();
        snapshot.slip_velocity[static_cast<size_t>(t)].resize(nc);
    }
    // The normal and the first tangent node by node, then each further tangent's friction.
    for (int t = 0; t < tangents; ++t) {
        const double foundation_step = foundation_velocity[static_cast<size_t>(t)] * dt;
        const Eigen::VectorXd& lT = snapshot.lambda_T[static_cast<size_t>(t)];
        Eigen::VectorXd& slip_velocity = snapshot.slip_velocity[static_cast<size_t>(t)];
        for (int i = 0; i < static_cast<int>(nc); ++i) {
            const double d = duT(i, t);
            slip_velocity[i] = (d - foundation_step) / dt;
            if (t == 0) {
                snapshot.state[i] = static_cast<signed char>(
                    add_node_contact(report, sticking[i], snapshot.lambda_N[i], lT[i], uN_old(i), duN(i), d,
                                     foundation_step, initial_gap + heights[static_cast<size_t>(i)], friction,
                                     touching, touching ? status[i] : NodeStatus::open));
            } else {
                report.friction_force[static_cast<size_t>(t)] += lT[i];
                report.work.friction += lT[i] * d;
                report.work.foundation += lT[i] * foundation_step;
                report.work.friction_dissipation += lT[i] * (foundation_step - d);
            }
        }
    }
    report.corner_lambda_N = snapshot.lambda_N[0];
    report.corner_lambda_T = snapshot.lambda_T[0][0];
}

// The full body: every dof of the mesh is a coordinate of its State.
class Stepper : public Body {
public:
    explicit Stepper(const SceneParameters& params);
    ~Stepper() override;

    // Starts over with new parameters of the same discretization (same_discretization): the
    // stepper is then as if constructed from them, but keeps its discretization and its
    // factors, which a substep of exactly the same size takes instead of refactoring. The
    // results are the same bits as a new stepper's (a factor depends only on the
    // discretization and its size). Throws std::invalid_argument for invalid parameters.
    void restart(const SceneParameters& params) override;

    const Discretization& discretization() const override { return disc_; }
    const SceneParameters& parameters() const override { return params_; }

    // The paper's initial state: u_x = 0, u_y = top * y / H, and v = the initial velocity on
    // the moving dofs (0 unless initial_velocity_x, _y are set).
    State initial_state(double top_displacement) const override;
    static State paper_initial_state(const Discretization& d, const SceneParameters& p,
                                     double top_displacement);
    State from_full(const State& full) const override { return full; }
    void to_full(const State& s, State& full) const override { full = s; }
    // Friction coefficient is tunable between substeps (F = 0 drops the tangential unknowns).
    void set_friction_coefficient(double friction) override;
    // The coefficient of the slipping rows a held factor may have: the kinetic F of a 2D body
    // (a 3D body's slip law is linearized at each iterate: its slips stay GCR's).
    double slip_coefficient() const;
    // The contact unknowns a node has in the held operator: y and x, and with friction every
    // tangent's.
    int held_unknowns_per_node(double friction) const;

    SubstepReport substep(State& s, double dt, const SubstepLoad& load) override;
    const ContactSnapshot& last_contact() const override { return snapshot_; }

    std::pair<double, double> kinetic_and_strain_energy(const State& s) override;
    double top_position(const State& s) const override { return s.u[disc_.top_y_dof()]; }
    double top_velocity(const State& s) const override { return s.v[disc_.top_y_dof()]; }
    double contact_height(const State& s, int node) const override {
        return s.u[disc_.mesh.dof(disc_.mesh.contact_nodes[static_cast<size_t>(node)], Mesh::normal)];
    }
    bool set_clamp(State& s, double top, double rate) const override;
    bool fits(const State& s) const override;

    const ContactProblem& last_contact_problem() const override { return problem_; }
    // Substep sizes of the cached factors, most recent first (Body::cached_substeps):
    // restoring them rebuilds exactly those factors.
    std::vector<double> cached_substeps() const override;
    void set_cached_substeps(const std::vector<double>& sizes) override;
    static constexpr size_t factor_cache_size = 2;
    size_t operator_cache_size() const override { return factor_cache_size; }
    double new_operator_in_solves() const override;
    int factorizations() const override { return factorizations_; }  // over the stepper's life
    const char* operator_name() const override { return "factorized 4/dt^2 M + A"; }
    // Which contact solve the factors carry: automatic takes the measured cost model
    // (sparse_contact_pays); the others force one (tests, benchmarks). Drops cached factors.
    // A consistent-mass body's contact at the end of the step (variant 3) or at its midpoint
    // (variant 0): the same mass and K, so the static start's load path and its settling
    // substep share one body and its factor. Throws std::logic_error for the other variants.
    void set_contact_at_end_of_step(bool at_end);
    // sparse_gcr: the sparse solve with no slipping rows in its factors (a slipping node's
    // friction left to GCR: the solve before the factor held them; benchmarks compare).
    enum class ContactPath { automatic, condensed, sparse, sparse_gcr };
    void set_contact_path(ContactPath path);
    // Tests: the sparse solve's factor is the supernodal one whatever its flops.
    void set_supernodal_factor(bool supernodal);
    // Whether the last substep's factor solves the contact on the sparse system.
    bool sparse_contact() const;
    // The cost model: the sparse solve where the condensed one's dense work per substep,
    // about (2 n_c)^2, exceeds kappa(F) = kappa_0 + kappa_F F times the unknowns n_f (a sparse
    // solve's work grows with them, and the friction costs it held solves), the constants
    // fitted to benchmarks/contact_crossover.py's bounds (docs/decisions.md, "Which solve"). The
    // choice is made when a factor is made. A slip-rate law keeps the condensed solve (its full
    // Jacobian and exact node solves need W).
    static bool sparse_contact_pays(Eigen::Index contact_nodes, Eigen::Index unknowns, double friction);
    static double sparse_contact_kappa(double friction) {
        return sparse_contact_kappa_0 + sparse_contact_kappa_F * friction;
    }
    static constexpr double sparse_contact_kappa_0 = 8, sparse_contact_kappa_F = 35;
    const SparseContactSolver& sparse_solver() const { return sparse_solver_; }
    // Which contact solve the body takes, and why (the log's).
    std::string summary() const override;
    long sparse_refactorizations() const;   // of the cached factors' held operators
    double sparse_refactored_work() const;  // what they factored, in whole factorizations
    // The last substep's factor of K (the sparse solve's, its held set's rows and columns the
    // identity's, or the condensed solve's Cholesky factor): its size and one solve with it,
    // the floor of a substep, for benchmarks. Throws std::logic_error before the first substep.
    TrailingCholesky& last_factor();
    // The sparse solve's held set (as a node pattern: 0 free, 2 y held, 1 x and y held, +-3 y
    // held and x slipping with +-F) of the
    // current factor: a saved state keeps it, so that a restored one solves on the same.
    ContactFactorization contact_factorization() const override;
    void set_contact_factorization(const ContactFactorization& f) override;
    void forget_kept() override { sparse_solver_.forget(); }
    void enable_timing(bool on) { timing_ = on; }
    const SubstepTimings& timings() const { return timings_; }
    ContactSolverOptions& contact_options() override { return options_; }
    const ContactSolver& contact_solver() const override { return solver_; }

private:
    struct Factor;
    Factor& factor_for(double dt);
    void setup_contact_problem(const Factor& f);

    SceneParameters params_;
    Discretization disc_;
    ContactSolverOptions options_;
    ContactSolver solver_;
    SparseContactSolver sparse_solver_;
    ContactPath contact_path_ = ContactPath::automatic;
    bool supernodal_factor_ = false;
    bool wants_sparse() const;
    ContactProblem problem_;
    // Most recent first: masters alternate step sizes. Two, as before refinement existed: which
    // factor a substep reuses decides its last bits, and the paper's figures are kept bit for
    // bit (a refined substep refactors its sizes; refinement is the rare path).
    std::array<std::unique_ptr<Factor>, factor_cache_size> cache_;
    // Factors no longer in cache_ (kept by restart, or dropped from it), most recent first, at
    // most spare_capacity: make_factor takes one of exactly its size instead of refactoring,
    // which gives the same bits (a factor depends only on the discretization and its size).
    // A refined substep's halves use them: without, a run that halves often refactored the
    // nominal size and every half each time (the 2-entry cache thrashed).
    std::vector<std::unique_ptr<Factor>> spare_;
    static constexpr size_t spare_capacity = 8;
    void keep_spare(std::unique_ptr<Factor> f);
    std::unique_ptr<Factor> make_factor(double dt);
    void start_run();         // the state of a new stepper, but for the discretization and factors
    int factor_ids_ = 0;      // factors built or taken from spare_: problem_factor_ names one
    int problem_factor_ = 0;  // id of the factor problem_.W was built from
    // The factor the last substep used: another one (new, switched to after a change of the
    // substep size, or after a restart) starts at the state's own held set.
    int current_factor_ = 0;
    int factorizations_ = 0;
    bool timing_ = false;
    SubstepTimings timings_;
    ContactSnapshot snapshot_;
    // Workspace, sized once.
    // w: u^{k+1/2} - u^k (w_free_ the unknowns'), relative_: u minus node 0's translation,
    // clamped_half_: the clamped dofs' w.
    Eigen::VectorXd relative_, rhs_, w_free_, w_, clamped_half_, du_, C_du_, product_;
    Eigen::VectorXd normal_free_, normal_mass_;  // a translation along y in the unknowns, and M times it
};

}  // namespace contactbody
