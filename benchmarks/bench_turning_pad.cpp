// One case of benchmarks/turning_pad.py: the pad of examples/turning_pad_3d.py (F = 0.5,
// damping_stiffness 2e-6 s, 4e-6 s substeps), pressed from the static start by 0.1 mm, the
// foundation at 0.2 m/s along x, its heading turning a right angle from 0.2 to 1.2 ms (a ramp
// within each communication step of 50 us), then along z to STOP. Prints one JSON object: the
// set-up, and per phase (straight, turning, along z) the substeps, the held solves and Newton
// iterations, the refactorizations and the CPU seconds; the whole run's CPU seconds per
// simulated millisecond and its final outputs (the same solution across contact paths).
//   bench_turning_pad MESH MODES PATH(automatic|sparse|sparse_gcr) [STOP]
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>

#include "bench_common.hpp"
#include "simulation/simulation.hpp"

using namespace contactbody;
using namespace bench;

namespace {

constexpr double speed = 0.2, turn_start = 2e-4, turn_end = 1.2e-3, interval = 5e-5;

// The foundation's heading (rad) at time t: 0 until turn_start, pi/2 from turn_end.
double heading(double t) {
    const double s = std::min(std::max((t - turn_start) / (turn_end - turn_start), 0.0), 1.0);
    return 0.5 * M_PI * s;
}

double cpu_seconds() { return static_cast<double>(std::clock()) / CLOCKS_PER_SEC; }

struct Phase {
    const char* name;
    int substeps = 0, iterations = 0;
    long held_solves = 0, refactorizations = 0;
    double cpu = 0;
};

}  // namespace

int main(int argc, char** argv) {
    if (argc < 4) {
        std::fprintf(stderr, "usage: bench_turning_pad MESH MODES PATH [STOP]\n");
        return 2;
    }
    SceneParameters p;
    p.mesh = argv[1];
    p.dimension = 3;
    p.modes = std::atoi(argv[2]);
    p.friction_coefficient = 0.5;
    p.damping_stiffness = 2e-6;
    p.static_initial_state = true;
    const double top = -1e-4, stop = argc > 4 ? std::atof(argv[4]) : 3e-3;
    double cpu = cpu_seconds();
    auto t0 = Clock::now();
    Stepper* stepper = nullptr;
    Simulation sim(body_on_path(p, argv[3], &stepper), top);
    const double setup_seconds = seconds_since(t0), setup_cpu = cpu_seconds() - cpu;
    std::array<Phase, 3> phases{Phase{"straight"}, Phase{"turning"}, Phase{"along z"}};
    const int steps = static_cast<int>(std::lround(stop / interval));
    double max_heading_lag = 0;
    for (int k = 0; k < steps; ++k) {
        const double t = k * interval;
        Phase& phase = phases[t < turn_start ? 0 : t < turn_end ? 1 : 2];
        StepInputs in;
        const double a0 = heading(t), a1 = heading(t + interval);
        in.foundation_velocity[0] = speed * std::cos(a0);
        in.foundation_velocity[1] = speed * std::sin(a0);
        in.foundation_acceleration[0] = speed * (std::cos(a1) - std::cos(a0)) / interval;
        in.foundation_acceleration[1] = speed * (std::sin(a1) - std::sin(a0)) / interval;
        in.top_displacement = top;
        const long solves = stepper ? stepper->sparse_solver().solves() : 0L;
        const long refactorizations = stepper ? stepper->sparse_refactorizations() : 0L;
        cpu = cpu_seconds();
        sim.do_step(interval, in);
        phase.cpu += cpu_seconds() - cpu;
        phase.substeps += sim.statistics().substeps;
        phase.iterations += sim.statistics().contact_iterations;
        if (stepper) {
            phase.held_solves += stepper->sparse_solver().solves() - solves;
            phase.refactorizations += stepper->sparse_refactorizations() - refactorizations;
        }
        // How far the friction's heading lags the foundation's (radians, the step's mean force;
        // turning_pad_3d.py's heading).
        const Observables& o = sim.observables();
        const double friction_heading = std::atan2(o.friction_force[1], o.friction_force[0]);
        max_heading_lag = std::max(max_heading_lag, std::abs(heading(t + interval) - friction_heading));
    }
    const Observables& o = sim.observables();
    double run_cpu = 0;
    std::printf(
        "{\"nodes\": %d, \"contact_nodes\": %d, \"modes\": %d, \"path\": \"%s\", "
        "\"sparse\": %s, \"setup_seconds\": %.6g, \"setup_cpu_seconds\": %.6g, \"phases\": [",
        sim.body().discretization().mesh.num_nodes(), sim.body().num_contact_nodes(), p.modes, argv[3],
        stepper && stepper->sparse_contact() ? "true" : "false", setup_seconds, setup_cpu);
    for (size_t i = 0; i < phases.size(); ++i) {
        const Phase& f = phases[i];
        run_cpu += f.cpu;
        std::printf(
            "%s{\"phase\": \"%s\", \"substeps\": %d, \"held_solves\": %ld, "
            "\"held_solves_per_substep\": %.4g, \"newton_iterations_per_substep\": %.4g, "
            "\"refactorizations\": %ld, \"cpu_seconds\": %.6g, \"cpu_ms_per_substep\": %.4g}",
            i ? ", " : "", f.name, f.substeps, f.held_solves, static_cast<double>(f.held_solves) / f.substeps,
            static_cast<double>(f.iterations) / f.substeps, f.refactorizations, f.cpu,
            1e3 * f.cpu / f.substeps);
    }
    std::printf(
        "], \"run_cpu_seconds\": %.6g, \"cpu_seconds_per_simulated_ms\": %.6g, "
        "\"max_heading_lag\": %.6g, \"normal_force\": %.17g, \"friction_force\": %.17g, "
        "\"friction_force_z\": %.17g, \"energy\": %.17g, \"peak_memory_mb\": %.1f}\n",
        run_cpu, run_cpu / (1e3 * stop), max_heading_lag, o.normal_force, o.friction_force[0],
        o.friction_force[1], o.energy, peak_rss_mb());
    return 0;
}
