// The static start: the quasi-static load path to the initial state, and its balance check.
#include "simulation/simulation.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <string>
#include <tuple>
#include <type_traits>
#include <utility>

#include "reduced/reduced_stepper.hpp"
#include "simulation/scheme_warnings.hpp"
#include "util/text.hpp"

namespace contactbody {

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
// nodes lie on the foundation, and its friction is within the cone the substep allowed.
// Without increments (a frictionless curved boundary: its static state does not depend on the
// path) that substep alone loads from `start`, to 2 top - start, so that its midpoint's top
// is `top`. At
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
    // Its midpoint's top is `top`: held there, or loaded from `start` where no increment ran.
    const double from = increments > 0 ? top : start;
    run(path, from, 2 * top - from);
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
    p.tolerance = 0;  // the path takes its own substeps (and the controller refuses this variant)
    p.damping_mass = p.damping_stiffness = 0;
    auto path = std::make_unique<Stepper>(p);
    // docs/decisions.md, "The static start's load path solves its early patterns loosely"
    path->contact_options().inexact_forcing = 0.1;
    path->contact_options().wide_span_nonzeros = std::numeric_limits<double>::infinity();
    path->contact_options().max_differing = 1024;
    return path;
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
    using Clock = std::chrono::steady_clock;
    const auto seconds_since = [](Clock::time_point t) {
        return std::chrono::duration<double>(Clock::now() - t).count();
    };
    auto started = Clock::now();
    std::unique_ptr<Stepper> path_body = own ? nullptr : path_stepper(path);
    Body& runs = own ? *body_ : *path_body;
    Stepper* timing = flat ? nullptr : path_body.get();
    static_start_cost_ = StaticStartCost{};
    static_start_cost_.path_body_seconds = seconds_since(started);
    started = Clock::now();
    // What the load paths cost, once they have run (both ways below).
    const auto count = [&] {
        static_start_cost_.path_seconds = seconds_since(started);
        if (const auto* stepper = dynamic_cast<const Stepper*>(&runs)) {
            static_start_cost_.held_solves = stepper->sparse_solver().solves();
            static_start_cost_.refactorizations = stepper->sparse_refactorizations();
        }
    };
    // Without friction the static state does not depend on the path (the least energy under
    // the contact): a curved boundary's path is its settling substep alone, not ten contact
    // solves whose contact sets differ (docs/decisions.md, "The factor of a 3D body" and "The
    // static start's load path solves its early patterns loosely"). A flat one keeps its ten
    // (its bits).
    const int increments_count = !flat && !(p.friction_coefficient > 0) ? 0 : 10;
    if (!p.force_control) {
        // A top pressed below the gap touches: close the gap rigidly first (above).
        const double start = top < -p.initial_gap ? -p.initial_gap : 0.0;
        state_ = body_->from_full(quasi_static_path(runs, timing, top, start, increments_count));
        count();
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
    count();
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

}  // namespace contactbody
