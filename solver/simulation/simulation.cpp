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

// A quasi-static load path: the top displacement goes from `start` to `top` in `increments`
// substeps so long (1e3 s) that the mass terms weigh 1e-15 of the stiffness, with the foundation at rest,
// so that friction acts on each increment's slip; then one more substep at the final load.
// The body starts at rest translated rigidly to `start` (strain-free, so in balance).
// The midpoint step puts u^{k+1/2} in balance and extrapolates u^{k+1} = 2 u^{k+1/2} - u^k,
// which stays in balance only while the problem is linear or positively homogeneous along the
// path: with contact and Coulomb friction that holds from an unloaded touching state, but not
// across the load where a gap closes, nor where a node's friction coefficient changes on the
// way (the stick memory: a node that stuck holds with F_s, one that slipped with F), nor where
// the contact set grows. So a gap is closed first by the rigid shift `start` = -gap, and the
// state taken is not the last u^{k+1} but the midpoint u^{k+1/2} of the final substep, run
// with the contact at the midpoint (`timing`, where given, switches the body's contact to the
// end of the step for the increments and back for it): that state is in static balance with
// the substep's multipliers to round-off (A u = B^T lambda, the mass terms 1e-15), its active
// nodes lie on the foundation, and its friction is within the cone the substep allowed. At
// rest every pressed node sticks: it is marked so, and the stick memory then allows it F_s,
// at least what it had. The body is left there at rest: the first dynamic substep's solution
// is w = 0 with these multipliers.
static State quasi_static_path(Body& path, Stepper* timing, double top, double start, int increments) {
    constexpr double quasi_static = 1e3;
    State rest;
    path.to_full(path.initial_state(0.0), rest);
    rest.v.setZero();
    const Mesh& mesh = path.discretization().mesh;
    for (int n = 0; n < mesh.num_nodes(); ++n) rest.u[mesh.dof(n, Mesh::normal)] = start;
    State s = path.from_full(rest);
    SubstepLoad load;
    const auto run = [&](Body& body, double from, double to) {
        load.top_start = from;
        load.top_end = to;
        try {
            body.substep(s, quasi_static, load);
        } catch (const ContactSolveError& e) {
            throw std::invalid_argument(
                std::string("initial_state = static: the load path's contact solve failed (") + e.what() +
                "); use initial_state = paper");
        }
    };
    if (timing) timing->set_contact_at_end_of_step(true);
    for (int k = 1; k <= increments; ++k)
        run(path, start + (top - start) * (k - 1) / increments, start + (top - start) * k / increments);
    const Eigen::VectorXd before = s.u;
    if (timing) timing->set_contact_at_end_of_step(false);
    run(path, top, top);
    s.u = 0.5 * (before + s.u);  // u^{k+1/2}
    s.v.setZero();
    const Eigen::Index nc = s.sticking.size();
    const bool friction = s.lambda.size() > nc;
    for (Eigen::Index i = 0; i < nc; ++i) s.sticking[i] = friction && s.lambda[i] < 0 ? 1.0 : 0.0;
    return s;
}

// The full body that runs a static start's load path: `p`'s mesh and material; the mass,
// which weighs 1e-15 there, is the consistent one (no M_r to build), and no damping
// (2/dt beta A would weigh 1e-8: a static state does not depend on it). Its contact is at the
// midpoint; a boundary of several heights switches it to the end of the step for the
// increments (below), on the same body and factor.
static std::unique_ptr<Stepper> path_stepper(SceneParameters p) {
    p.mass_matrix = MassVariant::standard;
    p.modes = 0;
    p.damping_mass = p.damping_stiffness = 0;
    return std::make_unique<Stepper>(p);
}

