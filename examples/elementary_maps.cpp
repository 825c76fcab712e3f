// Section 6 of the paper: the structure of the solution set of one midpoint step of the
// one-triangle example over the plane of loads f = (f_nu, f_tau) (the paper's Figs. 3-5),
// computed by ContactSolver (the stepper's contact solve) from a family of starting multipliers,
// against the closed forms S1-S4 on the sets sigma_1-sigma_4.
//   elementary_maps LAME MU DT M1 M2 FRICTION U_TAU_OLD FN_MIN FN_MAX FT_MIN FT_MAX N OUT.csv
//                   [EXCESS STRIBECK_VELOCITY VISCOUS]
// Writes one CSV row per grid point and prints a JSON summary. With the last three
// friction depends on the slip rate v = slip / (DT / 2): F(v) = FRICTION + EXCESS
// exp(-|v| / STRIBECK_VELOCITY) + VISCOUS |v|, and the reference set is rate_solutions()
// (the slip equation's roots) instead of the closed forms.
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>

#include "contact/elementary_example.hpp"

using namespace contactbody;

namespace {
int mask_of(const std::vector<ElementarySolution>& list) {
    int mask = 0;
    for (const ElementarySolution& s : list) mask |= 1 << s.region;
    return mask;
}

// Largest distance from a solution of `from` to the nearest one of `to`.
double set_distance(const std::vector<ElementarySolution>& from, const std::vector<ElementarySolution>& to) {
    double worst = 0;
    for (const ElementarySolution& s : from) {
        double best = 1e300;
        for (const ElementarySolution& t : to) best = std::min(best, (s.x - t.x).lpNorm<Eigen::Infinity>());
        worst = std::max(worst, best);
    }
    return worst;
}
}  // namespace

int main(int argc, char** argv) {
    if (argc != 14 && argc != 17) {
        std::fprintf(stderr,
                     "usage: elementary_maps LAME MU DT M1 M2 FRICTION U_TAU_OLD FN_MIN FN_MAX "
                     "FT_MIN FT_MAX N OUT.csv [EXCESS STRIBECK_VELOCITY VISCOUS]\n");
        return 2;
    }
    double v[12];
    for (int i = 0; i < 12; ++i) v[i] = std::atof(argv[i + 1]);
    const int n = static_cast<int>(v[11]);
    if (n < 2) {
        std::fprintf(stderr, "elementary_maps: N must be at least 2\n");
        return 2;
    }
    ElementaryExample example = ElementaryExample::from_material(v[0], v[1], v[2], v[3], v[4], v[5], v[6]);
    const bool rate = argc == 17;
    if (rate) {
        ContactProblem::RateLaw law;
        law.excess = std::atof(argv[14]);
        law.stribeck_velocity = std::atof(argv[15]);
        law.viscous = std::atof(argv[16]);
        law.slip_time = v[2] / 2;
        example.set_rate_law(law);
    }
    const bool critical = !rate && example.friction() * example.b() == example.c();
    std::ofstream out(argv[13]);
    if (!out) {
        std::fprintf(stderr, "elementary_maps: cannot write %s\n", argv[13]);
        return 1;
    }
    out << "f_nu,f_tau,closed_count,closed_regions,found_count,found_regions,failed_starts,"
           "continuum,max_violation,set_distance\n";
    ContactSolver solver;
    long points = 0, agree = 0, failed_total = 0, continuum_points = 0, by_count[5] = {0};
    double worst_violation = 0, worst_distance = 0;
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
            const Eigen::Vector2d f(v[7] + (v[8] - v[7]) * i / (n - 1), v[9] + (v[10] - v[9]) * j / (n - 1));
            const double tol = 1e-8 * (1 + f.lpNorm<Eigen::Infinity>());
            int failed = 0;
            const auto found = example.solver_solutions(f, solver, &failed);
            const auto closed =
                rate ? example.rate_solutions(f)
                     : example.closed_form_solutions(f, -1e-12 * (1 + f.lpNorm<Eigen::Infinity>()));
            double violation = 0;
            for (const ElementarySolution& s : found)
                violation = std::max(violation, example.violation(f, s.x));
            // On sigma_5 (F = c/b) the solutions form the segment S_5: every solution found
            // must solve (23); the closed forms S_1, S_2 are its end points.
            const bool continuum =
                critical && example.in_sigma5(f, tol) &&
                (f - Eigen::Vector2d(-example.b() * example.u_tau_old(), example.c() * example.u_tau_old()))
                        .lpNorm<Eigen::Infinity>() > tol;
            const double distance =
                continuum ? 0 : std::max(set_distance(found, closed), set_distance(closed, found));
            ++points;
            failed_total += failed;
            continuum_points += continuum;
            if (!continuum) ++by_count[std::min<size_t>(closed.size(), 4)];
            worst_violation = std::max(worst_violation, violation);
            worst_distance = std::max(worst_distance, distance);
            if (!found.empty() && violation <= tol && distance <= tol &&
                (continuum || found.size() == closed.size()))
                ++agree;
            char row[256];
            std::snprintf(row, sizeof row, "%.17g,%.17g,%zu,%d,%zu,%d,%d,%d,%.3e,%.3e\n", f[0], f[1],
                          closed.size(), mask_of(closed), found.size(), mask_of(found), failed,
                          continuum ? 1 : 0, violation, distance);
            out << row;
        }
    std::printf(
        "{\"a\": %.17g, \"b\": %.17g, \"c\": %.17g, \"c_over_b\": %.17g, \"friction\": %.17g, "
        "\"points\": %ld, \"agree\": %ld, \"one_solution\": %ld, \"two_solutions\": %ld, "
        "\"three_solutions\": %ld, \"continuum_points\": %ld, \"failed_starts\": %ld, "
        "\"max_violation\": %.3e, \"max_set_distance\": %.3e}\n",
        example.a(), example.b(), example.c(), example.c() / example.b(), example.friction(), points, agree,
        by_count[1], by_count[2], by_count[3], continuum_points, failed_total, worst_violation,
        worst_distance);
    return out ? 0 : 1;
}
