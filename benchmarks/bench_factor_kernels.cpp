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
    SceneParameters p;
    if (std::strncmp(argv[1], "rect:", 5) == 0)
        p.nx = p.ny = std::atoi(argv[1] + 5);
    else
        p.mesh = argv[1];
    p.dimension = std::atoi(argv[2]);
    p.friction_coefficient = 0;
    const Discretization d = discretize(p);
    const double dt = 1e-6;  // the substep of the contact_scaling scenes
    SparseMatrix K = d.A_free + (4 / (dt * dt)) * d.M_free;
    K.makeCompressed();
    const SparseMatrix lower = K.triangularView<Eigen::Lower>();
    const Eigen::VectorXd b = Eigen::VectorXd::Random(K.rows());
    std::printf("{\"unknowns\": %ld", static_cast<long>(K.rows()));
    for (auto kernel : {TrailingCholesky::Kernel::simplicial, TrailingCholesky::Kernel::supernodal_lu}) {
        auto t = Clock::now();
        TrailingCholesky f(K, {}, true, kernel);
        const double first = seconds_since(t);
        t = Clock::now();
        f.refactor(lower);
        const double refactor = seconds_since(t);
        Eigen::VectorXd x;
        f.solve(b, x);
        t = Clock::now();
        for (int k = 0; k < 20; ++k) f.solve(b, x);
        const double solve = seconds_since(t) / 20;
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
