// An experiment: can a preconditioned iterative solve, warm-started from the
// previous substep, beat the sparse direct solve (the floor) at large n?
// It runs the paper scene and, at every substep, solves the same linear system the stepper's
// solve ends on, K u^{k+1/2} = b with b = K u^{k+1/2} (free dofs, contact forces included), by
//   - the stepper's own factor (TrailingCholesky: one forward + one backward solve),
//   - Eigen's ConjugateGradient with a Jacobi or an incomplete-Cholesky preconditioner, started
//     from the predictor u^k + dt/2 v^k, at several relative-residual tolerances,
// and reports time per solve, CG iterations and the error against u^{k+1/2}.
// An iterative substep cannot use the factor's trailing block for the contact correction, and
// keeping K^-1 B^T dense is n x 2 n_c memory; so it needs two solves: u0 = K^-1 (b - B^T lambda)
// and the correction d = K^-1 B^T lambda, each warm-started (d from the previous substep's).
// "jacobi_two_solves" times that pair. Prints JSON.
//   bench_iterative NX DT SUBSTEPS [MASS_MATRIX]
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include <Eigen/IterativeLinearSolvers>

#include "bench_common.hpp"
#include "body/stepper.hpp"
#include "linalg/trailing_cholesky.hpp"

using namespace contactbody;
using namespace bench;

namespace {

struct Tally {
    std::string method;
    double tolerance = 0, seconds = 0, setup = 0, max_error = 0;
    long iterations = 0, solves = 0;
};

void gather(const Discretization& d, const Eigen::VectorXd& all, Eigen::VectorXd& free) {
    for (size_t k = 0; k < d.free_dofs.size(); ++k) free[k] = all[d.free_dofs[k]];
}

template <class Solver>
void run_cg(Solver& cg, Tally& t, const Eigen::VectorXd& b, const Eigen::VectorXd& guess,
            const Eigen::VectorXd& exact, Eigen::VectorXd& x) {
    const auto t0 = Clock::now();
    x = cg.solveWithGuess(b, guess);
    t.seconds += seconds_since(t0);
    t.iterations += cg.iterations();
    ++t.solves;
    t.max_error = std::max(t.max_error, (x - exact).norm() / exact.norm());
}
}  // namespace