// Under force control the plate (u_x = 0, one u_y) is a clamp at an unknown height, and only
// the contact holds the body in y, which a path driven by the force itself would leave to the
// 1e-15 mass terms. So the path is run clamped, with no gap: from the unloaded state, contact
// and Coulomb friction are positively homogeneous, so the state scales exactly with the
// clamp's displacement, and the scale that makes the reaction equal the force is one
// division. An initial gap is then closed by a rigid shift, which strains nothing.
//
// A contact boundary of several heights (a mesh's curved one) touches more as it is pressed.
// The midpoint contact's end-of-step state u^{k+1} = 2 u^{k+1/2} - u^k then overshoots the
// static one where the contact set grew within the substep, so such a path's increments are
// run with the contact at the end of the step (static for dt -> inf: the variant's mass does
// not enter), and its final substep settles at the midpoint (quasi_static_path). The state no
// longer scales with the clamp either: under force control the clamp's displacement for the
// force is found by regula falsi (Illinois) on the force, each a load path of its own, within
// a bracket: the force grows with the clamp's displacement.
//
// A reduced body takes the full body's path and its projection (exact: the static response
// to edge forces is in its basis). Its own path would differ where the path decides: with
// static friction above kinetic, which nodes stick along the way depends on the edge's
// extrapolated velocities (E(0) was 1.75e-3 off in variant 3 with static_friction_ratio = 2).
void Simulation::static_initial_state(double top, double force) {
    const SceneParameters& p = body_->parameters();
    const std::vector<double>& heights = body_->discretization().mesh.contact_heights;
    const bool flat = std::all_of(heights.begin(), heights.end(), [](double h) { return h == 0; });
    const double time = state_.time;
    SceneParameters path = p;
    if (p.force_control) {
        path.force_control = false;
        path.initial_gap = 0;
    }
    // The body itself runs the path where it can (a flat boundary, the full body, contact at
    // the midpoint, no damping); else full bodies of the path's own (path_stepper).
    const bool own = flat && body_->modes() == 0 && !contact_at_end_of_step(p.mass_matrix) &&
                     !p.force_control && !p.damped();
    std::unique_ptr<Stepper> path_body = own ? nullptr : path_stepper(path);
    Body& runs = own ? *body_ : *path_body;
    Stepper* timing = flat ? nullptr : path_body.get();
    // Without friction the static state does not depend on the path (the least energy under
    // the contact): a curved boundary's path is one increment, with its contact at the end of
    // the step, not ten contact solves whose contact sets differ (docs/decisions.md, "The
    // factor of a 3D body"). A flat one keeps its ten (its bits).
    const int increments_count = !flat && !(p.friction_coefficient > 0) ? 1 : 10;
    if (!p.force_control) {
        // A top pressed below the gap touches: close the gap rigidly first (above).
        const double start = top < -p.initial_gap ? -p.initial_gap : 0.0;
        state_ = body_->from_full(quasi_static_path(runs, timing, top, start, increments_count));
        state_.time = time;
        check_static_balance();
        return;
    }
    if (!(force > 0))
        throw std::invalid_argument(
            "initial_state = static with top_control = force needs top_force > 0 at the start "
            "(it is " +
            std::to_string(force) + " " + body_->discretization().mesh.force_unit() +
            "): only the contact holds the body; use "
            "initial_state = paper for a body that starts free");
    const Discretization& d = path_body->discretization();
    const auto pressing_force = [&](const State& s) {  // the clamp's force on the body, downwards
        double pressing = 0;                           // (A symmetric: col = row)
        for (int dof : d.top_dofs)
            if (d.mesh.component(dof) == Mesh::normal) pressing -= d.A.col(dof).dot(s.u);
        return pressing;
    };
    double probe = -1e-4 * d.mesh.clamp_height();
    State s = quasi_static_path(runs, timing, probe, 0.0, increments_count);
    double pressing = pressing_force(s);
    if (!(pressing > 0))
        throw std::invalid_argument(
            "initial_state = static: the clamped load path carries no "
            "force; use initial_state = paper");
    if (!flat) {  // (above)
        // The bracket [low, high] of clamp displacements (high pressing harder), and the
        // pressing at each end; the unloaded body (0, 0) is its first low end.
        double low = 0, low_pressing = 0, high = 0, high_pressing = 0;
        bool bracketed = false;
        int stale = 0;  // which end stayed last time (Illinois: halve its weight when it repeats)
        for (int iteration = 0; std::abs(pressing - force) > 1e-12 * force; ++iteration) {
            // The reaction sums terms much larger than itself: at 100 N/m on a tilted boundary
            // it moved by 2e-11 of itself between clamp displacements one ulp apart, so a
            // bracket of a few ulps is as near as the force can be told.
            if (bracketed &&
                std::abs(high - low) <= 8 * std::numeric_limits<double>::epsilon() * std::abs(high))
                break;
            if (iteration == 100) {
                Text msg;
                msg << "initial_state = static: the clamp's displacement for top_force = " << force << " "
                    << d.mesh.force_unit() << " was not found in 100 load paths (the nearest, " << probe
                    << " m, carries " << pressing << " " << d.mesh.force_unit()
                    << "); use initial_state = paper";
                throw std::invalid_argument(msg.str());
            }
            if (pressing < force) {
                low = probe, low_pressing = pressing;
                if (stale == -1) high_pressing = force + 0.5 * (high_pressing - force);
                stale = -1;
            } else {
                high = probe, high_pressing = pressing, bracketed = true;
                if (stale == 1) low_pressing = force + 0.5 * (low_pressing - force);
                stale = 1;
            }
            // Unbracketed, the force grows at least linearly (the contact only grows): the
            // linear estimate from the unloaded body reaches the force or passes it.
            probe = bracketed ? low + (force - low_pressing) * (high - low) / (high_pressing - low_pressing)
                              : probe * std::max(force / pressing, 1.0 + 1e-3);
            s = quasi_static_path(runs, timing, probe, 0.0, increments_count);
            pressing = pressing_force(s);
        }
    }
    const double scale = flat ? force / pressing : 1.0;
    State full;
    full.u = scale * s.u;
    for (int n = 0; n < d.mesh.num_nodes(); ++n) full.u[d.mesh.dof(n, Mesh::normal)] -= p.initial_gap;
    full.v.setZero(full.u.size());
    full.lambda = scale * s.lambda;
    full.sticking = s.sticking;
    full.time = time;
    state_ = body_->from_full(full);
    check_static_balance();
}

