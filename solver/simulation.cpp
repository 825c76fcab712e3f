#include "simulation.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace contactbody {

Simulation::Simulation(const SceneParameters& params, double initial_top_displacement,
                       double start_time)
    : stepper_(params), state_(stepper_.initial_state(initial_top_displacement)) {
    state_.time = start_time;
    product_.resize(state_.u.size());
}

int Simulation::substeps_for(double h) const {
    // The relative slack keeps h = 25 * internal_step at 25 substeps despite round-off.
    const double ratio = h / stepper_.parameters().internal_step;
    if (!(ratio <= 1e9)) throw std::invalid_argument("step needs more than 1e9 substeps");
    return std::max(1, static_cast<int>(std::ceil(ratio * (1 - 1e-12))));
}

void Simulation::do_step(double h, const StepInputs& in) {
    if (!(h > 0) || !std::isfinite(h)) throw std::invalid_argument("step size must be > 0");
    const int n = substeps_for(h);
    const double dt = h / n, t0 = state_.time;
    saved_ = state_;
    const Works saved_works = works_;

    Observables avg;
    StepStatistics stats;
    stats.substeps = n;
    SubstepLoad load;
    const Mesh& mesh = stepper_.discretization().mesh;
    try {
        for (int k = 0; k < n; ++k) {
            const double s0 = k * dt, s1 = (k + 1) * dt;
            load.top_start = in.top_displacement + in.top_velocity * s0;
            load.top_end = in.top_displacement + in.top_velocity * s1;
            load.top_rate = in.top_velocity;
            load.foundation_velocity =
                in.foundation_velocity + in.foundation_acceleration * 0.5 * (s0 + s1);
            if (k == 0) move_clamp(load.top_start, load.top_rate);
            const SubstepReport r = stepper_.substep(state_, dt, load);
            works_ += r.work;
            avg.normal_force += r.normal_force;
            avg.friction_force += r.friction_force;
            avg.corner_pressure -= r.corner_lambda_N;
            avg.corner_friction += r.corner_lambda_T;
            avg.top_reaction_x += r.top_reaction_x;
            avg.top_reaction_y += r.top_reaction_y;
            avg.max_penetration = std::max(avg.max_penetration, r.max_penetration);
            avg.active_contact_nodes = r.active_nodes;
            avg.slipping_contact_nodes = r.slipping_nodes;
            stats.contact_solves += r.contact_solved;
            stats.contact_iterations += r.contact_iterations;
            stats.max_contact_iterations = std::max(stats.max_contact_iterations, r.contact_iterations);
        }
        if (!state_.u.allFinite() || !state_.v.allFinite()) {
            std::ostringstream msg;
            msg << "state became non-finite during the step from t = " << t0;
            throw NumericalFailure(msg.str());
        }
    } catch (...) {
        state_ = saved_;
        works_ = saved_works;
        throw;
    }
    state_.time = t0 + h;  // no drift from summing substeps

    const double share = 0.5 * mesh.hx();  // boundary length carried by the corner node
    avg.normal_force /= n;
    avg.friction_force /= n;
    avg.corner_pressure /= n * share;
    avg.corner_friction /= n * share;
    avg.top_reaction_x /= n;
    avg.top_reaction_y /= n;
    observables_ = avg;
    statistics_ = stats;
    energies_current_ = false;
}

// Held inputs may have jumped since the last step: the clamp moves with them. The energy
// that jump puts in (the clamped dofs move at once, the free ones not at all) is the clamp's
// work, so that the balance closes across held steps too.
void Simulation::move_clamp(double top, double rate) {
    const Discretization& d = stepper_.discretization();
    const bool moves = std::any_of(d.mesh.top_nodes.begin(), d.mesh.top_nodes.end(), [&](int n) {
        return state_.u[dof_y(n)] != top || state_.v[dof_y(n)] != rate;
    });
    if (!moves) return;
    const double before = energy(state_);
    for (int node : d.mesh.top_nodes) {
        state_.u[dof_y(node)] = top;
        state_.v[dof_y(node)] = rate;
    }
    works_.clamp += energy(state_) - before;
    energies_current_ = false;
}

double Simulation::energy(const State& s) {
    const Discretization& d = stepper_.discretization();
    product_.noalias() = d.M * s.v;
    double e = 0.5 * s.v.dot(product_);
    product_.noalias() = d.A * s.u;
    return e + 0.5 * s.u.dot(product_);
}

void Simulation::restore(const SimulationSnapshot& snapshot) {
    const State& s = snapshot.state;
    const Eigen::Index dofs = stepper_.discretization().mesh.num_dofs();
    const Eigen::Index nc = stepper_.num_contact_nodes();
    if (s.u.size() != dofs || s.v.size() != dofs ||
        (s.lambda.size() != nc && s.lambda.size() != 2 * nc))
        throw std::invalid_argument("state does not fit this mesh");
    state_ = s;
    works_ = snapshot.works;
    observables_ = snapshot.observables;
    energies_current_ = false;
}

const Observables& Simulation::observables() {
    if (!energies_current_) {
        const Discretization& d = stepper_.discretization();
        product_.noalias() = d.M * state_.v;
        observables_.kinetic_energy = 0.5 * state_.v.dot(product_);
        product_.noalias() = d.A * state_.u;
        observables_.strain_energy = 0.5 * state_.u.dot(product_);
        observables_.energy = observables_.kinetic_energy + observables_.strain_energy;
        observables_.friction_work = works_.friction;
        observables_.energy_minus_friction_work = observables_.energy - works_.friction;
        observables_.damping_work = works_.damping;
        observables_.clamp_work = works_.clamp;
        observables_.normal_contact_work = works_.normal_contact;
        observables_.friction_dissipation = works_.friction_dissipation;
        observables_.foundation_work = works_.foundation;
        energies_current_ = true;
    }
    return observables_;
}

}  // namespace contactbody
