// Substeps chosen by a tolerance (docs/decisions.md "Substeps chosen by a tolerance"): step
// doubling on the midpoint scheme. A pair is one coarse substep and two halves from the same
// state; the halves advance the state (each a midpoint substep, so the energy balance holds
// as for fixed substeps) and their difference to the coarse one estimates their error.
#include <cmath>
#include <algorithm>
#include <cstdint>
#include <limits>

#include "simulation/simulation.hpp"
#include "util/text.hpp"

namespace contactbody {

namespace {
// The midpoint scheme is of order 2: the halves' error is their difference to the coarse
// substep over 2^2 - 1, and doubling the size multiplies a pair's estimate by about 8.
constexpr double richardson_divisor = 3;
// A pair grows its size where 8 times its estimate stays below half the tolerance.
constexpr double grow_below = 1.0 / 16;
}  // namespace

double Simulation::pair_error() {
    pair_difference_.u = state_.u - pair_coarse_.u;
    pair_difference_.v = state_.v - pair_coarse_.v;
    const auto [kinetic, strain] = kinetic_and_strain_energy(pair_difference_);
    const double difference = std::sqrt(2 * (kinetic + strain));
    if (difference == 0) return 0;
    const double scale = std::sqrt(2 * std::max(energy(state_), energy(pair_start_)));
    if (!(scale > 0)) return std::numeric_limits<double>::infinity();
    return difference / (richardson_divisor * scale);
}

Simulation::PairOutcome Simulation::controlled_pair(const StepInputs& in, const PairLadder& ladder,
                                                    std::int64_t position, int level, StepSums& sums) {
    const SceneParameters& p = body_->parameters();
    StepStatistics& stats = sums.stats;
    const double coarse = std::ldexp(ladder.nominal, -level), half = 0.5 * coarse;
    const double s0 = static_cast<double>(position) * ladder.tick;
    const double weight = std::ldexp(1.0, -(level + 1));  // a half over the nominal substep
    pair_start_ = state_;
    pair_works_ = works_;
    const Observables pair_avg = sums.avg;
    pair_sum_N_ = edge_sum_N_;
    pair_sum_T_ = edge_sum_T_;
    double error = 0;
    try {
        const SubstepReport r = solve_substep(in, s0, coarse);
        ++stats.estimate_substeps;
        stats.contact_iterations += r.contact_iterations;
        pair_coarse_ = state_;
        state_ = pair_start_;
        add_substep(solve_substep(in, s0, half), weight, sums);
        add_substep(solve_substep(in, s0 + half, half), weight, sums);
        error = pair_error();
    } catch (const ContactSolveError& e) {
        if (level >= ladder.deepest) {
            state_ = pair_start_;
            fail_contact(e, s0, half, sums);
        }
        error = std::numeric_limits<double>::infinity();
    }
    stats.smallest_substep = std::min(stats.smallest_substep, half);
    if (error <= p.tolerance || level >= ladder.deepest) {
        if (error > p.tolerance) ++stats.unmet_tolerance;
        stats.substeps += 2;
        return {error, level};  // the last pair accepted: this one
    }
    // Rejected: the same interval as two pairs of half the size, each refined as far as it needs.
    state_ = pair_start_;
    works_ = pair_works_;
    sums.avg = pair_avg;
    edge_sum_N_ = pair_sum_N_;
    edge_sum_T_ = pair_sum_T_;
    ++stats.refinements;
    controlled_pair(in, ladder, position, level + 1, sums);
    return controlled_pair(in, ladder, position + ladder.ticks(level + 1), level + 1, sums);
}

void Simulation::controlled_substeps(const StepInputs& in, int n, double dt, StepSums& sums) {
    const SceneParameters& p = body_->parameters();
    sums.stats.substeps = 0;
    PairLadder ladder;
    ladder.nominal = dt;
    ladder.tick = std::ldexp(dt, -PairLadder::finest_level);
    // The deepest level: its halves at least min_internal_step (level 0 always).
    while (ladder.deepest + 1 < PairLadder::finest_level &&
           std::ldexp(dt, -(ladder.deepest + 2)) >= p.min_internal_step)
        ++ladder.deepest;
    // Start where the last step ended (the first step: at the nominal substep).
    int level = 0;
    while (controlled_substep_ > 0 && level < ladder.deepest &&
           std::ldexp(dt, -level) > controlled_substep_ * (1 + 1e-9))
        ++level;
    const std::int64_t end = static_cast<std::int64_t>(n) * ladder.ticks(0);
    std::int64_t position = 0;
    while (position < end) {
        const PairOutcome last = controlled_pair(in, ladder, position, level, sums);
        position += ladder.ticks(level);
        // The next pair at the last accepted one's size, doubled where its estimate leaves room
        // (and the double lands on the ladder).
        level = last.level;
        if (last.error <= grow_below * p.tolerance && level > 0 && position % ladder.ticks(level - 1) == 0)
            --level;
    }
    controlled_substep_ = std::ldexp(dt, -level);
}

void Simulation::warn_unmet_tolerance(const StepStatistics& stats) {
    if (stats.unmet_tolerance == 0) return;
    const SceneParameters& p = body_->parameters();
    Text msg;
    msg << "step to t = " << state_.time << ": " << stats.unmet_tolerance << " pairs of substeps of "
        << stats.smallest_substep << " s missed tolerance = " << p.tolerance
        << " and were kept: their size is the smallest min_internal_step = " << p.min_internal_step
        << " s allows (a nonsmooth event the substeps do not resolve, or a tolerance below what the "
           "contact solve's contact_tolerance = "
        << p.contact_tolerance << " leaves); lower min_internal_step or raise tolerance";
    warnings_.push_back(msg.str());
}

}  // namespace contactbody
