// One case of benchmarks/hertz3d.py: a 3D mesh body (tetrahedra) pressed onto the foundation
// by the static start under a clamp displacement, F = 0. Prints one JSON object: the measured
// load P (N), the contact nodes' positions in the foundation's plane and their pressures (the
// static start's multipliers over each node's share of the foundation), the set-up's wall
// time, the sizes and the peak memory.
//   bench_hertz3d MESH TOP_DISPLACEMENT [LAMBDA MU]
#include <cstdio>
#include <cstdlib>
#include <string>

#include "bench_common.hpp"
#include "simulation/simulation.hpp"

using namespace contactbody;
using namespace bench;

int main(int argc, char** argv) {
    if (argc < 3) {
        std::fprintf(stderr, "usage: bench_hertz3d MESH TOP_DISPLACEMENT [LAMBDA MU]\n");
        return 2;
    }
    SceneParameters p;
    p.mesh = argv[1];
    p.dimension = 3;
    p.friction_coefficient = 0;
    p.static_initial_state = true;
    if (argc > 4) {
        p.lambda = std::atof(argv[3]);
        p.mu = std::atof(argv[4]);
    }
    const double top = std::atof(argv[2]);
    try {
        const auto t0 = Clock::now();
        Simulation sim(p, top);
        const double start = seconds_since(t0);
        const Mesh& mesh = sim.body().discretization().mesh;
        const EdgeSnapshot& edge = sim.edge();
        const Observables& o = sim.observables();
        const auto json_string = [](const std::string& text) {
            std::string out = "\"";
            for (char c : text) {
                if (c == '"' || c == '\\') out += '\\';
                out += c == '\n' ? ' ' : c;
            }
            return out + "\"";
        };
        const std::string summary = json_string(sim.body().summary());
        std::string notes = "[";  // what the discretization did that the log says (M_r's choice)
        for (const std::string& note : sim.body().discretization().mesh_notes)
            notes += (notes.size() > 1 ? ", " : "") + json_string(note);
        notes += "]";
        std::printf(
            "{\"nodes\": %d, \"contact_nodes\": %zu, \"start_seconds\": %.6g, "
            "\"peak_mb\": %.1f, \"load\": %.17g, \"top_reaction_y\": %.17g, \"contact_path\": %s, \"notes\": "
            "%s",
            mesh.num_nodes(), mesh.contact_nodes.size(), start, peak_rss_mb(), o.normal_force,
            o.top_reaction[1], summary.c_str(), notes.c_str());
        const char* names[] = {"x", "z", "height", "pressure", "share"};
        for (int k = 0; k < 5; ++k) {
            std::printf(", \"%s\": [", names[k]);
            for (size_t i = 0; i < mesh.contact_nodes.size(); ++i) {
                const Point& q = mesh.point(mesh.contact_nodes[i]);
                const double v = k == 0   ? q.x
                                 : k == 1 ? q.z
                                 : k == 2 ? mesh.contact_heights[i]
                                 : k == 3 ? edge.pressure[static_cast<Eigen::Index>(i)]
                                          : mesh.contact_shares[i];
                std::printf("%s%.17g", i ? ", " : "", v);
            }
            std::printf("]");
        }
        std::printf("}\n");
    } catch (const std::exception& e) {
        std::fprintf(stderr, "bench_hertz3d: %s\n", e.what());
        return 1;
    }
    return 0;
}
