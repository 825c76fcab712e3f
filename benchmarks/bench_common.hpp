// What the benchmark programs share: the clock, peak memory, the paper scene from the command
// line (NX DT, the scene's substep size), a body's K and a solve's mean time.
#pragma once

#include <chrono>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <string>

#include "assembly/discretization.hpp"

namespace bench {

using Clock = std::chrono::steady_clock;

inline double seconds_since(Clock::time_point t) {
    return std::chrono::duration<double>(Clock::now() - t).count();
}

// Peak resident memory of this process image in MB (VmHWM; ru_maxrss would include the
// parent's peak, which survives execve).
inline double peak_rss_mb() {
    std::ifstream status("/proc/self/status");
    std::string key;
    double kb = 0;
    while (status >> key) {
        if (key == "VmHWM:") {
            status >> kb;
            break;
        }
    }
    return kb / 1024.0;
}

// The paper scene with nx = ny = NX (argv[1]) and substep DT (argv[2]).
inline contactbody::SceneParameters paper_scene(char** argv) {
    contactbody::SceneParameters p;
    p.nx = p.ny = std::atoi(argv[1]);
    p.internal_step = std::atof(argv[2]);
    return p;
}

// K = A + 4/dt^2 M on the free dofs of a body (the sparse contact solve's, dt = 1e-6 s, the
// contact_scaling scenes' substep): BODY a Gmsh file or rect:NX (the paper's rectangle with
// nx = ny = NX), DIMENSION its dimension.
inline contactbody::SparseMatrix body_stiffness(const char* body, int dimension) {
    contactbody::SceneParameters p;
    if (std::strncmp(body, "rect:", 5) == 0)
        p.nx = p.ny = std::atoi(body + 5);
    else
        p.mesh = body;
    p.dimension = dimension;
    p.friction_coefficient = 0;
    const contactbody::Discretization d = contactbody::discretize(p);
    const double dt = 1e-6;
    contactbody::SparseMatrix K = d.A_free + (4 / (dt * dt)) * d.M_free;
    K.makeCompressed();
    return K;
}

// The mean seconds of `count` solves of `factor` (after one untimed), its solution in x.
template <class Factor>
double mean_solve_seconds(Factor& factor, const Eigen::VectorXd& b, Eigen::VectorXd& x, int count) {
    factor.solve(b, x);
    const auto t = Clock::now();
    for (int k = 0; k < count; ++k) factor.solve(b, x);
    return seconds_since(t) / count;
}

}  // namespace bench
