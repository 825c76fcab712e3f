// Communication steps of the body and its observables (docs/contract.md).
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "body/body.hpp"
#include "body/stepper.hpp"

namespace contactbody {

// Substeps one communication step may take: beyond, the step is refused (an int counts them,
// and a master that sends such a step has almost surely mistaken its units).
constexpr double max_substeps_per_step = 1e8;

struct Observables {
    double energy = 0, kinetic_energy = 0, strain_energy = 0;
    double friction_work = 0, energy_minus_friction_work = 0;
    // Works on the body since t0 (Works): E - E(0) = clamp + normal_contact + friction - damping.
    double damping_work = 0, clamp_work = 0, normal_contact_work = 0;
    double friction_dissipation = 0, foundation_work = 0;
    double top_position = 0, top_velocity = 0;  // u_y, v_y of the top edge (the plate)
    // Averaged over the last communication step.
    double normal_force = 0;
    Tangential friction_force{};  // per tangent (z: a 3D body's, 0 in 2D)
    double corner_pressure = 0, corner_friction = 0;
    PerComponent top_reaction{};  // per component (z: a 3D body's, 0 in 2D)
    double max_penetration = 0;   // over the substeps of the last communication step
    int active_contact_nodes = 0, slipping_contact_nodes = 0;  // at the last substep
    // What the last communication step cost (StepStatistics): substeps taken (a refined one
    // counts once per piece), refinements, Newton iterations and Gauss-Seidel sweeps.
    int substeps = 0, substep_refinements = 0, contact_iterations = 0, gauss_seidel_sweeps = 0;

    // Every field once, with the FMU output it is: f(name, the field of each o...). The
    // finiteness check, the FMU's output variables and its saved state follow this list (the
    // state's bytes in this order).
    template <class F, class... O>
    static void for_each(F&& f, O&... o) {
        f("energy", o.energy...);
        f("kinetic_energy", o.kinetic_energy...);
        f("strain_energy", o.strain_energy...);
        f("friction_work", o.friction_work...);
        f("energy_minus_friction_work", o.energy_minus_friction_work...);
        f("normal_force", o.normal_force...);
        f("friction_force", o.friction_force[0]...);
        f("friction_force_z", o.friction_force[1]...);
        f("corner_pressure", o.corner_pressure...);
        f("corner_friction", o.corner_friction...);
        f("top_reaction_x", o.top_reaction[0]...);
        f("top_reaction_y", o.top_reaction[1]...);
        f("top_reaction_z", o.top_reaction[2]...);
        f("max_penetration", o.max_penetration...);
        f("damping_work", o.damping_work...);
        f("clamp_work", o.clamp_work...);
        f("normal_contact_work", o.normal_contact_work...);
        f("friction_dissipation", o.friction_dissipation...);
        f("foundation_work", o.foundation_work...);
        f("top_position", o.top_position...);
        f("top_velocity", o.top_velocity...);
        f("active_contact_nodes", o.active_contact_nodes...);
        f("slipping_contact_nodes", o.slipping_contact_nodes...);
        f("substeps", o.substeps...);
        f("substep_refinements", o.substep_refinements...);
        f("contact_iterations", o.contact_iterations...);
        f("gauss_seidel_sweeps", o.gauss_seidel_sweeps...);
    }
};

// The bottom edge after a communication step, node by node (the edge history output).
struct EdgeSnapshot {
    Eigen::VectorXd x;         // m: the nodes' positions along the edge (reference)
    Eigen::VectorXd pressure;  // Pa: normal contact force / the node's share of the edge,
                               //     averaged over the step like normal_force
    // Per tangent (empty past the body's tangents):
    PerTangent<Eigen::VectorXd> friction;       // Pa: force density, averaged like friction_force
    PerTangent<Eigen::VectorXd> slip_velocity;  // m/s: node velocity minus V over the last substep
    Eigen::VectorXd gap;                        // m: height above the foundation at the end of the step
    Eigen::Matrix<signed char, Eigen::Dynamic, 1> state;  // last substep: 0 open, 1 stick, 2 slip
    Eigen::VectorXd z;  // m: a 3D body's positions across the edge (empty in 2D)
};

// Inputs over one communication step: values at its start and their time derivatives
// (zero derivatives hold the inputs constant, as FMI 2.0 does without input derivatives).
struct StepInputs {
    Tangential foundation_velocity{}, foundation_acceleration{};  // per tangent of its plane
    double top_displacement = 0, top_velocity = 0;
    double top_force = 0, top_force_rate = 0;  // force control
};

// Everything that evolves in time, as plain data. The factorizations are derived from the
// parameters and the substep sizes they were made for, so only those sizes are part of it;
// and the reduced body's contact factorization from W and the node pattern it was made for.
struct SimulationSnapshot {
    State state;
    Works works;                                 // since t0
    double initial_energy = 0;                   // E(0), J/m
    Observables observables;                     // the last step's averages
    std::vector<double> factor_substeps;         // Stepper::cached_substeps()
    EdgeSnapshot edge;                           // the last step's edge (its x is the mesh's)
    ContactFactorization contact_factorization;  // Body::contact_factorization()
    double controlled_substep = 0;               // the controller's pair span (tolerance > 0), 0: none yet
    double declined_savings = 0;                 // substeps its declined doublings forwent
};

// What the last communication step cost.
struct StepStatistics {
    int substeps = 0;                // nominal: ceil(h / internal_step)
    int refinements = 0;             // substeps redone as two halves after a failed solve
    double smallest_substep = 0;     // the smallest substep size used
    int contact_solves = 0;          // substeps where some node could touch
    int contact_iterations = 0;      // Newton iterations, summed over the substeps
    int max_contact_iterations = 0;  // in one substep
    int gauss_seidel_sweeps = 0;     // of the contact solver's fallback, summed
    // tolerance > 0: the estimates' coarse substeps solved, and the pairs accepted at the
    // smallest size with their estimate above the tolerance.
    int estimate_substeps = 0, unmet_tolerance = 0;
    // Pairs whose estimate allowed a doubled span that was not taken yet: its new step
    // operator costs more solves (new_operator_solves) than the declined doublings have
    // forgone so far (Simulation::declined_savings_).
    int declined_growths = 0;
    double new_operator_solves = 0;
};

// What the static start (initial_state = static) cost: the load path's own body (its
// discretization), the load paths (their factor and contact solves), and the held solves and
// refactorizations of the body that ran them (a full one; zero for a reduced body's own).
struct StaticStartCost {
    double path_body_seconds = 0, path_seconds = 0;
    long held_solves = 0, refactorizations = 0;
};

// The share of E(0) + the work put in that the contact may create before a warning: sound
// scenes stay below 5e-4 (recommended settings 4e-5), unsound ones pass 0.05 (docs/contract.md).
constexpr double contact_work_warning = 0.01;
// A step warns that its substep halvings pile up from this many, and this share of its
// nominal substeps, on.
constexpr int refinement_warning_count = 4;
constexpr double refinement_warning_share = 0.05;

class NumericalFailure : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

class Simulation {
public:
    // The initial load: the top displacement (top_control = displacement) or the force on the
    // plate (force), which initial_state = static puts the body in balance with. The initial
    // foundation velocity is the sliding speed at which the initialization warning evaluates a
    // slip-rate law.
    Simulation(const SceneParameters& params, double initial_top_displacement, double start_time = 0,
               double initial_top_force = 0, double initial_foundation_velocity = 0);
    // Starts over from t0 with new parameters of the same discretization
    // (same_discretization): the same bits as a new Simulation, without rebuilding the
    // discretization or the factors it already made (Stepper::restart). If it throws, the
    // simulation is unusable and must be discarded.
    void restart(const SceneParameters& params, double initial_top_displacement, double start_time = 0,
                 double initial_top_force = 0, double initial_foundation_velocity = 0);

