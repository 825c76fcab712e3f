// One case of benchmarks/cattaneo3d.py: a 3D mesh body pressed by the static start (with
// friction), then the foundation creeping along x. Prints one JSON object: per communication
// step, the time, the normal and friction forces, and the contact nodes' states (0 open,
// 1 stick, 2 slip); once, the contact nodes' x, z and shares.
//   bench_cattaneo3d MESH TOP F SPEED STOP INTERVAL SUBSTEP BETA LAMBDA MU [FRICTIONLESS_LOAD]
// FRICTIONLESS_LOAD 1: the static start at F = 0, then F before the first step (as the 2D
// benchmark's frictionless normal load).
#include <cstdio>
#include <cstdlib>
#include <string>

#include "bench_common.hpp"
#include "simulation/simulation.hpp"

using namespace contactbody;
using namespace bench;

int main(int argc, char** argv) {
    if (argc < 11) {
        std::fprintf(stderr,
                     "usage: bench_cattaneo3d MESH TOP F SPEED STOP INTERVAL SUBSTEP BETA LAMBDA MU\n");
        return 2;
    }
    SceneParameters p;
    p.mesh = argv[1];
    p.dimension = 3;
    const double top = std::atof(argv[2]);
    p.friction_coefficient = std::atof(argv[3]);
    const double speed = std::atof(argv[4]), stop = std::atof(argv[5]), interval = std::atof(argv[6]);
    p.internal_step = std::atof(argv[7]);
    p.damping_stiffness = std::atof(argv[8]);
    p.lambda = std::atof(argv[9]);
    p.mu = std::atof(argv[10]);
    // Contact at the end of the step (variant 4): the node states are those of u^{k+1}, as
    // the 2D benchmark takes them (benchmarks/cattaneo_mindlin.py).
    p.mass_matrix = MassVariant::redistributed_implicit_contact;
    p.static_initial_state = true;
    const bool frictionless_load = argc > 11 && std::atoi(argv[11]) != 0;
    const double F = p.friction_coefficient;
    if (frictionless_load) p.friction_coefficient = 0;
    try {
        const auto t0 = Clock::now();
        Simulation sim(p, top);
        if (frictionless_load) sim.set_friction_coefficient(F);
        const Mesh& mesh = sim.body().discretization().mesh;
        const size_t nc = mesh.contact_nodes.size();
        std::printf("{\"contact_nodes\": %zu, \"start_seconds\": %.4g", nc, seconds_since(t0));
        const char* names[] = {"x", "z", "share"};
        for (int k = 0; k < 3; ++k) {
            std::printf(", \"%s\": [", names[k]);
            for (size_t i = 0; i < nc; ++i) {
                const Point& q = mesh.point(mesh.contact_nodes[i]);
                std::printf("%s%.17g", i ? ", " : "", k == 0 ? q.x : k == 1 ? q.z : mesh.contact_shares[i]);
            }
            std::printf("]");
        }
        StepInputs in;
        in.top_displacement = top;
        in.foundation_velocity[0] = speed;
        std::printf(", \"records\": [");
        const auto t1 = Clock::now();
        const int steps = static_cast<int>(stop / interval + 0.5);
        for (int k = 0; k < steps; ++k) {
            sim.do_step(interval, in);
            const Observables& o = sim.observables();
            std::printf("%s{\"t\": %.9g, \"P\": %.17g, \"Q\": %.17g, \"state\": [", k ? ", " : "", sim.time(),
                        o.normal_force, o.friction_force[0]);
            for (Eigen::Index i = 0; i < sim.edge().state.size(); ++i)
                std::printf("%s%d", i ? "," : "", static_cast<int>(sim.edge().state[i]));
            std::printf("]}");
        }
        std::printf("], \"run_seconds\": %.4g, \"peak_mb\": %.1f}\n", seconds_since(t1), peak_rss_mb());
    } catch (const std::exception& e) {
        std::fprintf(stderr, "bench_cattaneo3d: %s\n", e.what());
        return 1;
    }
    return 0;
}
