// The reduced body's two contact edges (issue 42: reduced_edge = massless against
// tangential_mass) beside the full body, one substep per step, on one scene of the paper's
// body at nx = ny = NX:
//   paper:   the paper's scene (F = 1.2, the top held at -2.5e-5 m, 20 m/s, the paper's state);
//   sliding: damped sliding from the static start (F = 0.3, beta = 4e-6 s, 20 m/s).
// For each variant, edge and mode count, against the full body at the same substep:
//   error_normal_force: relative L2 error of the substeps' normal force;
//   departure: the largest |v_x^{k+1} - (u_x^{k+1} - u_x^k) / dt| of a contact node, m/s (how
//     far the edge's end-of-step velocity is from its motion over the step);
//   perturbation: the largest change of the normal force (relative to its largest value) that
//     a 1e-14 relative change of the initial displacement makes;
//   us_per_substep: wall microseconds per substep; failure: the error of a step that failed.
// Prints one JSON object.
//   bench_reduced_edge NX DT STEPS SCENE VARIANT[,VARIANT...] MODES[,MODES...]
#include <cmath>
#include <cstdio>
#include <sstream>
#include <string>
#include <vector>

#include "bench_common.hpp"
#include "simulation/simulation.hpp"

using namespace contactbody;
using namespace bench;

namespace {

std::vector<int> integers(const char* list) {
    std::vector<int> out;
    std::stringstream in(list);
    std::string item;
    while (std::getline(in, item, ',')) out.push_back(std::atoi(item.c_str()));
    return out;
}

struct Run {
    std::vector<double> normal;
    double departure = 0, us_per_substep = 0;
    std::string failure;
};

Run simulate(const SceneParameters& p, int steps, double perturbation) {
    Run run;
    const double top = -2.5e-5;
    StepInputs in;
    in.foundation_velocity[0] = 20;
    in.top_displacement = top;
    try {
        Simulation sim(p, top, 0, 0, 0);
        if (perturbation != 0) {  // scale the initial displacement
            SimulationSnapshot snap = sim.snapshot();
            snap.state.u *= 1 + perturbation;
            sim.restore(snap);
        }
        const Discretization& d = sim.body().discretization();
        State before, after;
        const auto t0 = Clock::now();
        double measuring = 0;
        for (int k = 0; k < steps; ++k) {
            const auto m0 = Clock::now();
            sim.full_state(before);
            measuring += seconds_since(m0);
            sim.do_step(p.internal_step, in);
            run.normal.push_back(sim.observables().normal_force);
            const auto m1 = Clock::now();
            sim.full_state(after);
            for (size_t i = 0; i < d.contact_tangential[0].size(); ++i) {
                const int dof = d.free_dofs[static_cast<size_t>(d.contact_tangential[0][i])];
                const double mean = (after.u[dof] - before.u[dof]) / p.internal_step;
                run.departure = std::max(run.departure, std::abs(after.v[dof] - mean));
            }
            measuring += seconds_since(m1);
        }
        run.us_per_substep = 1e6 * (seconds_since(t0) - measuring) / steps;
    } catch (const std::exception& e) {
        run.failure = e.what();
        for (char& c : run.failure)
            if (c == '"' || c == '\\' || c == '\n') c = '\'';
        run.failure = run.failure.substr(0, 200);
    }
    return run;
}

double relative_l2(const std::vector<double>& x, const std::vector<double>& reference) {
    if (x.size() != reference.size()) return NAN;
    double e = 0, r = 0;
    for (size_t k = 0; k < x.size(); ++k)
        e += std::pow(x[k] - reference[k], 2), r += reference[k] * reference[k];
    return std::sqrt(e / r);
}

double largest_change(const std::vector<double>& x, const std::vector<double>& y) {
    if (x.size() != y.size()) return NAN;
    double change = 0, scale = 0;
    for (size_t k = 0; k < x.size(); ++k)
        change = std::max(change, std::abs(x[k] - y[k])), scale = std::max(scale, std::abs(x[k]));
    return change / scale;
}

void print(const char* edge, int variant, int modes, const Run& run, const Run& perturbed, const Run& full,
           bool first) {
    std::printf(
        "%s\n  {\"variant\": %d, \"edge\": \"%s\", \"modes\": %d, \"error_normal_force\": %.6g, "
        "\"departure\": %.6g, \"perturbation\": %.6g, \"us_per_substep\": %.6g, "
        "\"failure\": \"%s\"}",
        first ? "" : ",", variant, edge, modes, modes == 0 ? 0.0 : relative_l2(run.normal, full.normal),
        run.departure, largest_change(run.normal, perturbed.normal), run.us_per_substep, run.failure.c_str());
}

}  // namespace

int main(int argc, char** argv) {
    if (argc < 7) {
        std::fprintf(stderr, "usage: bench_reduced_edge NX DT STEPS SCENE VARIANT[,..] MODES[,..]\n");
        return 2;
    }
    SceneParameters base = paper_scene(argv);
    const int steps = std::atoi(argv[3]);
    const std::string scene = argv[4];
    if (scene == "sliding") {
        base.friction_coefficient = 0.3;
        base.damping_stiffness = 4e-6;
        base.static_initial_state = true;
    } else if (scene != "paper") {
        std::fprintf(stderr, "scene: paper or sliding\n");
        return 2;
    }
    std::printf("{\"nx\": %d, \"dt\": %.6g, \"steps\": %d, \"scene\": \"%s\", \"runs\": [", base.nx,
                base.internal_step, steps, scene.c_str());
    bool first = true;
    for (int variant : integers(argv[5])) {
        SceneParameters p = base;
        p.mass_matrix = static_cast<MassVariant>(variant);
        const Run full = simulate(p, steps, 0), full_perturbed = simulate(p, steps, 1e-14);
        print("full", variant, 0, full, full_perturbed, full, first);
        first = false;
        for (ReducedEdge edge : {ReducedEdge::massless, ReducedEdge::tangential_mass}) {
            if (edge == ReducedEdge::tangential_mass && p.mass_matrix == MassVariant::redistributed_both)
                continue;
            for (int modes : integers(argv[6])) {
                SceneParameters r = p;
                r.modes = modes;
                r.reduced_edge = edge;
                const Run run = simulate(r, steps, 0), perturbed = simulate(r, steps, 1e-14);
                print(edge == ReducedEdge::massless ? "massless" : "tangential_mass", variant, modes, run,
                      perturbed, full, false);
            }
        }
    }
    std::printf("]}\n");
    return 0;
}