    // Runs n = ceil(h / internal_step) substeps of size h / n. A substep whose contact solve
    // fails is redone from its start as two halves, recursively down to min_internal_step
    // (and at most 20 times). With tolerance > 0 the sizes are the controller's instead
    // (controlled_substeps).
    // On failure (a contact solve at the smallest size, or a non-finite state or output)
    // the state is restored to the start of the step and NumericalFailure propagates, its
    // message naming the time, the sizes tried, the contact state and what to change.
    void do_step(double h, const StepInputs& inputs);

    const Observables& observables();  // energies computed here: once per step (checked finite)
    double time() const { return state_.time; }
    const State& state() const { return state_; }
    // The full body (modes = 0) or the reduced one.
    Body& body() { return *body_; }
    const Body& body() const { return *body_; }
    void set_friction_coefficient(double friction);
    // The state on every dof (the reduced body's expanded): what field output writes.
    void full_state(State& out) const { body_->to_full(state_, out); }
    // Substeps per step for a step of size h.
    int substeps_for(double h) const;

    // Taking a snapshot drops what the body keeps only to go faster (Body::forget_kept), as
    // restoring one does: the steps after either start from the snapshot alone, in the same
    // bits (its kept GCR directions would cost ~10 MB a snapshot at 1,600 contact nodes).
    SimulationSnapshot snapshot() const {
        body_->forget_kept();
        return {state_,
                works_,
                initial_energy_,
                observables_,
                body_->cached_substeps(),
                edge_,
                body_->contact_factorization(),
                controlled_substep_,
                declined_savings_};
    }
    // Throws std::invalid_argument if the snapshot does not fit this discretization.
    void restore(const SimulationSnapshot& snapshot);
    const StepStatistics& statistics() const { return statistics_; }
    const StaticStartCost& static_start_cost() const { return static_start_cost_; }
    // The bottom edge after the last step (before the first: the initial static reactions).
    const EdgeSnapshot& edge() const { return edge_; }
    // Warnings since the last call: a scene in a measured unstable region (at construction),
    // the contact creating energy, the top moved beyond the height (each once per run);
    // substep halvings piling up (once per step where they do).
    std::vector<std::string> take_warnings() { return std::exchange(warnings_, {}); }

