// The 2D condensed contact solve's two Newton methods on one scene: the reduced system
// (ContactSolverOptions::reduced_newton, the default: open nodes and slipping nodes' tangential
// unknowns eliminated, its LU reused and updated while the node states hold) against the full
// generalized Jacobian that a 3D body's isotropic friction takes (open nodes eliminated, an LU
// every iteration). Damped sliding from the static start (the paper's body, the foundation at
// VELOCITY, the top held), the condensed solve on both. Two simulations step side by side, in
// ROUNDS alternating rounds of STEPS substeps; per method: the rounds' median wall µs per substep,
// Newton iterations, Newton matrices factored, Gauss-Seidel sweeps and refinements per substep,
// and the two runs' largest difference in normal force, friction force and energy after any
// substep, relative to that output's largest size. Prints one JSON object.
//   bench_reduced_newton NX MODES DT STEPS ROUNDS F VELOCITY [STATIC_RATIO STRIBECK_VELOCITY]
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <vector>

#include "bench_common.hpp"
#include "body/stepper.hpp"
#include "reduced/reduced_stepper.hpp"
#include "simulation/simulation.hpp"

using namespace contactbody;
using namespace bench;

namespace {

double median(std::vector<double> x) {
    std::nth_element(x.begin(), x.begin() + x.size() / 2, x.end());
    return x[x.size() / 2];
}

std::unique_ptr<Simulation> make(const SceneParameters& p, double top, bool reduced_newton) {
    std::unique_ptr<Body> body;
    if (p.modes == 0) {
        auto s = std::make_unique<Stepper>(p);
        s->set_contact_path(Stepper::ContactPath::condensed);
        body = std::move(s);
    } else {
        body = std::make_unique<ReducedStepper>(p, p.modes);
    }
    body->contact_options().reduced_newton = reduced_newton;
    return std::make_unique<Simulation>(std::move(body), top);
}

struct Run {
    std::unique_ptr<Simulation> sim;
    std::vector<double> us;
    long iterations = 0, sweeps = 0, refinements = 0, substeps = 0;
    std::vector<double> normal, friction, energy;
};

}  // namespace

int main(int argc, char** argv) {
    if (argc < 8) {
        std::fprintf(stderr,
                     "usage: bench_reduced_newton NX MODES DT STEPS ROUNDS F VELOCITY "
                     "[STATIC_RATIO STRIBECK_VELOCITY]\n");
        return 2;
    }
    SceneParameters p;
    p.nx = p.ny = std::atoi(argv[1]);
    p.modes = std::atoi(argv[2]);
    p.internal_step = std::atof(argv[3]);
    const int steps = std::atoi(argv[4]), rounds = std::atoi(argv[5]);
    p.friction_coefficient = std::atof(argv[6]);
    const double velocity = std::atof(argv[7]);
    if (argc > 9) {
        p.static_friction_ratio = std::atof(argv[8]);
        p.stribeck_velocity = std::atof(argv[9]);
    }
    p.damping_stiffness = 4e-6;
    p.static_initial_state = true;
    const double top = -2.5e-5;
    StepInputs in;
    in.foundation_velocity[0] = velocity;
    in.top_displacement = top;
    Run runs[2];
    long factorizations0[2];
    for (int m = 0; m < 2; ++m) {
        runs[m].sim = make(p, top, m == 0);
        runs[m].sim->do_step(p.internal_step, in);  // factors what the others reuse
        factorizations0[m] = runs[m].sim->body().contact_solver().factorizations();
    }
    for (int round = 0; round < rounds; ++round) {
        for (Run& r : runs) {
            double seconds = 0;
            for (int k = 0; k < steps; ++k) {
                const auto t0 = Clock::now();
                r.sim->do_step(p.internal_step, in);
                seconds += seconds_since(t0);
                const StepStatistics& s = r.sim->statistics();
                r.iterations += s.contact_iterations;
                r.sweeps += s.gauss_seidel_sweeps;
                r.refinements += s.refinements;
                ++r.substeps;
                const Observables& o = r.sim->observables();
                r.normal.push_back(o.normal_force);
                r.friction.push_back(o.friction_force[0]);
                r.energy.push_back(o.energy);
            }
            r.us.push_back(seconds / steps * 1e6);
        }
    }
    const auto difference = [](const std::vector<double>& a, const std::vector<double>& b) {
        double scale = 0, d = 0;
        for (size_t k = 0; k < a.size(); ++k) {
            scale = std::max({scale, std::abs(a[k]), std::abs(b[k])});
            d = std::max(d, std::abs(a[k] - b[k]));
        }
        return scale > 0 ? d / scale : d;
    };
    std::printf(
        "{\"nx\": %d, \"modes\": %d, \"dt\": %.6g, \"friction_coefficient\": %.6g, "
        "\"velocity\": %.6g, \"static_friction_ratio\": %.6g, \"stribeck_velocity\": %.6g, "
        "\"contact_nodes\": %d, "
        "\"substeps\": %ld, \"methods\": {",
        p.nx, p.modes, p.internal_step, p.friction_coefficient, velocity, p.static_friction_ratio,
        p.stribeck_velocity, runs[0].sim->body().num_contact_nodes(), runs[0].substeps);
    for (int m = 0; m < 2; ++m) {
        const Run& r = runs[m];
        const double n = static_cast<double>(r.substeps);
        const long factorizations = r.sim->body().contact_solver().factorizations() - factorizations0[m];
        std::printf(
            "%s\"%s\": {\"substep_us\": %.6g, \"newton_iterations\": %.6g, "
            "\"factorizations\": %.6g, \"sweeps\": %.6g, \"refinements\": %.6g, "
            "\"active_nodes\": %d, \"slipping_nodes\": %d}",
            m ? ", " : "", m == 0 ? "reduced" : "full_jacobian", median(r.us), r.iterations / n,
            factorizations / n, r.sweeps / n, r.refinements / n, r.sim->observables().active_contact_nodes,
            r.sim->observables().slipping_contact_nodes);
    }
    std::printf("}, \"difference\": {\"normal_force\": %.3g, \"friction_force\": %.3g, \"energy\": %.3g}}\n",
                difference(runs[0].normal, runs[1].normal), difference(runs[0].friction, runs[1].friction),
                difference(runs[0].energy, runs[1].energy));
    return 0;
}
