#include "simulation/simulation.hpp"

#include "reduced/reduced_stepper.hpp"
#include "simulation/scheme_warnings.hpp"
#include "util/text.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <tuple>
#include <type_traits>
#include <utility>

namespace contactbody {

// The body the parameters ask for: the full mesh, or the reduced one of `modes` modes.
static std::unique_ptr<Body> make_body(const SceneParameters& params) {
    check_parameters(params);
    if (params.modes == 0) return std::make_unique<Stepper>(params);
    return std::make_unique<ReducedStepper>(params, params.modes);
}

Simulation::Simulation(const SceneParameters& params, double initial_top_displacement, double start_time,
                       double initial_top_force, double initial_foundation_velocity)
    : Simulation(make_body(params), initial_top_displacement, start_time, initial_top_force,
                 initial_foundation_velocity) {}

void Simulation::restart(const SceneParameters& params, double initial_top_displacement, double start_time,
                         double initial_top_force, double initial_foundation_velocity) {
    body_->restart(params);
    *this = Simulation(std::move(body_), initial_top_displacement, start_time, initial_top_force,
                       initial_foundation_velocity);
}

Simulation::Simulation(std::unique_ptr<Body> body, double initial_top_displacement, double start_time,
                       double initial_top_force, double initial_foundation_velocity)
    : body_(std::move(body)),
      state_(body_->initial_state(initial_top_displacement)),
      sliding_speed_(std::abs(initial_foundation_velocity)) {
    const SceneParameters& params = body_->parameters();
    state_.time = start_time;
    const Mesh& mesh = body_->discretization().mesh;
    const Eigen::Index nc = body_->num_contact_nodes();
    edge_sum_N_.setZero(nc);
    edge_.x.resize(nc);
    for (Eigen::Index i = 0; i < nc; ++i) edge_.x[i] = mesh.point(mesh.contact_nodes[i]).x;
    edge_.pressure.setZero(nc);
    edge_.gap.setZero(nc);
    edge_.state.setZero(nc);
    for (size_t t = 0; t < static_cast<size_t>(mesh.tangents()); ++t) {
        edge_sum_T_[t].setZero(nc);
        edge_.friction[t].setZero(nc);
        edge_.slip_velocity[t].setZero(nc);
    }
    if (mesh.tangents() > 1) {  // the edge's second coordinate
        edge_.z.resize(nc);
        for (Eigen::Index i = 0; i < nc; ++i) edge_.z[i] = mesh.point(mesh.contact_nodes[i]).z;
    }
    if (params.static_initial_state) static_initial_state(initial_top_displacement, initial_top_force);
    initial_reactions();
    initial_energy_ = energy(state_);
    if (std::string why = scheme_warning(params, sliding_speed_); !why.empty()) {
        if (params.modes > 0)
            why +=
                " (measured on the full body: the reduced body of modes = " + std::to_string(params.modes) +
                " has not been mapped)";
        warnings_.push_back(std::move(why));
    }
    if (std::string why = massless_edge_warning(params); !why.empty()) warnings_.push_back(std::move(why));
    const Discretization& d = body_->discretization();  // a contact node's unknowns: one per dimension
    if (std::string why =
            long_reduced_edge_warning(params, static_cast<long>(d.mesh.dim) * body_->num_contact_nodes(),
                                      static_cast<long>(d.A_free.rows()));
        !why.empty())
        warnings_.push_back(std::move(why));
}

// Before the first step the outputs describe the initial state. A bottom node touches the
// foundation where its gap is closed (g + u_y <= 0). The contact forces at t0: for the static
// state, the multipliers of its load path (normal and friction: they hold it in balance);
// for the paper's state, which is no equilibrium and has no slip history, the normal force
// that would hold a touching node where it is, max(0, (A u)_y), and no friction. Nodes with a
// normal force are active, and at rest none slips. The top reactions are A u on the top rows.
void Simulation::initial_reactions() {
    const Discretization& d = body_->discretization();
    const SceneParameters& p = body_->parameters();
    State full;
    body_->to_full(state_, full);
    Eigen::VectorXd relative, product;
    d.remove_translation(full.u, relative);
    product.noalias() = d.A * relative;
    const Eigen::Index nc = body_->num_contact_nodes();
    const bool multipliers = p.static_initial_state;
    // A node on the foundation touches it. The full body's heights are exact there (u_y = 0 of
    // the paper's state); the reduced body rebuilds them from its coordinates, to round-off
    // of the displacements (1e-20 m where they are 1e-5 m), which must not decide.
    const double resolution = 1e-12 * (full.u.size() ? full.u.cwiseAbs().maxCoeff() : 0.0);
    Observables o;
    for (Eigen::Index k = 0; k < nc; ++k) {
        const size_t i = static_cast<size_t>(k);
        const int node = d.mesh.contact_nodes[i];
        const double share = d.mesh.edge_share(i);
        const double gap = p.initial_gap + d.mesh.contact_heights[i] + full.u[d.mesh.dof(node, Mesh::normal)];
        const bool touching = gap <= resolution;
        double normal = 0;
        Tangential friction{};
        if (multipliers) {
            normal = -state_.lambda[k];
            for (Eigen::Index t = 0; t < d.mesh.tangents(); ++t)
                if (state_.lambda.size() > (1 + t) * nc)
                    friction[static_cast<size_t>(t)] = state_.lambda[(1 + t) * nc + k];
        } else if (touching) {
            normal = std::max(0.0, product[d.mesh.dof(node, Mesh::normal)]);
        }
        edge_.pressure[k] = normal / share;
        for (size_t t = 0; t < static_cast<size_t>(d.mesh.tangents()); ++t) {
            edge_.friction[t][k] = friction[t] / share;
            o.friction_force[t] += friction[t];
        }
        edge_.gap[k] = gap;
        edge_.state[k] = normal > 0 ? 1 : 0;  // pressed at rest: sticking
        o.max_penetration = std::max(o.max_penetration, -gap);
        o.normal_force += normal;
        if (normal > 0) ++o.active_contact_nodes;
        if (k == 0) {
            o.corner_pressure = normal / share;
            o.corner_friction = friction[0] / share;
        }
    }
    for (int dof : d.top_dofs) o.top_reaction[static_cast<size_t>(d.mesh.component(dof))] += product[dof];
    observables_ = o;
    energies_current_ = false;
}

void Simulation::set_friction_coefficient(double friction) {
    SceneParameters p = body_->parameters();
    p.friction_coefficient = friction;
    check_dimension(body_->discretization().mesh, p);
    body_->set_friction_coefficient(friction);
}

int Simulation::substeps_for(double h) const {
    // The relative slack keeps h = 25 * internal_step at 25 substeps despite round-off, and
    // despite masters that add up time and send steps a few 1e-12 too long.
    const double ratio = h / body_->parameters().internal_step;
    if (!(ratio <= max_substeps_per_step)) {
        Text msg;
        msg << "communication step " << h << " needs " << ratio << " substeps of internal_step "
            << "(at most " << max_substeps_per_step << "); use smaller steps";
        throw std::invalid_argument(msg.str());
    }
    return std::max(1, static_cast<int>(std::ceil(ratio * (1 - 1e-9))));
}

void Simulation::do_step(double h, const StepInputs& in) {
    if (!(h > 0) || !std::isfinite(h)) throw std::invalid_argument("step size must be > 0");
    for (size_t t = static_cast<size_t>(body_->discretization().mesh.tangents()); t < max_tangents; ++t) {
        if (in.foundation_velocity[t] == 0 && in.foundation_acceleration[t] == 0) continue;
        Text msg;
        msg << "foundation_velocity_" << component_letter(tangent_component(static_cast<int>(t))) << " = "
            << in.foundation_velocity[t] << " m/s: a 2D body (plane strain in x-y) has no z direction";
        throw std::invalid_argument(msg.str());
    }
    const int n = substeps_for(h);
    const double dt = h / n, t0 = state_.time;
    saved_ = state_;
    const Works saved_works = works_;

    StepSums sums;
    Observables& avg = sums.avg;
    StepStatistics& stats = sums.stats;
    stats.substeps = n;
    stats.smallest_substep = dt;
    nominal_substep_ = dt;
    const Mesh& mesh = body_->discretization().mesh;
    const Observables saved_observables = observables_;
    edge_sum_N_.setZero();
    for (Eigen::VectorXd& sum : edge_sum_T_) sum.setZero();
    const bool controlled = body_->parameters().tolerance > 0;
    const double saved_controlled_substep = controlled_substep_, saved_declined = declined_savings_;
    try {
        // Held inputs may have jumped since the last step: the clamp moves with them.
        if (!body_->parameters().force_control) move_clamp(in.top_displacement, in.top_velocity);
        if (controlled)
            controlled_substeps(in, n, dt, sums);
        else
            for (int k = 0; k < n; ++k) advance(in, k * dt, dt, 1.0, sums);
        state_.time = t0 + h;  // no drift from summing substeps

        const double share = mesh.edge_share(0);  // boundary length carried by the corner node
        avg.normal_force /= n;
        for (double& f : avg.friction_force) f /= n;
        avg.corner_pressure /= n * share;
        avg.corner_friction /= n * share;
        for (double& r : avg.top_reaction) r /= n;
        observables_ = avg;
        // Each halving adds one substep; the controller counts the substeps its pairs advanced.
        observables_.substeps = controlled ? stats.substeps : n + stats.refinements;
        observables_.substep_refinements = stats.refinements;
        observables_.contact_iterations = stats.contact_iterations;
        observables_.gauss_seidel_sweeps = stats.gauss_seidel_sweeps;
        update_edge(n);
        energies_current_ = false;
        check_finite(observables());  // no NaN under fmi2OK: every output, every step
        check_plausible();
        if (controlled)
            warn_unmet_tolerance(stats);
        else
            warn_refinements(stats);
    } catch (...) {
        state_ = saved_;
        controlled_substep_ = saved_controlled_substep;
        declined_savings_ = saved_declined;
        body_->forget_kept();  // what the failed step kept is not the saved state's
        works_ = saved_works;
        observables_ = saved_observables;
        energies_current_ = false;
        throw;
    }
    statistics_ = stats;
}

// The edge after a successful step of n nominal substeps: the averaged densities, and the
// last substep's slip velocities and states.
void Simulation::update_edge(int substeps) {
    const Mesh& mesh = body_->discretization().mesh;
    const ContactSnapshot& c = body_->last_contact();
    const Eigen::Index nc = edge_.x.size();
    body_->contact_heights(state_, edge_.gap);
    for (Eigen::Index i = 0; i < nc; ++i) {
        const double share = mesh.edge_share(static_cast<size_t>(i)) * substeps;
        edge_.pressure[i] = -edge_sum_N_[i] / share;
        for (int t = 0; t < mesh.tangents(); ++t)
            edge_.friction[static_cast<size_t>(t)][i] = edge_sum_T_[static_cast<size_t>(t)][i] / share;
        edge_.gap[i] += body_->parameters().initial_gap + mesh.contact_heights[i];
    }
    for (int t = 0; t < mesh.tangents(); ++t)
        edge_.slip_velocity[static_cast<size_t>(t)] = c.slip_velocity[static_cast<size_t>(t)];
    edge_.state = c.state;
}

// Held inputs may have jumped since the last step: the clamp moves with them. The energy
// that jump puts in (the clamped dofs move at once, the free ones not at all) is the clamp's
// work, so that the balance closes across held steps too.
void Simulation::move_clamp(double top, double rate) {
    if (body_->top_position(state_) == top && body_->top_velocity(state_) == rate) return;
    const double before = energy(state_);
    body_->set_clamp(state_, top, rate);
    works_.clamp += energy(state_) - before;
    energies_current_ = false;
}

double Simulation::energy(const State& s) {
    const auto [kinetic, strain] = kinetic_and_strain_energy(s);
    return kinetic + strain;
}

SubstepReport Simulation::solve_substep(const StepInputs& in, double s0, double dt) {
    const double s1 = s0 + dt;
    SubstepLoad load;
    load.top_start = in.top_displacement + in.top_velocity * s0;
    load.top_end = in.top_displacement + in.top_velocity * s1;
    load.top_rate = in.top_velocity;
    for (size_t t = 0; t < max_tangents; ++t)
        load.foundation_velocity[t] =
            in.foundation_velocity[t] + in.foundation_acceleration[t] * 0.5 * (s0 + s1);
    load.top_force = in.top_force + in.top_force_rate * 0.5 * (s0 + s1);
    lambda_before_ = state_.lambda;
    try {
        return body_->substep(state_, dt, load);
    } catch (const ContactSolveError&) {
        state_.lambda = lambda_before_;  // the substep changed nothing else
        throw;
    }
}

void Simulation::advance(const StepInputs& in, double s0, double dt, double weight, StepSums& sums) {
    SubstepReport r;
    try {
        r = solve_substep(in, s0, dt);
    } catch (const ContactSolveError& e) {
        const double half = 0.5 * dt;
        // At most 20 halvings (a millionth of the substep), whatever min_internal_step says.
        if (half < body_->parameters().min_internal_step || weight < 0x1p-19) fail_contact(e, s0, dt, sums);
        StepStatistics& stats = sums.stats;
        ++stats.refinements;
        stats.smallest_substep = std::min(stats.smallest_substep, half);
        advance(in, s0, half, 0.5 * weight, sums);
        advance(in, s0 + half, half, 0.5 * weight, sums);
        return;
    }
    add_substep(r, weight, sums);
}

void Simulation::add_substep(const SubstepReport& r, double weight, StepSums& sums) {
    works_ += r.work;
    const ContactSnapshot& c = body_->last_contact();
    edge_sum_N_ += weight * c.lambda_N;
    for (size_t t = 0; t < max_tangents; ++t)
        if (edge_sum_T_[t].size()) edge_sum_T_[t] += weight * c.lambda_T[t];
    Observables& avg = sums.avg;
    avg.normal_force += weight * r.normal_force;
    for (size_t t = 0; t < max_tangents; ++t) avg.friction_force[t] += weight * r.friction_force[t];
    avg.corner_pressure -= weight * r.corner_lambda_N;
    avg.corner_friction += weight * r.corner_lambda_T;
    for (size_t component = 0; component < 3; ++component)
        avg.top_reaction[component] += weight * r.top_reaction[component];
    avg.max_penetration = std::max(avg.max_penetration, r.max_penetration);
    avg.active_contact_nodes = r.active_nodes;
    avg.slipping_contact_nodes = r.slipping_nodes;
    StepStatistics& stats = sums.stats;
    stats.contact_solves += r.contact_solved;
    stats.contact_iterations += r.contact_iterations;
    stats.max_contact_iterations = std::max(stats.max_contact_iterations, r.contact_iterations);
    stats.gauss_seidel_sweeps += r.contact_sweeps;
}

void Simulation::restore(const SimulationSnapshot& snapshot) {
    const State& s = snapshot.state;
    const Eigen::Index nc = body_->num_contact_nodes();
    if (!body_->fits(s)) throw std::invalid_argument("state does not fit this body");
    const EdgeSnapshot& e = snapshot.edge;
    bool fits = e.pressure.size() == nc && e.gap.size() == nc && e.state.size() == nc;
    for (size_t t = 0; t < max_tangents; ++t)
        fits = fits && e.friction[t].size() == edge_.friction[t].size() &&
               e.slip_velocity[t].size() == edge_.friction[t].size();
    if (!fits) throw std::invalid_argument("edge does not fit this mesh");
    for (double dt : snapshot.factor_substeps)
        if (!(std::isfinite(dt) && dt > 0))
            throw std::invalid_argument("cached substep sizes must be finite and > 0");
    const ContactFactorization& f = snapshot.contact_factorization;
    if (!(std::isfinite(f.substep) && f.substep >= 0))
        throw std::invalid_argument("the contact factorization's substep must be finite and >= 0");
    if (!(std::isfinite(snapshot.controlled_substep) && snapshot.controlled_substep >= 0))
        throw std::invalid_argument("the controller's substep must be finite and >= 0");
    if (!(std::isfinite(snapshot.declined_savings) && snapshot.declined_savings >= 0))
        throw std::invalid_argument("the controller's declined savings must be finite and >= 0");
    if (!f.pattern.empty() && f.pattern.size() != static_cast<size_t>(nc))
        throw std::invalid_argument("the contact factorization does not fit this mesh");
    for (signed char x : f.pattern)
        if (x != 0 && x != 1 && x != 2 && x != -2 && x != 3 && x != -3)
            throw std::invalid_argument("invalid node state in the contact factorization");
    if (!f.slip.empty() && (f.pattern.empty() || f.slip.size() % f.pattern.size() != 0 ||
                            f.slip.size() / f.pattern.size() > max_tangents))
        throw std::invalid_argument("the contact factorization's slips do not fit its nodes");
    for (size_t s = 0; s < f.slip.size(); ++s)
        if (!(std::abs(f.slip[s]) <= 1) || (f.slip[s] != 0 && f.pattern[s % f.pattern.size()] != 3))
            throw std::invalid_argument("invalid slip in the contact factorization");
    body_->set_cached_substeps(snapshot.factor_substeps);
    body_->forget_kept();
    body_->set_contact_factorization(f);
    state_ = s;
    controlled_substep_ = snapshot.controlled_substep;
    declined_savings_ = snapshot.declined_savings;
    works_ = snapshot.works;
    initial_energy_ = snapshot.initial_energy;
    observables_ = snapshot.observables;
    edge_.pressure = e.pressure;  // x and z stay the mesh's
    edge_.friction = e.friction;
    edge_.slip_velocity = e.slip_velocity;
    edge_.gap = e.gap;
    edge_.state = e.state;
    energies_current_ = false;
}

const Observables& Simulation::observables() {
    if (!energies_current_) {
        std::tie(observables_.kinetic_energy, observables_.strain_energy) = kinetic_and_strain_energy(state_);
        observables_.energy = observables_.kinetic_energy + observables_.strain_energy;
        observables_.friction_work = works_.friction;
        observables_.energy_minus_friction_work = observables_.energy - works_.friction;
        observables_.damping_work = works_.damping;
        observables_.clamp_work = works_.clamp;
        observables_.normal_contact_work = works_.normal_contact;
        observables_.friction_dissipation = works_.friction_dissipation;
        observables_.foundation_work = works_.foundation;
        observables_.top_position = body_->top_position(state_);
        observables_.top_velocity = body_->top_velocity(state_);
        energies_current_ = true;
    }
    return observables_;
}

}  // namespace contactbody