    // A simulation of a body built elsewhere (the benchmarks' Craig-Bampton body); the one
    // above builds the body its parameters ask for (modes).
    Simulation(std::unique_ptr<Body> body, double initial_top_displacement, double start_time = 0,
               double initial_top_force = 0, double initial_foundation_velocity = 0);

private:
    // What a step's substeps add up.
    struct StepSums {
        Observables avg;
        StepStatistics stats;
    };
    void initial_reactions();                             // the force outputs before the first step
    void static_initial_state(double top, double force);  // initial_state = static
    void check_static_balance() const;
    // One substep over [s0, s0 + dt] of the step (times from its start), halved on failure;
    // weight = dt / nominal substep (a power of two), for the step averages.
    void advance(const StepInputs& in, double s0, double dt, double weight, StepSums& sums);
    // One substep of state_ over [s0, s0 + dt]; a ContactSolveError leaves state_ as it was.
    SubstepReport solve_substep(const StepInputs& in, double s0, double dt);
    // A solved substep's works, edge sums and averages, weight as advance's.
    void add_substep(const SubstepReport& r, double weight, StepSums& sums);
    // tolerance > 0: the n nominal substeps of size dt as the controller's pairs
    // (simulation/substep_control.cpp; docs/decisions.md "Substeps chosen by a tolerance").
    void controlled_substeps(const StepInputs& in, int n, double dt, StepSums& sums);
    // The ladder's sizes are the nominal substep over 2^k; positions count its finest sizes, so
    // that pairs land on the nominal substeps' ends (and the step's) exactly.
    struct PairLadder {
        static constexpr int finest_level = 20;
        double nominal = 0, tick = 0;
        int deepest = 0;  // the deepest level: its fine substeps at least min_internal_step
        std::int64_t ticks(int level) const { return std::int64_t{1} << (finest_level - level); }
    };
    struct PairOutcome {  // the last pair accepted: its estimate and level
        double error;
        int level;
    };
    // A pair at this level from position, refined into two of the next level while its
    // estimate exceeds the tolerance (down to the deepest level, where it is kept); its
    // outcome is the last pair accepted.
    PairOutcome controlled_pair(const StepInputs& in, const PairLadder& ladder, std::int64_t position,
                                int level, StepSums& sums);
    // The estimate of a pair: |fine - coarse|_E / (3 max(|fine|_E, |start|_E)).
    double pair_error();
    void warn_unmet_tolerance(const StepStatistics& stats);
    [[noreturn]] void fail_contact(const ContactSolveError& e, double s0, double dt,
                                   const StepSums& sums) const;
    void check_finite(const Observables& o) const;  // throws NumericalFailure
    // After a step: the blow-up guard and a top below the foundation throw NumericalFailure;
    // the contact's created energy and a top moved beyond the height warn.
    void check_plausible();
    std::string growth_advice() const;                   // what to change when E runs away
    void warn_refinements(const StepStatistics& stats);  // halvings piled up in the step
    void move_clamp(double top, double rate);
    double energy(const State& s);  // E of a state
    std::pair<double, double> kinetic_and_strain_energy(const State& s) {
        return body_->kinetic_and_strain_energy(s);
    }

    std::unique_ptr<Body> body_;  // owned by pointer: restart hands it on
    State state_, saved_;
    Works works_;  // since t0
    // E(0), kept: rebuilt from the balance (E - works) it is round-off where E is 1e15-1e17
    // and the guard's message printed -65 for 22.99.
    double initial_energy_ = 0;
    double sliding_speed_ = 0;  // |V| at t0: where the warnings evaluate a slip-rate law
    Observables observables_;
    StepStatistics statistics_;
    StaticStartCost static_start_cost_;
    bool energies_current_ = false;
    Eigen::VectorXd lambda_before_;  // warm start of the substep being tried
    // Multipliers summed over the step's substeps (friction per tangent).
    Eigen::VectorXd edge_sum_N_;
    PerTangent<Eigen::VectorXd> edge_sum_T_;
    EdgeSnapshot edge_;
    void update_edge(int substeps);
    double nominal_substep_ = 0;
    // The span of the controller's pairs (two coarse substeps, four fine ones), kept from step
    // to step; 0 before its first. Its scratch: the pair's start, coarse end and their
    // difference, and the sums a rejected pair takes back.
    double controlled_substep_ = 0;
    // The substeps the doublings declined at this span have forgone (substep_control.cpp); 0
    // after a change of span.
    double declined_savings_ = 0;
    State pair_start_, pair_coarse_, pair_difference_;
    // E of the next pair's start (the last accepted pair's end, or the step's start): every
    // pair's scale needs it, and a state's E costs as much as a third of a substep at nx = 20.
    double pair_start_energy_ = 0, pair_end_energy_ = 0;
    Works pair_works_;
    Eigen::VectorXd pair_sum_N_;
    PerTangent<Eigen::VectorXd> pair_sum_T_;
    std::vector<std::string> warnings_;
    bool contact_work_warned_ = false, travel_warned_ = false;
};

}  // namespace contactbody
