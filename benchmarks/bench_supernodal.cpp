// The supernodal Cholesky (linalg/supernodal_cholesky.hpp) against the body's factor today
// (TrailingCholesky: CHOLMOD's simplicial Cholesky, or the supernodal LU of the same order) on
// one body's K, in the same order, in one run; and the machine's dense rate: Eigen's GEMM at
// n = 1000 on one thread. Prints one JSON object: unknowns, supernodes, nonzeros and flops of
// each factor, the seconds of a factorization (the best of REPEATS) and of a solve, the
// GFlop/s, and the solutions' largest difference; the supernodal Cholesky with its baseline
// kernels and with the fastest this CPU has; the peak memory.
// With WRITE_K=PREFIX in the environment it also writes K's lower triangle (PREFIX.mtx, Matrix
// Market) and CHOLMOD's order (PREFIX.perm: factor position -> unknown, a line each) for
// cholmod_supernodal.c.
//   bench_supernodal MESH|rect:NX DIMENSION [REPEATS [ONLY]]   (ONLY: supernodal, or fast)
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <string>

#include "bench_common.hpp"
#include "linalg/supernodal_cholesky.hpp"
#include "linalg/trailing_cholesky.hpp"

using namespace contactbody;
using namespace bench;

int main(int argc, char** argv) {
    if (argc < 3) {
        std::fprintf(stderr, "usage: bench_supernodal MESH|rect:NX DIMENSION [REPEATS]\n");
        return 2;
    }
    const SparseMatrix K = body_stiffness(argv[1], std::atoi(argv[2]));
    const int repeats = argc > 3 ? std::atoi(argv[3]) : 3;
    // ONLY = supernodal: the supernodal Cholesky alone (CHOLMOD's order), for bodies where
    // today's factors take tens of minutes.
    // ONLY = fast: that, and of it the fast kernels on one thread alone (for perf).
    const bool only_fast = argc > 4 && std::strcmp(argv[4], "fast") == 0;
    const bool only_supernodal = only_fast || (argc > 4 && std::strcmp(argv[4], "supernodal") == 0);
    const SparseMatrix lower = K.triangularView<Eigen::Lower>();
    const Eigen::VectorXd b = Eigen::VectorXd::Random(K.rows());
    // The machine's dense rate, in this run.
    const Eigen::Index g = 1000;
    const Eigen::MatrixXd A = Eigen::MatrixXd::Random(g, g), B = Eigen::MatrixXd::Random(g, g);
    Eigen::MatrixXd C(g, g);
    double gemm = 1e30;
    for (int k = 0; k < 3; ++k) {
        const auto t = Clock::now();
        C.noalias() = A * B;
        gemm = std::min(gemm, seconds_since(t));
    }
    std::printf("{\"unknowns\": %ld, \"gemm_gflops\": %.4g", static_cast<long>(K.rows()),
                2.0 * g * g * g / gemm * 1e-9);
    Eigen::VectorXd reference_x;
    std::vector<int> position;
    for (auto kernel : {TrailingCholesky::Kernel::simplicial, TrailingCholesky::Kernel::supernodal_lu}) {
        if (only_supernodal && kernel == TrailingCholesky::Kernel::supernodal_lu) continue;
        // (ONLY: CHOLMOD's order by way of the factor that is fast to make there)
        TrailingCholesky f(K, {}, true, only_supernodal ? TrailingCholesky::Kernel::supernodal : kernel);
        if (only_supernodal) {  // its order only
            position.resize(static_cast<size_t>(K.rows()));
            for (Eigen::Index i = 0; i < K.rows(); ++i)
                position[static_cast<size_t>(i)] = f.position(static_cast<int>(i));
            std::printf(", \"cholesky_flops\": %.6g, \"cholesky_nonzeros\": %.6g", f.factor_flops(),
                        f.factor_nonzeros());
            continue;
        }
        // A refactorization of the same values redoes nothing (only what changed): each timed
        // one follows one of other values (untimed), so that it redoes every supernode.
        const SparseMatrix other = 2 * lower;
        double best = 1e30;
        for (int k = 0; k < repeats; ++k) {
            f.refactor(other);
            const auto t = Clock::now();
            f.refactor(lower);
            best = std::min(best, seconds_since(t));
        }
        Eigen::VectorXd x;
        const double solve = mean_solve_seconds(f, b, x, 10);
        const bool lu = kernel == TrailingCholesky::Kernel::supernodal_lu;
        if (!lu) {
            reference_x = x;
            position.resize(static_cast<size_t>(K.rows()));
            for (Eigen::Index i = 0; i < K.rows(); ++i)
                position[static_cast<size_t>(i)] = f.position(static_cast<int>(i));
            std::printf(", \"cholesky_flops\": %.6g, \"cholesky_nonzeros\": %.6g", f.factor_flops(),
                        f.factor_nonzeros());
        }
        std::printf(", \"%s\": {\"factor_seconds\": %.6g, \"solve_seconds\": %.6g}",
                    lu ? "supernodal_lu" : "simplicial", best, solve);
    }
    if (const char* prefix = std::getenv("WRITE_K")) {
        FILE* f = std::fopen((std::string(prefix) + ".mtx").c_str(), "w");
        std::fprintf(f, "%%%%MatrixMarket matrix coordinate real symmetric\n%ld %ld %ld\n",
                     static_cast<long>(K.rows()), static_cast<long>(K.cols()),
                     static_cast<long>(lower.nonZeros()));
        for (Eigen::Index j = 0; j < lower.outerSize(); ++j)
            for (SparseMatrix::InnerIterator it(lower, j); it; ++it)
                std::fprintf(f, "%ld %ld %.17g\n", static_cast<long>(it.row() + 1), static_cast<long>(j + 1),
                             it.value());
        std::fclose(f);
        std::vector<int> unknown_at(position.size());
        for (size_t i = 0; i < position.size(); ++i)
            unknown_at[static_cast<size_t>(position[i])] = static_cast<int>(i);
        f = std::fopen((std::string(prefix) + ".perm").c_str(), "w");
        for (int u : unknown_at) std::fprintf(f, "%d\n", u);
        std::fclose(f);
    }
    // The supernodal Cholesky with the baseline kernels, then with the fastest this CPU has, on
    // one thread and on two (whose solution must be the one thread's bit for bit).
    Eigen::VectorXd baseline_x, one_thread_x;
    for (const auto& [baseline, threads] : {std::pair{true, 1}, std::pair{false, 1}, std::pair{false, 2}}) {
        if (only_fast && (baseline || threads > 1)) continue;
        // Each repeat a factor of its own: a refactorization of the same values redoes nothing
        // (only what changed), so the same object would time no work after the first.
        double analysis = 0, best = 1e30;
        std::unique_ptr<SupernodalCholesky> factor;
        for (int k = 0; k < repeats; ++k) {
            factor.reset();
            const auto t0 = Clock::now();
            factor = std::make_unique<SupernodalCholesky>(lower, position, baseline, threads);
            analysis = seconds_since(t0);
            const auto t = Clock::now();
            if (!factor->factor(lower)) {
                std::fprintf(stderr, "not positive definite at %ld\n", static_cast<long>(factor->failed_column()));
                return 1;
            }
            best = std::min(best, seconds_since(t));
        }
        const SupernodalCholesky& s = *factor;
        Eigen::VectorXd x;
        const double solve = mean_solve_seconds(s, b, x, 10);
        if (baseline) baseline_x = x;
        if (!baseline && threads == 1) one_thread_x = x;
        const Eigen::VectorXd& against = reference_x.size() ? reference_x : baseline_x.size() ? baseline_x : x;
        const Eigen::VectorXd& baseline_or_x = baseline_x.size() ? baseline_x : x;
        std::printf(
            ", \"%s\": {\"kernel_set\": \"%s\", \"analysis_seconds\": %.6g, \"factor_seconds\": %.6g, "
            "\"solve_seconds\": %.6g, \"supernodes\": %ld, \"nonzeros\": %.6g, \"flops\": %.6g, "
            "\"gflops\": %.4g, \"difference\": %.3g, \"difference_to_baseline\": %.3g, \"threads\": %d, "
            "\"top_share\": %.3g, \"buffer_mb\": %.1f, \"same_bits_as_one_thread\": %s}",
            baseline       ? "supernodal_cholesky"
            : threads == 1 ? "supernodal_cholesky_fast"
                           : "supernodal_cholesky_fast_2_threads",
            s.kernel_set(), analysis, best, solve, static_cast<long>(s.supernodes()), s.factor_nonzeros(),
            s.factor_flops(), s.factor_flops() / best * 1e-9,
            (x - against).lpNorm<Eigen::Infinity>() / against.lpNorm<Eigen::Infinity>(),
            (x - baseline_or_x).lpNorm<Eigen::Infinity>() / baseline_or_x.lpNorm<Eigen::Infinity>(), threads,
            s.top_share(), 8e-6 * s.buffer_values(),
            threads > 1 ? (x == one_thread_x ? "true" : "false") : "null");
    }
    // The process's peak before the LU below, whose twice as large factor raises it.
    std::printf(", \"cholesky_peak_memory_mb\": %.1f", peak_rss_mb());
    if (only_fast) {
        std::printf("}\n");
        return 0;
    }
    // The LU without pivoting on the same supernodes (the held operator's slipping rows), of K
    // itself: twice the Cholesky's flops, its solution the Cholesky's to round-off.
    {
        SparseMatrix full = K;
        full.makeCompressed();
        double best = 1e30;
        std::unique_ptr<SupernodalCholesky> factor;
        for (int k = 0; k < repeats; ++k) {  // (each its own, as above)
            factor.reset();
            factor = std::make_unique<SupernodalCholesky>(lower, position);
            const auto t = Clock::now();
            if (!factor->factor_lu(full, full.valuePtr())) {
                std::fprintf(stderr, "no pivot at %ld\n", static_cast<long>(factor->failed_column()));
                return 1;
            }
            best = std::min(best, seconds_since(t));
        }
        const SupernodalCholesky& s = *factor;
        Eigen::VectorXd x;
        const double solve = mean_solve_seconds(s, b, x, 10);
        std::printf(
            ", \"supernodal_lu_fast\": {\"factor_seconds\": %.6g, \"solve_seconds\": %.6g, "
            "\"flops\": %.6g, \"gflops\": %.4g, \"difference\": %.3g}",
            best, solve, 2 * s.factor_flops(), 2 * s.factor_flops() / best * 1e-9,
            (x - one_thread_x).lpNorm<Eigen::Infinity>() / one_thread_x.lpNorm<Eigen::Infinity>());
    }
    std::printf(", \"peak_memory_mb\": %.1f}\n", peak_rss_mb());
    return 0;
}
