// "No refactorization while the substep size is unchanged": a master that alternates
// two communication step sizes (1e-4 and 7e-5 s) against one that keeps one, and against one
// whose step changes every time (what alternation costs without a cache: a factorization of
// K = 4/dt^2 M_r + A and its Delassus block per step). Same number of steps, same scene.
// Prints JSON.   bench_step_sizes NX INTERNAL_STEP STEPS
#include <cstdio>
#include <cstdlib>
#include <functional>

#include "bench_common.hpp"
#include "simulation/simulation.hpp"

using namespace contactbody;
using namespace bench;

int main(int argc, char** argv) {
    if (argc != 4) {
        std::fprintf(stderr, "usage: bench_step_sizes NX INTERNAL_STEP STEPS\n");
        return 2;
    }
    const SceneParameters p = paper_scene(argv);
    const int steps = std::atoi(argv[3]);
    const double top = -2.5e-5;
    const StepInputs inputs{{20, 0}, {0, 0}, top, 0};

    struct Schedule {
        const char* name;
        std::function<double(int)> step;
    };
    const Schedule schedules[] = {
        {"constant 1e-4", [](int) { return 1e-4; }},
        {"alternating 1e-4 / 7e-5", [](int k) { return k % 2 ? 7e-5 : 1e-4; }},
        // Every step a new substep size (the substep count stays 25 or 18, as alternating).
        {"changing every step", [](int k) { return (k % 2 ? 7e-5 : 1e-4) * (1 - 1e-6 * k); }},
    };
    std::printf("{\"nx\": %d, \"internal_step\": %g, \"steps\": %d, \"schedules\": [", p.nx, p.internal_step,
                steps);
    bool first = true;
    for (const Schedule& s : schedules) {
        Simulation sim(p, top);
        long substeps = 0;
        const auto t0 = Clock::now();
        for (int k = 0; k < steps; ++k) {
            sim.do_step(s.step(k), inputs);
            substeps += sim.statistics().substeps;
        }
        const double seconds = seconds_since(t0);
        std::printf(
            "%s{\"schedule\": \"%s\", \"seconds\": %.4f, \"factorizations\": %d, "
            "\"substeps\": %ld}",
            first ? "" : ", ", s.name, seconds, sim.body().factorizations(), substeps);
        first = false;
    }
    std::printf("]}\n");
    return 0;
}
