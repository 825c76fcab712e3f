// Cost of one midpoint substep on the paper scene against its floor, one bare sparse solve
// with the same Cholesky factor, measured in the same run. Prints one JSON object.
//   bench_substep NX DT SUBSTEPS [FRICTION] [MASS_MATRIX] [TOP_DISPLACEMENT] [BETA] [ALPHA]
#include <cstdio>
#include <cstdlib>
#include <string>

#include <Eigen/CholmodSupport>

#include "bench_common.hpp"
#include "linalg/trailing_cholesky.hpp"
#include "simulation/simulation.hpp"

using namespace contactbody;
using namespace bench;

int main(int argc, char** argv) {
    if (argc < 4) {
        std::fprintf(stderr,
                     "usage: bench_substep NX DT SUBSTEPS [FRICTION] [MASS_MATRIX] [TOP] [BETA] [ALPHA]\n");
        return 2;
    }
    SceneParameters p = paper_scene(argv);
    const double dt = p.internal_step;
    const int substeps = std::atoi(argv[3]);
    if (argc > 4) p.friction_coefficient = std::atof(argv[4]);
    if (argc > 5) p.mass_matrix = static_cast<MassVariant>(std::atoi(argv[5]));
    const double top = argc > 6 ? std::atof(argv[6]) : -2.5e-5;  // > 0 lifts the body off
    if (argc > 7) p.damping_stiffness = std::atof(argv[7]);      // Rayleigh damping C = alpha M + beta A
    if (argc > 8) p.damping_mass = std::atof(argv[8]);

    auto t0 = Clock::now();
    Stepper stepper(p);
    const double setup_assembly = seconds_since(t0);
    State s = stepper.initial_state(top);
    const SubstepLoad load{top, top, 0, 20};

    stepper.enable_timing(true);
    stepper.substep(s, dt, load);  // factorization + Delassus, then one substep
    const double setup_factor = stepper.timings().factor;
    const SubstepTimings first = stepper.timings();

    // The floor: one solve (forward + backward) with the same factor; and, to show what the
    // constrained ordering costs, one solve with CHOLMOD's own unconstrained choice.
    const Discretization& d = stepper.discretization();
    SparseMatrix K = (4.0 / (dt * dt)) * d.M_free + d.A_free;
    if (p.damped()) K += (2.0 / dt) * d.C_free;
    TrailingCholesky factor(K, d.contact_unknowns());
    Eigen::CholmodDecomposition<SparseMatrix, Eigen::Lower> unconstrained(K);
    Eigen::VectorXd rhs = Eigen::VectorXd::Random(K.rows()), x(K.rows());
    x = unconstrained.solve(rhs);  // first-call workspace allocation is not timed
    factor.solve(rhs, x);

    // Substeps and bare solves alternate in blocks, so that a drift of the (shared, noisy)
    // machine during the run weighs on both sides of the ratio alike.
    const int blocks = std::min(10, substeps);
    long iterations = 0, solves = 0;
    double substep_seconds = 0, floor_seconds = 0;
    const long newton_factors_before = stepper.contact_solver().factorizations();
    for (int block = 0; block < blocks; ++block) {
        const int count = substeps / blocks + (block < substeps % blocks ? 1 : 0);
        t0 = Clock::now();
        for (int k = 0; k < count; ++k) {
            const SubstepReport r = stepper.substep(s, dt, load);
            iterations += r.contact_iterations;
            solves += r.contact_solved;
        }
        substep_seconds += seconds_since(t0);
        t0 = Clock::now();
        for (int k = 0; k < count; ++k) {
            factor.solve(rhs, x);
            rhs[k % rhs.size()] += 1e-3 * x[0];  // the right-hand side changes every time
        }
        floor_seconds += seconds_since(t0);
    }
    const double per_substep = substep_seconds / substeps;
    const double floor = floor_seconds / substeps;
    const double newton_factors =
        double(stepper.contact_solver().factorizations() - newton_factors_before) / substeps;
    SubstepTimings t = stepper.timings();
    t.solve -= first.solve;
    t.contact -= first.contact;
    t.update -= first.update;

    const int bare = std::max(50, std::min(substeps / 2, 2000));
    t0 = Clock::now();
    for (int k = 0; k < bare; ++k) {
        x = unconstrained.solve(rhs);
        rhs[k % rhs.size()] += 1e-3 * x[0];
    }
    const double floor_unconstrained = seconds_since(t0) / bare;

    // Energies are computed only when an output asks for them: what one evaluation costs
    // (each do_step of one substep makes the next observables() call recompute them).
    Simulation sim(p, top);
    const StepInputs inputs{{20, 0}, {0, 0}, top, 0};
    double energy_seconds = 0, e = 0;
    const int evaluations = 50;
    for (int k = 0; k < evaluations; ++k) {
        sim.do_step(dt, inputs);
        t0 = Clock::now();
        e += sim.observables().energy;
        energy_seconds += seconds_since(t0);
    }
    std::printf(
        "{\"nx\": %d, \"dt\": %g, \"friction\": %g, \"mass_matrix\": %d, \"unknowns\": %zu, "
        "\"substeps\": %d, \"per_substep\": %.6e, \"floor_solve\": %.6e, \"ratio\": %.3f, "
        "\"split_solve\": %.6e, \"split_contact\": %.6e, \"split_update\": %.6e, "
        "\"contact_iterations\": %.3f, \"contact_solve_fraction\": %.3f, "
        "\"setup_assembly\": %.4f, \"setup_factor_delassus\": %.4f, \"peak_rss_mb\": %.1f, "
        "\"top_displacement\": %g, \"floor_unconstrained\": %.6e, \"factor_nonzeros\": %.0f, "
        "\"newton_factorizations\": %.3f, \"energy_evaluation\": %.6e}\n",
        p.nx, dt, p.friction_coefficient, static_cast<int>(p.mass_matrix), d.free_dofs.size(), substeps,
        per_substep, floor, per_substep / floor, t.solve / substeps, t.contact / substeps,
        t.update / substeps, double(iterations) / substeps, double(solves) / substeps, setup_assembly,
        setup_factor, peak_rss_mb(), top, floor_unconstrained, factor.factor_nonzeros(), newton_factors,
        energy_seconds / evaluations);
    return e > 0 ? 0 : 1;
}