int main(int argc, char** argv) {
    if (argc < 4) {
        std::fprintf(stderr, "usage: bench_iterative NX DT SUBSTEPS [MASS_MATRIX]\n");
        return 2;
    }
    SceneParameters p = paper_scene(argv);
    const double dt = p.internal_step;
    const int substeps = std::atoi(argv[3]);
    if (argc > 4) p.mass_matrix = static_cast<MassVariant>(std::atoi(argv[4]));
    const double top = -2.5e-5;

    Stepper stepper(p);
    const Discretization& d = stepper.discretization();
    State s = stepper.initial_state(top);
    const SubstepLoad load{top, top, 0, 20};
    const SparseMatrix K = (4.0 / (dt * dt)) * d.M_free + d.A_free;
    const Eigen::Index n = K.rows();

    TrailingCholesky direct(K, d.contact_unknowns());
    Tally direct_tally{"cholmod_trailing_factor", 0};

    const std::vector<double> tolerances = {1e-6, 1e-8, 1e-10};
    Eigen::ConjugateGradient<SparseMatrix, Eigen::Lower | Eigen::Upper, Eigen::DiagonalPreconditioner<double>>
        jacobi;
    Eigen::ConjugateGradient<SparseMatrix, Eigen::Lower | Eigen::Upper, Eigen::IncompleteCholesky<double>>
        ichol;
    std::vector<Tally> tallies;
    auto t0 = Clock::now();
    jacobi.compute(K);
    const double jacobi_setup = seconds_since(t0);
    t0 = Clock::now();
    ichol.compute(K);
    const double ichol_setup = seconds_since(t0);
    if (ichol.info() != Eigen::Success) {
        std::fprintf(stderr, "bench_iterative: incomplete Cholesky failed\n");
        return 1;
    }
    for (double tol : tolerances) {
        tallies.push_back({"cg_jacobi", tol, 0, jacobi_setup});
        tallies.push_back({"cg_incomplete_cholesky", tol, 0, ichol_setup});
    }
    for (double tol : tolerances) tallies.push_back({"jacobi_two_solves", tol, 0, jacobi_setup});
    const std::vector<int> contact = d.contact_unknowns();
    std::vector<Eigen::VectorXd> correction(tolerances.size(), Eigen::VectorXd::Zero(n));
    Eigen::VectorXd contact_force(n), b0(n), x0(n), x1(n);

    Eigen::VectorXd u_old(n), v_old(n), u_new(n), exact(n), b(n), guess(n), x(n);
    stepper.substep(s, dt, load);  // factor + first substep, not timed
    for (int k = 0; k < substeps; ++k) {
        gather(d, s.u, u_old);
        gather(d, s.v, v_old);
        stepper.substep(s, dt, load);
        gather(d, s.u, u_new);
        exact = 0.5 * (u_old + u_new);
        b = K * exact;
        guess = u_old + 0.5 * dt * v_old;  // the predictor, known before the solve

        t0 = Clock::now();
        direct.solve(b, x);
        direct_tally.seconds += seconds_since(t0);
        ++direct_tally.solves;
        direct_tally.max_error = std::max(direct_tally.max_error, (x - exact).norm() / exact.norm());

        for (size_t i = 0; i < tolerances.size(); ++i) {
            jacobi.setTolerance(tolerances[i]);
            ichol.setTolerance(tolerances[i]);
            run_cg(jacobi, tallies[2 * i], b, guess, exact, x);
            run_cg(ichol, tallies[2 * i + 1], b, guess, exact, x);
        }
        // The contact forces of this substep on the free dofs (B^T lambda, any fixed sign).
        contact_force.setZero();
        for (Eigen::Index c = 0; c < s.lambda.size(); ++c) contact_force[contact[c]] = s.lambda[c];
        b0 = b - contact_force;
        for (size_t i = 0; i < tolerances.size(); ++i) {
            Tally& t = tallies[2 * tolerances.size() + i];
            jacobi.setTolerance(tolerances[i]);
            const auto start = Clock::now();
            x0 = jacobi.solveWithGuess(b0, guess - correction[i]);
            t.iterations += jacobi.iterations();
            x1 = jacobi.solveWithGuess(contact_force, correction[i]);
            t.iterations += jacobi.iterations();
            correction[i] = x1;
            x = x0 + x1;
            t.seconds += seconds_since(start);
            ++t.solves;
            t.max_error = std::max(t.max_error, (x - exact).norm() / exact.norm());
        }
    }
    std::printf(
        "{\"nx\": %d, \"dt\": %g, \"unknowns\": %ld, \"substeps\": %d, "
        "\"factor_nonzeros\": %.0f, \"K_nonzeros\": %ld, \"direct_solve\": %.6e, "
        "\"direct_max_error\": %.3e, \"iterative\": [",
        p.nx, dt, static_cast<long>(n), substeps, direct.factor_nonzeros(), static_cast<long>(K.nonZeros()),
        direct_tally.seconds / direct_tally.solves, direct_tally.max_error);
    for (size_t i = 0; i < tallies.size(); ++i) {
        const Tally& t = tallies[i];
        std::printf(
            "%s{\"method\": \"%s\", \"tolerance\": %g, \"per_solve\": %.6e, "
            "\"setup\": %.4f, \"iterations\": %.2f, \"max_error\": %.3e, "
            "\"ratio_to_direct\": %.3f}",
            i ? ", " : "", t.method.c_str(), t.tolerance, t.seconds / t.solves, t.setup,
            double(t.iterations) / t.solves, t.max_error,
            (t.seconds / t.solves) / (direct_tally.seconds / direct_tally.solves));
    }
    std::printf("]}\n");
    return 0;
}
