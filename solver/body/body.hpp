// What a Simulation needs of a body: the full mesh (Stepper) or the reduced one
// (ReducedStepper, docs/decisions.md "The reduced body"). Both step the same scheme and the
// same contact problem on the same bottom edge; they differ in the coordinates of a State:
// every dof for the full body, the basis' coordinates for the reduced one. So a Simulation
// reads a state only through this interface (energies, the top, the contact nodes) and
// expands it to every dof only where a user sees the whole field.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "assembly/discretization.hpp"
#include "contact/contact_solver.hpp"

namespace contactbody {

struct State;
struct SubstepLoad;
struct SubstepReport;
struct ContactSnapshot;

// The contact solver's factorization that a body's next substep of this size would update
// (ContactSolver::factored_pattern): the node pattern, or empty for none.
struct ContactFactorization {
    double substep = 0;
    // Per contact node: 0 open, 1 sticking, 2 pressed, 3 pressed with its slipping rows held.
    std::vector<signed char> pattern;
    // The held slips (HeldOperator::slip: tangents x nodes, +-1 in 2D, a unit direction in 3D),
    // nonzero where the pattern is 3; empty where none is.
    std::vector<double> slip;
};

class Body {
public:
    virtual ~Body() = default;

    virtual const Discretization& discretization() const = 0;
    virtual const SceneParameters& parameters() const = 0;
    int num_contact_nodes() const { return static_cast<int>(discretization().contact_tangential[0].size()); }

    // Starts over with new parameters of the same discretization (same_discretization), keeping
    // what was built from it (factors; the reduced body's basis). Throws std::logic_error for
    // another discretization, std::invalid_argument for invalid parameters.
    virtual void restart(const SceneParameters& params) = 0;

    // The paper's initial state (Stepper::initial_state) in this body's coordinates.
    virtual State initial_state(double top_displacement) const = 0;
    // A state of every dof in this body's coordinates (the reduced body projects it), and back.
    virtual State from_full(const State& full) const = 0;
    virtual void to_full(const State& s, State& full) const = 0;

    virtual void set_friction_coefficient(double friction) = 0;
    // Advances s by one substep of size dt. Throws ContactSolveError if the contact problem
    // cannot be solved to the tolerance; s is then unchanged but for lambda.
    virtual SubstepReport substep(State& s, double dt, const SubstepLoad& load) = 0;
    virtual const ContactSnapshot& last_contact() const = 0;
    // The contact problem of the last substep (for studying its solution set: W, a, the
    // gaps, slip origins and friction law it was solved with). Valid until the next substep.
    virtual const ContactProblem& last_contact_problem() const = 0;

    // 1/2 v^T M v (with the plate's) and 1/2 u^T A u of a state.
    virtual std::pair<double, double> kinetic_and_strain_energy(const State& s) = 0;
    // The top edge's u_y and v_y, and a contact node's u_y.
    virtual double top_position(const State& s) const = 0;
    virtual double top_velocity(const State& s) const = 0;
    virtual double contact_height(const State& s, int node) const = 0;
    // Every contact node's u_y at once (the reduced body: one product with its basis' rows).
    virtual void contact_heights(const State& s, Eigen::Ref<Eigen::VectorXd> out) const {
        for (Eigen::Index i = 0; i < out.size(); ++i) out[i] = contact_height(s, static_cast<int>(i));
    }
    // Moves the clamp (displacement control) at once to top with velocity rate, leaving the
    // rest of the body where it is; returns whether anything moved.
    virtual bool set_clamp(State& s, double top, double rate) const = 0;
    // Whether s has this body's sizes (a restored state).
    virtual bool fits(const State& s) const = 0;

    // Substep sizes of the cached step operators, most recent first: a substep reuses one
    // whose size is within 1e-14 of its own, so results depend on them to the last bit.
    virtual std::vector<double> cached_substeps() const = 0;
    virtual void set_cached_substeps(const std::vector<double>& sizes) = 0;
    virtual size_t operator_cache_size() const = 0;
    // What a step operator of a new substep size costs, in solves with the current one (its
    // factorization's flops over a solve's); 0 where it is cheap (the reduced body's).
    virtual double new_operator_in_solves() const { return 0; }
    virtual int factorizations() const = 0;  // step operators built over the body's life
    virtual ContactSolverOptions& contact_options() = 0;
    virtual const ContactSolver& contact_solver() const = 0;  // its counters, for profiles
    // The contact factorization the next substep would update, where the body updates it (the
    // reduced body): results depend on it to the last bit, so a saved state keeps it, and
    // setting it makes the next substep of its size start from it.
    virtual ContactFactorization contact_factorization() const { return {}; }
    virtual void set_contact_factorization(const ContactFactorization&) {}
    // What the body keeps from substep to substep only to go faster, and that is no part of a
    // saved state, goes: what follows depends on the State alone. Where a state is saved
    // (Simulation::snapshot) or restored, and after a failed step, so that a restored state
    // replays the bits that followed its saving.
    virtual void forget_kept() {}
    virtual int modes() const { return 0; }  // 0: the full body
    // What the step operator is ("factorized 4/dt^2 M + A" and the like), for the log.
    virtual const char* operator_name() const = 0;
    // One line on how the body was built (the reduced body's basis), or empty.
    virtual std::string summary() const { return {}; }
};

}  // namespace contactbody
