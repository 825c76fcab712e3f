// The reduced body against the full body on the damped sliding scene (the paper's body,
// F = 0.3, beta = 4e-6 s, the foundation at 20 m/s, the top held), in one run: per mode count
// and substep, the error of the step-averaged normal and friction forces and of the energy
// (L2 over the communication steps, relative to the full body's) and the wall time per
// simulated second of both. Prints one JSON object.
//   bench_reduced_body NX DT STOP MODES[,MODES...] [DT_FACTOR[,DT_FACTOR...]]
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <string>
#include <vector>

#include "bench_common.hpp"
#include "reduced/reduced_stepper.hpp"

using namespace contactbody;
using namespace bench;

namespace {

constexpr double interval = 1e-4;  // the communication step whose averages are compared
constexpr double top = -2.5e-5;

struct Series {
    std::vector<double> normal, friction, energy;
    double wall = 0, setup = 0;
    int substeps = 0;
};

std::vector<double> numbers(const char* text) {
    std::vector<double> out;
    std::stringstream in(text);
    std::string item;
    while (std::getline(in, item, ',')) out.push_back(std::atof(item.c_str()));
    return out;
}

// Runs `step` (one substep, returning its report) over [0, stop], averaging per interval;
// `energy` reads E at the end of each interval.
template <class Step, class Energy>
Series run(double dt, double stop, Step&& step, Energy&& energy) {
    Series s;
    // As the FMU does: whole substeps per interval, at most dt (a dt that does not divide the
    // interval would shift every average against the reference's).
    const int per_interval = static_cast<int>(std::ceil(interval / dt * (1 - 1e-9)));
    dt = interval / per_interval;
    const int intervals = static_cast<int>(std::lround(stop / interval));
    const auto t0 = Clock::now();
    for (int i = 0; i < intervals; ++i) {
        double n = 0, f = 0;
        for (int k = 0; k < per_interval; ++k) {
            const SubstepReport r = step(dt);
            n += r.normal_force;
            f += r.friction_force[0];
        }
        s.normal.push_back(n / per_interval);
        s.friction.push_back(f / per_interval);
        s.energy.push_back(energy());
        s.substeps += per_interval;
    }
    s.wall = seconds_since(t0);
    return s;
}

double l2_relative(const std::vector<double>& x, const std::vector<double>& ref) {
    double num = 0, den = 0;
    for (size_t i = 0; i < ref.size(); ++i) {
        num += (x[i] - ref[i]) * (x[i] - ref[i]);
        den += ref[i] * ref[i];
    }
    return std::sqrt(num / den);
}

}  // namespace

int main(int argc, char** argv) {
    if (argc < 5) {
        std::fprintf(stderr, "usage: bench_reduced_body NX DT STOP MODES[,...] [DT_FACTOR[,...]]\n");
        return 2;
    }
    SceneParameters p = paper_scene(argv);
    p.friction_coefficient = 0.3;
    p.damping_stiffness = 4e-6;
    const double dt = p.internal_step, stop = std::atof(argv[3]);
    const std::vector<double> modes = numbers(argv[4]);
    const std::vector<double> factors = argc > 5 ? numbers(argv[5]) : std::vector<double>{1};
    const SubstepLoad load{top, top, 0, 20};

    auto t0 = Clock::now();
    Stepper full(p);
    State s = full.initial_state(top);
    const double full_setup = seconds_since(t0);
    const Discretization& d = full.discretization();
    Series reference = run(
        dt, stop, [&](double h) { return full.substep(s, h, load); },
        [&] { return 0.5 * s.v.dot(d.M * s.v) + 0.5 * s.u.dot(d.A * s.u); });
    reference.setup = full_setup;

    std::printf("{\"nx\": %d, \"dt\": %.6g, \"stop\": %.6g, \"free_dofs\": %ld, \"contact_nodes\": %d,\n",
                p.nx, dt, stop, static_cast<long>(d.A_free.rows()), full.num_contact_nodes());
    std::printf(
        " \"full\": {\"setup_s\": %.6g, \"wall_s\": %.6g, \"substeps\": %d, \"wall_per_simulated_s\": "
        "%.6g},\n",
        reference.setup, reference.wall, reference.substeps, reference.wall / stop);
    std::printf(" \"reduced\": [");
    bool first = true;
    for (double m : modes) {
        t0 = Clock::now();
        ReducedStepper reduced(p, static_cast<int>(m));
        const double setup = seconds_since(t0);
        // Where a reduced substep's time goes: the same substeps pressed (the contact solve
        // on every node) and lifted off (no contact solve), 200 each after 20 unmeasured.
        double substep_us[2] = {0, 0};
        for (int lifted = 0; lifted < 2; ++lifted) {
            const double at = lifted ? 1e-3 : top;
            ReducedState r = reduced.from_full(full.initial_state(at));
            const SubstepLoad held{at, at, 0, 20};
            for (int k = 0; k < 20; ++k) reduced.substep(r, dt, held);
            const auto tic = Clock::now();
            for (int k = 0; k < 200; ++k) reduced.substep(r, dt, held);
            substep_us[lifted] = seconds_since(tic) / 200 * 1e6;
        }
        for (double factor : factors) {
            ReducedState r = reduced.from_full(full.initial_state(top));
            Series x = run(
                dt * factor, stop, [&](double h) { return reduced.substep(r, h, load); },
                [&] { return reduced.energy(r); });
            std::printf(
                "%s\n  {\"modes\": %d, \"residual\": %ld, \"dt\": %.6g, \"setup_s\": %.6g, "
                "\"basis_s\": %.6g, \"wall_s\": %.6g, \"wall_per_simulated_s\": %.6g, "
                "\"speedup\": %.6g, \"error_normal_force\": %.6g, "
                "\"error_friction_force\": %.6g, \"error_energy\": %.6g, "
                "\"highest_mode_hz\": %.6g, \"substep_us_pressed\": %.6g, "
                "\"substep_us_lifted\": %.6g}",
                first ? "" : ",", static_cast<int>(m), static_cast<long>(reduced.basis().residual.cols()),
                dt * factor, setup, reduced.basis().setup_seconds, x.wall, x.wall / stop,
                reference.wall / x.wall, l2_relative(x.normal, reference.normal),
                l2_relative(x.friction, reference.friction), l2_relative(x.energy, reference.energy),
                std::sqrt(reduced.basis().omega2.maxCoeff()) / (2 * M_PI), substep_us[0], substep_us[1]);
            first = false;
        }
    }
    std::printf("]}\n");
    return 0;
}
