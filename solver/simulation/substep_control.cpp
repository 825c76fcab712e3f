// Substeps chosen by a tolerance (docs/decisions.md "Substeps chosen by a tolerance"): step
// doubling on the midpoint scheme. A pair is two coarse substeps and four fine ones of half
// their size from the same state; the fine ones advance the state (each a midpoint substep, so
// the energy balance holds as for fixed substeps) and their difference to the coarse ones
// estimates their error.
#include <cmath>
#include <algorithm>
#include <cstdint>
#include <limits>

#include "simulation/simulation.hpp"
#include "util/text.hpp"

namespace contactbody {

namespace {
// The midpoint scheme is of order 2: the fine substeps' error is their difference to the coarse
// ones over 2^2 - 1, and doubling the span multiplies a smooth pair's estimate by about 8.
constexpr double richardson_divisor = 3;
// A pair grows its size where 8 times its estimate stays below half the tolerance.
constexpr double grow_below = 1.0 / 16;
// Coarse substeps a pair takes (fine ones: twice as many, each half as long); the fine
// substeps are nominal / 2^(level + pair_levels), pair_levels = log2(2 pair_substeps).
constexpr int pair_substeps = 2, pair_levels = 2;
constexpr double solved_per_pair = 3 * pair_substeps;  // coarse and fine
}  // namespace

double Simulation::pair_error() {
    pair_end_energy_ = energy(state_);
    pair_difference_.u = state_.u - pair_coarse_.u;
    pair_difference_.v = state_.v - pair_coarse_.v;
    const auto [kinetic, strain] = kinetic_and_strain_energy(pair_difference_);
    const double difference = std::sqrt(2 * (kinetic + strain));
    if (difference == 0) return 0;
    const double scale = std::sqrt(2 * std::max(pair_end_energy_, pair_start_energy_));
    if (!(scale > 0)) return std::numeric_limits<double>::infinity();
    return difference / (richardson_divisor * scale);
}

Simulation::PairOutcome Simulation::controlled_pair(const StepInputs& in, const PairLadder& ladder,
                                                    std::int64_t position, int level, StepSums& sums) {
    const SceneParameters& p = body_->parameters();
    StepStatistics& stats = sums.stats;
    // The pair spans nominal / 2^level: `pair_substeps` coarse substeps against twice as many
    // fine ones, which advance. An even number on each side: a massless dof's end values
    // alternate about its midpoint values from substep to substep, which after an odd number
    // would differ between the sides by an amount no size reduces.
    const int fine_level = level + pair_levels;
    const double fine = std::ldexp(ladder.nominal, -fine_level), coarse = 2 * fine;
    const double weight = std::ldexp(1.0, -fine_level);  // a fine substep over the nominal one
    auto at = [&](int k, int at_level) {  // the start of substep k of size nominal / 2^at_level
        return static_cast<double>(position + k * ladder.ticks(at_level)) * ladder.tick;
    };
    pair_start_ = state_;
    pair_works_ = works_;
    const Observables pair_avg = sums.avg;
    pair_sum_N_ = edge_sum_N_;
    pair_sum_T_ = edge_sum_T_;
    double error = 0;
    try {
        for (int k = 0; k < pair_substeps; ++k) {
            const SubstepReport r = solve_substep(in, at(k, fine_level - 1), coarse);
            ++stats.estimate_substeps;
            stats.contact_iterations += r.contact_iterations;
        }
        pair_coarse_ = state_;
        state_ = pair_start_;
        for (int k = 0; k < 2 * pair_substeps; ++k)
            add_substep(solve_substep(in, at(k, fine_level), fine), weight, sums);
        error = pair_error();
    } catch (const ContactSolveError& e) {
        if (level >= ladder.deepest) {
            state_ = pair_start_;
            fail_contact(e, at(0, fine_level), fine, sums);
        }
        error = std::numeric_limits<double>::infinity();
    }
    stats.smallest_substep = std::min(stats.smallest_substep, fine);
    if (error <= p.tolerance || level >= ladder.deepest) {
        if (error > p.tolerance) ++stats.unmet_tolerance;
        stats.substeps += 2 * pair_substeps;
        pair_start_energy_ = pair_end_energy_;
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
    // The deepest level: its fine substeps at least min_internal_step (level 0 always).
    while (ladder.deepest + 1 + pair_levels <= PairLadder::finest_level &&
           std::ldexp(dt, -(ladder.deepest + 1 + pair_levels)) >= p.min_internal_step)
        ++ladder.deepest;
    // Start where the last step ended (the first step: at the nominal substep).
    int level = 0;
    while (controlled_substep_ > 0 && level < ladder.deepest &&
           std::ldexp(dt, -level) > controlled_substep_ * (1 + 1e-9))
        ++level;
    pair_start_energy_ = energy(state_);
    const std::int64_t end = static_cast<std::int64_t>(n) * ladder.ticks(0);
    std::int64_t position = 0;
    while (position < end) {
        const PairOutcome last = controlled_pair(in, ladder, position, level, sums);
        position += ladder.ticks(level);
        // The next pair at the last accepted one's size, doubled where its estimate leaves room
        // (and the double lands on the ladder).
        if (last.level != level) declined_savings_ = 0;
        level = last.level;
        if (last.error <= grow_below * p.tolerance && level > 0 && position % ladder.ticks(level - 1) == 0) {
            // The doubled span brings in a coarse substep of this span: on a large body a new
            // factorization. It is taken once the doublings declined at this span have forgone
            // as many substeps as it costs solves (each forgoes a pair's: the two pairs to the
            // next chance solve twice what one doubled pair does), as one rents skis until the
            // rent reaches the price. Whether a factor of that size is kept is not asked: a
            // restored state must choose the same (the sum is part of it).
            const double cost = body_->new_operator_in_solves();
            if (declined_savings_ >= cost) {
                --level;
                declined_savings_ = 0;
            } else {
                declined_savings_ += solved_per_pair;
                ++sums.stats.declined_growths;
                sums.stats.new_operator_solves = cost;
            }
        }
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
