// One case of benchmarks/contact_scaling.py: a mesh body sliding from the static start, its
// contact solved by the path asked for. Prints one JSON object: the static start's and one
// substep's wall time (the mean over SUBSTEPS after the first step), one sparse solve of the
// same body (K in its fill-reducing order, the floor of a substep: the run's own factor),
// timed beside the substeps (as many solves after each communication step as it had
// substeps, so that both see the same machine: the ratio is what this run measured, on a
// machine whose speed drifts between runs), that factor's flops, nonzeros and kernel, the
// solve's counts (held solves over the timed substeps too), what the static start's parts
// cost (its load path's body, its load paths, their held solves and refactorizations) and the
// peak memory.
//   bench_contact_scaling MESH|rect:NX MODES PATH(automatic|condensed|sparse|sparse_gcr) [SUBSTEPS] [F]
//                         [DIMENSION [TOP [GAP [STEP [SAVE [BETA]]]]]]
// DIMENSION 3 takes a tetrahedral mesh; TOP is the clamp's displacement (-5e-6 m), GAP the
// initial gap (0; a large one lifts the body), STEP the communication step (1e-5 s); SAVE 1
// saves a state before each step (untimed), as an importer that can go back a step does:
// what the contact solve keeps from step to step goes at each (Body::forget_kept); BETA the
// stiffness-proportional damping (4e-6 s; 0: undamped).
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>

#include "bench_common.hpp"
#include "linalg/trailing_cholesky.hpp"
#include "simulation/simulation.hpp"

using namespace contactbody;
using namespace bench;

int main(int argc, char** argv) {
    if (argc < 4) {
        std::fprintf(stderr, "usage: bench_contact_scaling MESH MODES PATH [SUBSTEPS]\n");
        return 2;
    }
    SceneParameters p;  // contact_scaling.py's SCENE
    // MESH: a Gmsh file, or rect:NX for the paper's rectangle with nx = ny = NX.
    if (std::strncmp(argv[1], "rect:", 5) == 0)
        p.nx = p.ny = std::atoi(argv[1] + 5);
    else
        p.mesh = argv[1];
    p.modes = std::atoi(argv[2]);
    p.friction_coefficient = 0.3;
    p.damping_stiffness = argc > 11 ? std::atof(argv[11]) : 4e-6;
    p.internal_step = 1e-6;
    p.static_initial_state = true;
    if (argc > 6) p.dimension = std::atoi(argv[6]);
    const double top = argc > 7 ? std::atof(argv[7]) : -5e-6, velocity = 20;
    const double step = argc > 9 ? std::atof(argv[9]) : 1e-5;
    const bool save = argc > 10 && std::atoi(argv[10]) != 0;
    if (argc > 8) p.initial_gap = std::atof(argv[8]);
    const int substeps = argc > 4 ? std::atoi(argv[4]) : 30;
    if (argc > 5) p.friction_coefficient = std::atof(argv[5]);
    auto t0 = Clock::now();
    Stepper* stepper = nullptr;
    Simulation sim(body_on_path(p, argv[3], &stepper), top);
    const double start = seconds_since(t0);
    StepInputs in;
    in.foundation_velocity[0] = velocity;
    in.top_displacement = top;
    sim.do_step(step, in);  // factors what the others reuse
    // The floor: one solve with K's factor in its fill-reducing order. The full body's is its own
    // factor (the sparse contact solve's, its held set's rows the identity's: the same
    // cost); the reduced body's K is factored beside it with the kernel the full body's would
    // take (TrailingCholesky's rule).
    const Discretization& d = sim.body().discretization();
    const double dt = p.internal_step;
    const SparseMatrix K = (4.0 / (dt * dt)) * d.M_free + d.A_free + (2.0 / dt) * d.C_free;
    std::unique_ptr<TrailingCholesky> reduced_floor;
    if (!stepper) reduced_floor = std::make_unique<TrailingCholesky>(K, std::vector<int>{}, true);
    TrailingCholesky& factor = stepper ? stepper->last_factor() : *reduced_floor;
    Eigen::VectorXd b = Eigen::VectorXd::Random(K.rows()), x(K.rows());
    factor.solve(b, x);
    const int per_step = static_cast<int>(std::lround(step / p.internal_step));
    const int steps = std::max(1, substeps / per_step);
    const long solves_before = stepper ? stepper->sparse_solver().solves() : 0L;
    int iterations = 0;
    double stepping = 0, solving = 0;
    for (int k = 0; k < steps; ++k) {
        if (save) sim.snapshot();
        t0 = Clock::now();
        sim.do_step(step, in);
        stepping += seconds_since(t0);
        iterations += sim.statistics().contact_iterations;
        t0 = Clock::now();
        for (int j = 0; j < per_step; ++j) factor.solve(b, x);
        solving += seconds_since(t0);
    }
    const double substep = stepping / (steps * per_step), solve = solving / (steps * per_step);
    const Observables o = sim.observables();
    const int contact_nodes = sim.body().num_contact_nodes();
    const bool sparse = stepper && stepper->sparse_contact();
    const long held_solves = stepper ? stepper->sparse_solver().solves() : 0L;
    const double held_solves_per_substep =
        static_cast<double>(held_solves - solves_before) / (steps * per_step);
    const long krylov_iterations = stepper ? stepper->sparse_solver().krylov_iterations() : 0L;
    const long gcr_rounds = stepper ? stepper->sparse_solver().gcr_rounds() : 0L;
    const long held_refactorizations = stepper ? stepper->sparse_refactorizations() : 0L;
    const double held_refactored_work = stepper ? stepper->sparse_refactored_work() : 0.0;
    const double peak_memory = peak_rss_mb();
    std::printf(
        "{\"contact_nodes\": %d, \"unknowns\": %ld, \"modes\": %d, \"sparse\": %s, "
        "\"static_start_seconds\": %.6g, \"substep_seconds\": %.6g, "
        "\"sparse_solve_seconds\": %.6g, \"substep_per_solve\": %.4g, "
        "\"newton_iterations_per_substep\": %.4g, \"held_solves\": %ld, "
        "\"held_solves_per_substep\": %.4g, "
        "\"krylov_iterations\": %ld, \"gcr_rounds\": %ld, \"held_refactorizations\": %ld, "
        "\"held_refactored_work\": %.4g, "
        "\"normal_force\": %.17g, \"kinetic_energy\": %.17g, \"strain_energy\": %.17g, "
        "\"peak_memory_mb\": %.1f, \"factor_flops\": %.6g, \"factor_nonzeros\": %.6g, "
        "\"factor_kernel\": \"%s\", \"static_start_body_seconds\": %.6g, "
        "\"static_start_path_seconds\": %.6g, \"static_start_held_solves\": %ld, "
        "\"static_start_refactorizations\": %ld}\n",
        contact_nodes, static_cast<long>(K.rows()), p.modes, sparse ? "true" : "false", start, substep, solve,
        substep / solve, static_cast<double>(iterations) / (steps * per_step), held_solves,
        held_solves_per_substep, krylov_iterations, gcr_rounds, held_refactorizations, held_refactored_work,
        o.normal_force, o.kinetic_energy, o.strain_energy, peak_memory, factor.factor_flops(),
        factor.factor_nonzeros(),
        factor.kernel() == TrailingCholesky::Kernel::supernodal      ? "supernodal"
        : factor.kernel() == TrailingCholesky::Kernel::supernodal_lu ? "supernodal_lu"
                                                                     : "simplicial",
        sim.static_start_cost().path_body_seconds, sim.static_start_cost().path_seconds,
        sim.static_start_cost().held_solves, sim.static_start_cost().refactorizations);
}
