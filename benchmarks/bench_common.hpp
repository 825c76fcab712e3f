// What the benchmark programs share: the clock, peak memory, the paper scene from the command
// line (NX DT, the scene's substep size), a body's K and a solve's mean time.
#pragma once

#include <chrono>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <limits>
#include <memory>
#include <string>

#include "assembly/discretization.hpp"
#include "body/stepper.hpp"
#include "reduced/reduced_stepper.hpp"

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

// A contact path by its name on the command line: sparse, sparse_gcr, condensed, else automatic
// (body_on_path: automatic_narrow, automatic with GCR's kept directions at max_directions on
// every factor, the solve before the wide span; automatic_supernodal, with the supernodal factor
// whatever its flops; automatic_wide, that and the wide span on it).
inline contactbody::Stepper::ContactPath contact_path(const char* name) {
    using Path = contactbody::Stepper::ContactPath;
    return std::strcmp(name, "sparse") == 0       ? Path::sparse
           : std::strcmp(name, "sparse_gcr") == 0 ? Path::sparse_gcr
           : std::strcmp(name, "condensed") == 0  ? Path::condensed
                                                  : Path::automatic;
}

// The full body (modes = 0) on the contact path named, with *stepper set to it, or the reduced
// body (*stepper null).
inline std::unique_ptr<contactbody::Body> body_on_path(const contactbody::SceneParameters& p,
                                                       const char* path, contactbody::Stepper** stepper) {
    *stepper = nullptr;
    if (p.modes > 0) return std::make_unique<contactbody::ReducedStepper>(p, p.modes);
    auto s = std::make_unique<contactbody::Stepper>(p);
    s->set_contact_path(contact_path(path));
    if (std::strcmp(path, "automatic_narrow") == 0)
        s->contact_options().wide_span_nonzeros = std::numeric_limits<double>::infinity();
    if (std::strcmp(path, "automatic_supernodal") == 0) s->set_supernodal_factor(true);
    if (std::strcmp(path, "automatic_wide") == 0) {
        s->contact_options().wide_span_nonzeros = 0;
        s->set_supernodal_factor(true);
    }
    *stepper = s.get();
    return s;
}

}  // namespace bench
