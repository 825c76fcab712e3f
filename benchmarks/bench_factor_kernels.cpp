// One case of benchmarks/factor_kernels.py: the refactorable factor of a body's K (the sparse
// contact solve's), with CHOLMOD's simplicial Cholesky and with the supernodal LU of the same
// ordering (TrailingCholesky::Kernel). Prints one JSON object: the unknowns, the analysis's
// flops, the nonzeros of L, and for each kernel the first factorization (with its analysis),
// a refactorization and a solve (the mean of 20), in seconds.
//   bench_factor_kernels MESH|rect:NX DIMENSION
#include <cstdio>
#include <cstdlib>
#include <cstring>

#include "bench_common.hpp"
#include "linalg/trailing_cholesky.hpp"

using namespace contactbody;
using namespace bench;

int main(int argc, char** argv) {
    if (argc < 3) {
        std::fprintf(stderr, "usage: bench_factor_kernels MESH|rect:NX DIMENSION\n");
        return 2;
    }
    const SparseMatrix K = body_stiffness(argv[1], std::atoi(argv[2]));
    const SparseMatrix lower = K.triangularView<Eigen::Lower>();
    const Eigen::VectorXd b = Eigen::VectorXd::Random(K.rows());
    std::printf("{\"unknowns\": %ld", static_cast<long>(K.rows()));
    for (auto kernel : {TrailingCholesky::Kernel::simplicial, TrailingCholesky::Kernel::supernodal_lu}) {
        auto t = Clock::now();
        TrailingCholesky f(K, {}, true, kernel);
        const double first = seconds_since(t);
        // (after one of other values: one of the same values redoes nothing)
        f.refactor(SparseMatrix(2 * lower));
        t = Clock::now();
        f.refactor(lower);
        const double refactor = seconds_since(t);
        Eigen::VectorXd x;
        const double solve = mean_solve_seconds(f, b, x, 20);
        const bool lu = kernel == TrailingCholesky::Kernel::supernodal_lu;
        if (!lu)
            std::printf(", \"flops\": %.6g, \"factor_nonzeros\": %.6g", f.factor_flops(),
                        f.factor_nonzeros());
        std::printf(", \"%s\": {\"factor\": %.6g, \"refactor\": %.6g, \"solve\": %.6g, \"residual\": %.3g}",
                    lu ? "supernodal_lu" : "simplicial", first, refactor, solve,
                    (K * x - b).norm() / b.norm());
    }
    std::printf("}\n");
    return 0;
}