// A static start is in balance: what the contact carries is what the top does, to round-off.
// Anything else is a start that moves at once; initialization fails rather than give one.
void Simulation::check_static_balance() const {
    State full;
    body_->to_full(state_, full);
    const Discretization& d = body_->discretization();
    Eigen::VectorXd relative, product;
    d.remove_translation(full.u, relative);
    product.noalias() = d.A * relative;
    double top = 0;
    for (int dof : d.top_dofs)
        if (d.mesh.component(dof) == Mesh::normal) top += product[dof];
    const Eigen::Index nc = body_->num_contact_nodes();
    const double normal = -full.lambda.head(nc).sum();
    // Round-off: relative, or the force of a strain of 1e-12 over the body's width where the
    // body hangs free (the top then carries round-off and the contact nothing).
    const SceneParameters& p = body_->parameters();
    const double floor = 1e-12 * (p.lambda + 2 * p.mu) * d.mesh.width();
    if (!(std::abs(normal + top) <= std::max(1e-9 * std::max(std::abs(normal), std::abs(top)), floor))) {
        Text msg;
        msg << "initial_state = static: the load path ended out of balance (the contact carries " << normal
            << " " << d.mesh.force_unit() << ", the top " << -top << " " << d.mesh.force_unit()
            << "); use initial_state = paper";
        throw std::invalid_argument(msg.str());
    }
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

struct Simulation::StepSums {
    Observables avg;
    StepStatistics stats;
};

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
    try {
        // Held inputs may have jumped since the last step: the clamp moves with them.
        if (!body_->parameters().force_control) move_clamp(in.top_displacement, in.top_velocity);
        for (int k = 0; k < n; ++k) advance(in, k * dt, dt, 1.0, sums);
        state_.time = t0 + h;  // no drift from summing substeps

        const double share = mesh.edge_share(0);  // boundary length carried by the corner node
        avg.normal_force /= n;
        for (double& f : avg.friction_force) f /= n;
        avg.corner_pressure /= n * share;
        avg.corner_friction /= n * share;
        for (double& r : avg.top_reaction) r /= n;
        observables_ = avg;
        observables_.substeps = n + stats.refinements;  // each halving adds one substep
        observables_.substep_refinements = stats.refinements;
        observables_.contact_iterations = stats.contact_iterations;
        observables_.gauss_seidel_sweeps = stats.gauss_seidel_sweeps;
        update_edge(n);
        energies_current_ = false;
        check_finite(observables());  // no NaN under fmi2OK: every output, every step
        check_plausible();
        warn_refinements(stats);
    } catch (...) {
        state_ = saved_;
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

void Simulation::check_finite(const Observables& o) const {
    Observables::for_each(
        [&](const char* name, const auto& value) {
            if constexpr (std::is_floating_point_v<std::decay_t<decltype(value)>>) {
                if (std::isfinite(value)) return;
                Text msg;
                msg << "output " << name << " = " << value << " at t = " << state_.time
                    << ": the solution grows without bound" << growth_advice();
                throw NumericalFailure(msg.str());
            }
        },
        o);
}

void Simulation::check_plausible() {
    const SceneParameters& p = body_->parameters();
    const double energy = observables().energy;
    const Works& w = works_;
    const double initial = initial_energy_;
    // Floored by the energy of a strain of 1e-12 over the body: where nothing was put in
    // (E(0) = 0, the gap never closes), round-off of 1e-28 J/m must not trip the ratio.
    const Mesh& mesh = body_->discretization().mesh;
    const char* J = mesh.energy_unit();
    const double strain = 1e-12;
    const double floor = 0.5 * (p.lambda + 2 * p.mu) * strain * strain * mesh.width() * mesh.height();
    const double put_in = std::max(initial + std::abs(w.clamp) + std::abs(w.foundation), floor);
    const bool over_ratio = p.max_energy_ratio > 0 && energy > 0 && energy > p.max_energy_ratio * put_in;
    if (over_ratio || (p.max_energy > 0 && energy > p.max_energy)) {
        Text msg;
        msg << "energy E = " << energy << " " << J << " at t = " << state_.time << " exceeds ";
        if (over_ratio)
            msg << "max_energy_ratio x (E(0) + work put in"
                << (put_in == floor ? ", floored by "
                                      "the energy of a strain of 1e-12 over the body"
                                    : "")
                << ") = " << p.max_energy_ratio << " x " << put_in << " " << J;
        else
            msg << "max_energy = " << p.max_energy << " " << J;
        msg << " (E(0) = " << initial << ", clamp_work = " << w.clamp
            << ", foundation_work = " << w.foundation << ", normal_contact_work = " << w.normal_contact
            << ", friction_work = " << w.friction << ", damping_work = " << w.damping << " " << J
            << "): the solution grows without bound";
        // The likely cause: what the run itself shows (the contact creating energy), else the
        // measured map's region.
        if (w.normal_contact > contact_work_warning * put_in)
            msg << "; likely cause: the contact created normal_contact_work = " << w.normal_contact << " "
                << J << " of it (the midpoint contact of mass_matrix = " << static_cast<int>(p.mass_matrix)
                << ")";
        else if (const std::string why = scheme_warning(p, sliding_speed_); !why.empty())
            msg << "; likely cause: " << why;
        msg << growth_advice();
        throw NumericalFailure(msg.str());
    }
    // The top edge's travel: below the foundation the body would be compressed to nothing
    // (nothing sensible follows); beyond the body's height either way, a warning.
    const double top = body_->top_position(state_);
    const double height = body_->discretization().mesh.clamp_height();
    if (!(top > -(height + p.initial_gap))) {
        Text msg;
        msg << "at t = " << state_.time << " the top edge is at top_position = " << top
            << " m, at or below the foundation (the body is " << height << " m high, " << p.initial_gap
            << " m above it): the body would be compressed to nothing, where "
            << "linear elasticity means nothing; check top_displacement (or top_force) and its "
            << "coupling";
        throw NumericalFailure(msg.str());
    }
    if (std::abs(top) > height && !travel_warned_) {
        travel_warned_ = true;
        Text msg;
        msg << "at t = " << state_.time << " the top edge has moved by top_position = " << top
            << " m, more than the body's height " << height << " m: check top_displacement "
            << "(or top_force) and its coupling";
        warnings_.push_back(msg.str());
    }
    if (w.normal_contact > contact_work_warning * put_in && !contact_work_warned_) {
        contact_work_warned_ = true;
        Text msg;
        msg << "at t = " << state_.time
            << " the contact has created normal_contact_work = " << w.normal_contact << " " << J
            << ", more than " << contact_work_warning << " of E(0) + the work put in (" << put_in << " " << J
            << "): energy the scheme makes, not "
            << "physics. mass_matrix = 4 (redistributed_implicit_contact) cannot create it";
        if (p.friction_coefficient > 0) msg << "; with friction, also see damping_stiffness";
        warnings_.push_back(msg.str());
    }
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

void Simulation::advance(const StepInputs& in, double s0, double dt, double weight, StepSums& sums) {
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
    SubstepReport r;
    try {
        r = body_->substep(state_, dt, load);
    } catch (const ContactSolveError& e) {
        state_.lambda = lambda_before_;  // the substep changed nothing else
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
    for (size_t c3 = 0; c3 < 3; ++c3) avg.top_reaction[c3] += weight * r.top_reaction[c3];
    avg.max_penetration = std::max(avg.max_penetration, r.max_penetration);
    avg.active_contact_nodes = r.active_nodes;
    avg.slipping_contact_nodes = r.slipping_nodes;
    StepStatistics& stats = sums.stats;
    stats.contact_solves += r.contact_solved;
    stats.contact_iterations += r.contact_iterations;
    stats.max_contact_iterations = std::max(stats.max_contact_iterations, r.contact_iterations);
    stats.gauss_seidel_sweeps += r.contact_sweeps;
}

// Halvings are the rare path: a step where they pile up costs several times its nominal
// substeps (each failed try runs the contact solver to its limits first), and says that
// internal_step is too large for the contact problem here. Said once per such step.
void Simulation::warn_refinements(const StepStatistics& stats) {
    if (stats.refinements < refinement_warning_count ||
        stats.refinements < refinement_warning_share * stats.substeps)
        return;
    const SceneParameters& p = body_->parameters();
    Text msg;
    msg << "step to t = " << state_.time << ": " << stats.refinements << " substep halvings for "
        << stats.substeps << " substeps of " << nominal_substep_ << " s (smallest substep "
        << stats.smallest_substep << " s): the contact problem of a substep this large had no "
        << "solution the solver could reach from its start, and the retries cost time";
    const bool weakening =
        p.friction_coefficient > 0 && p.stribeck_velocity > 0 && p.static_friction_ratio > 1;
    if (weakening)
        msg << ". With friction that drops with the slip rate (static_friction_ratio = "
            << p.static_friction_ratio << " over stribeck_velocity = " << p.stribeck_velocity
            << " m/s) a substep is uniquely solvable only below a size that shrinks as the "
               "normal force grows (docs/contract.md, \"Friction that depends on the slip rate\")";
    msg << ". To avoid the retries set internal_step <= " << stats.smallest_substep << " s";
    if (weakening)
        msg << ", or soften the drop (a larger stribeck_velocity or a smaller static_friction_ratio)";
    warnings_.push_back(msg.str());
}

std::string Simulation::growth_advice() const {
    const SceneParameters& p = body_->parameters();
    Text msg;
    msg << ". What to change:";
    const double wedge = wedging_friction(p);
    if (p.friction_coefficient >= wedge)
        msg << " with F = " << p.friction_coefficient << " no steady sliding exists (from F = " << wedge
            << " on the damped stability map the clamped body wedges and its normal "
            << "force grows without bound), so no damping_stiffness helps: lower "
               "friction_coefficient below "
            << wedge << ";";
    else if (p.friction_coefficient > 0)
        msg << " with friction (F = " << p.friction_coefficient << ") steady sliding is "
            << "unstable unless damped: set damping_stiffness (4e-6 s stabilizes F <= 0.3 on "
               "the paper's scene);";
    if (!contact_at_end_of_step(p.mass_matrix) && (p.lambda >= 5 * p.mu || works_.normal_contact > 0))
        msg << " the midpoint contact gains energy (lambda/mu = " << p.lambda / p.mu
            << "; normal_contact_work = " << works_.normal_contact << " "
            << body_->discretization().mesh.energy_unit() << "): mass_matrix = 4 "
            << "(redistributed_implicit_contact) cannot;";
    msg << " or reduce internal_step (now " << p.internal_step << " s)";
    return msg.str();
}

// Section 6 of the paper: the one-element step with the normal mass removed is uniquely
// solvable for every F only below a step size; with F > c/b = (lambda+3mu)/(lambda+mu) and
// the tangential mass removed too (redistributed_both) it can have several solutions.
void Simulation::fail_contact(const ContactSolveError& e, double s0, double dt, const StepSums& sums) const {
    const SceneParameters& p = body_->parameters();
    const double c_over_b = (p.lambda + 3 * p.mu) / (p.lambda + p.mu);
    Text msg;
    msg << "contact solve failed at t = " << state_.time << " (" << s0
        << " s into the step) with F = " << p.friction_coefficient << ", for substeps of "
        << nominal_substep_;
    for (double size = 0.5 * nominal_substep_; size >= dt; size *= 0.5) msg << ", " << size;
    msg << " s (min_internal_step = " << p.min_internal_step << " s); at the last solved "
        << "substep of this step " << sums.avg.active_contact_nodes << " of " << body_->num_contact_nodes()
        << " contact nodes were in contact, " << sums.avg.slipping_contact_nodes << " slipping. " << e.what()
        << ". ";
    if (const std::string why = massless_edge_warning(p); !why.empty()) {
        msg << "Cause: " << why;
    } else if (p.friction_coefficient > c_over_b) {
        msg << "F exceeds c/b = (lambda+3mu)/(lambda+mu) = " << c_over_b
            << (p.mass_matrix == MassVariant::redistributed_both
                    ? ": with redistributed_both the step can then have several solutions at "
                      "any step size (paper, section 6); use mass_matrix = 1 or a smaller F"
                    : ": the step is uniquely solvable only below a step size (paper, section 6);"
                      " reduce internal_step (by 10x to 1000x) or F");
    } else if (p.friction_coefficient > 0 && p.stribeck_velocity > 0 && p.static_friction_ratio > 1) {
        // Halving did not help: the law, not the substep's size (docs/contract.md, "Friction
        // that depends on the slip rate").
        msg << "Cause: friction that drops with the slip rate (static_friction_ratio = "
            << p.static_friction_ratio << " over stribeck_velocity = " << p.stribeck_velocity
            << " m/s): where the drop is steep against the normal force, a substep's problem can "
               "lose its unique solution (the paper's open question for such laws), and halving "
               "the substep did not restore it. Settings that run such scenes: mass_matrix = 4 "
               "(redistributed_implicit_contact) or 3, or a softer drop (a larger "
               "stribeck_velocity, or static_friction_ratio nearer 1)";
    } else {
        msg << "Reduce internal_step, or check contact_tolerance (" << p.contact_tolerance << ")";
    }
    throw NumericalFailure(msg.str());
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
    if (!f.pattern.empty() && f.pattern.size() != static_cast<size_t>(nc))
        throw std::invalid_argument("the contact factorization does not fit this mesh");
    for (signed char x : f.pattern)
        if (x != 0 && x != 1 && x != 2 && x != -2 && x != 3 && x != -3)
            throw std::invalid_argument("invalid node state in the contact factorization");
    body_->set_cached_substeps(snapshot.factor_substeps);
    body_->forget_kept();
    body_->set_contact_factorization(f);
    state_ = s;
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
