// The guards of a step: finite and plausible outputs, the halvings' warning, and the message of
// a contact solve that failed.
#include "simulation/simulation.hpp"

#include <algorithm>
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

}  // namespace contactbody
