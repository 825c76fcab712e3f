// Massless against mass-carrying reduction, side by side with the full body (issue: "whether
// the paper's finding holds here"): the massless-boundary reduced body (ReducedStepper) and
// standard Craig-Bampton (CraigBamptonStepper, the edge carrying the interior's mass through
// its constraint modes), both with the same number of modes, on two scenes of the paper's
// body at nx = ny = NX:
//   impact:  frictionless; the body falls at 1 m/s from a 10 um gap, the clamp moving with it
//            for 30 us and then held (1.5 ms, outputs every 1e-5 s);
//   sliding: F = 0.3, beta = 4e-6 s, the foundation at 20 m/s, the top held (5 ms, 1e-4 s).
// For each body and substep (DT times each factor): wall seconds per simulated second, the
// energy balance's largest residual, and the step-averaged normal force and energy over time
// (the script compares them with the full body's). Prints one JSON object.
//   bench_mass_carrying NX DT MODES FACTOR[,FACTOR...]
#include <cmath>
#include <cstdio>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "bench_common.hpp"
#include "craig_bampton.hpp"
#include "reduced/reduced_stepper.hpp"
#include "simulation/simulation.hpp"

using namespace contactbody;
using namespace bench;

namespace {

struct Scene {
    const char* name;
    SceneParameters params;
    double top0, stop, interval;
    // The inputs of the step starting at t.
    StepInputs (*inputs)(double t);
};

StepInputs impact_inputs(double t) {
    constexpr double contact_phase = 3e-5;  // the clamp follows the body down, then holds
    StepInputs in;
    if (t < contact_phase - 1e-12) {
        in.top_displacement = -t;
        in.top_velocity = -1.0;
    } else {
        in.top_displacement = -contact_phase;
    }
    return in;
}

StepInputs sliding_inputs(double) {
    StepInputs in;
    in.foundation_velocity[0] = 20;
    in.top_displacement = -2.5e-5;
    return in;
}

std::string json_array(const std::vector<double>& x) {
    std::ostringstream out;
    out.precision(10);
    out << "[";
    for (size_t i = 0; i < x.size(); ++i) out << (i ? ", " : "") << x[i];
    out << "]";
    return out.str();
}

// Runs the scene on the body; prints its record.
void run(const Scene& scene, std::unique_ptr<Body> body, const char* kind, int modes, double dt, double setup,
         bool first) {
    std::vector<double> normal, energy;
    double worst_balance = 0, scale = 0;
    std::string failure;
    const auto t0 = Clock::now();
    try {
        Simulation sim(std::move(body), scene.top0, 0, 0, sliding_inputs(0).foundation_velocity[0]);
        const double E0 = sim.observables().energy;
        scale = E0;
        const int steps = static_cast<int>(std::lround(scene.stop / scene.interval));
        for (int k = 0; k < steps; ++k) {
            sim.do_step(scene.interval, scene.inputs(k * scene.interval));
            const Observables& o = sim.observables();
            normal.push_back(o.normal_force);
            energy.push_back(o.energy);
            scale = std::max({scale, o.energy, std::abs(o.clamp_work)});
            worst_balance =
                std::max(worst_balance,
                         std::abs(o.energy - E0 -
                                  (o.clamp_work + o.normal_contact_work + o.friction_work - o.damping_work)));
        }
    } catch (const std::exception& e) {
        failure = e.what();
        for (char& c : failure)
            if (c == '"' || c == '\\' || c == '\n') c = '\'';
    }
    const double wall = seconds_since(t0);
    const double simulated = scene.interval * static_cast<double>(normal.size());
    std::printf(
        "%s\n  {\"scene\": \"%s\", \"body\": \"%s\", \"modes\": %d, \"dt\": %.6g, "
        "\"setup_s\": %.6g, \"wall_per_simulated_s\": %.6g, \"balance\": %.6g, "
        "\"failure\": \"%s\", \"normal_force\": %s, \"energy\": %s}",
        first ? "" : ",", scene.name, kind, modes, dt, setup, simulated > 0 ? wall / simulated : 0.0,
        scale > 0 ? worst_balance / scale : 0.0, failure.c_str(), json_array(normal).c_str(),
        json_array(energy).c_str());
}

}  // namespace

int main(int argc, char** argv) {
    if (argc < 5) {
        std::fprintf(stderr, "usage: bench_mass_carrying NX DT MODES FACTOR[,FACTOR...]\n");
        return 2;
    }
    const SceneParameters base = paper_scene(argv);
    const double dt = base.internal_step;
    const int modes = std::atoi(argv[3]);
    std::vector<double> factors;
    {
        std::stringstream in(argv[4]);
        std::string item;
        while (std::getline(in, item, ',')) factors.push_back(std::atof(item.c_str()));
    }
    Scene impact{"impact", base, 0.0, 1.5e-3, 1e-5, impact_inputs};
    impact.params.friction_coefficient = 0;
    impact.params.initial_gap = 1e-5;
    impact.params.initial_velocity[1] = -1.0;
    Scene sliding{"sliding", base, -2.5e-5, 5e-3, 1e-4, sliding_inputs};
    sliding.params.friction_coefficient = 0.3;
    sliding.params.damping_stiffness = 4e-6;

    std::printf("{\"nx\": %d, \"dt\": %.6g, \"modes\": %d, \"runs\": [", base.nx, dt, modes);
    bool first = true;
    for (const Scene& scene : {impact, sliding}) {
        SceneParameters p = scene.params;
        auto t0 = Clock::now();
        auto full = std::make_unique<Stepper>(p);
        run(scene, std::move(full), "full", 0, dt, seconds_since(t0), first);
        first = false;
        for (double factor : factors) {
            p.internal_step = dt * factor;
            t0 = Clock::now();
            auto massless = std::make_unique<ReducedStepper>(p, modes);
            run(scene, std::move(massless), "massless", modes, p.internal_step, seconds_since(t0), false);
            t0 = Clock::now();
            auto carrying = std::make_unique<CraigBamptonStepper>(p, modes);
            run(scene, std::move(carrying), "craig_bampton", modes, p.internal_step, seconds_since(t0),
                false);
        }
    }
    std::printf("]}\n");
    return 0;
}
