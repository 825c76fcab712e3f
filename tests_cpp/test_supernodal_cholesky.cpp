// The supernodal Cholesky (linalg/supernodal_cholesky.hpp) against the body's factor: the same
// solutions of K x = b on a 2D and a 3D body's K in the factor's own order, a factor that
// groups its columns into far fewer supernodes, and a matrix that is not positive definite
// reported with its column.
#include <gtest/gtest.h>

#include "assembly/discretization.hpp"
#include "linalg/supernodal_cholesky.hpp"
#include "linalg/trailing_cholesky.hpp"

using namespace contactbody;

namespace {

// The paper's rectangle at nx = ny = n (2D), or the lopsided solid of the outside checks (3D).
SparseMatrix body_matrix(int dimension, int n) {
    SceneParameters p;
    p.dimension = dimension;
    p.nx = p.ny = n;
    p.friction_coefficient = 0;
    if (dimension == 3) p.mesh = CONTACTBODY_TEST_DATA "/outside/lopsided3d.msh";
    const Discretization d = discretize(p);
    const double dt = 1e-6;
    SparseMatrix K = d.A_free + (4 / (dt * dt)) * d.M_free;
    K.makeCompressed();
    return K;
}

}  // namespace

TEST(SupernodalCholesky, SolvesAsTheBodysFactorOn2DAnd3DBodies) {
    for (const auto& [dimension, n] : {std::pair{2, 24}, std::pair{3, 0}}) {
        const SparseMatrix K = body_matrix(dimension, n);
        const SparseMatrix lower = K.triangularView<Eigen::Lower>();
        TrailingCholesky reference(K, {});
        std::vector<int> position(static_cast<size_t>(K.rows()));
        for (Eigen::Index i = 0; i < K.rows(); ++i)
            position[static_cast<size_t>(i)] = reference.position(static_cast<int>(i));
        SupernodalCholesky f(lower, position);
        ASSERT_TRUE(f.factor(lower));
        EXPECT_LT(f.supernodes(), K.rows() / 3) << "dimension " << dimension;
        EXPECT_GE(f.factor_nonzeros(), reference.factor_nonzeros());  // the amalgamation's zeros
        const Eigen::VectorXd b = Eigen::VectorXd::Random(K.rows());
        Eigen::VectorXd x, expected;
        f.solve(b, x);
        reference.solve(b, expected);
        EXPECT_LE((x - expected).lpNorm<Eigen::Infinity>(), 1e-10 * expected.lpNorm<Eigen::Infinity>())
            << "dimension " << dimension;
        EXPECT_LE((K * x - b).lpNorm<Eigen::Infinity>(), 1e-8 * b.lpNorm<Eigen::Infinity>());
    }
}

TEST(SupernodalCholesky, AMatrixThatIsNotPositiveDefiniteIsReportedWithItsColumn) {
    SparseMatrix K = body_matrix(2, 8);
    const Eigen::Index bad = K.rows() / 2;
    K.coeffRef(bad, bad) = -1;
    const SparseMatrix lower = K.triangularView<Eigen::Lower>();
    std::vector<int> position(static_cast<size_t>(K.rows()));
    for (Eigen::Index i = 0; i < K.rows(); ++i) position[static_cast<size_t>(i)] = static_cast<int>(i);
    SupernodalCholesky f(lower, position);
    EXPECT_FALSE(f.factor(lower));
    EXPECT_GE(f.failed_column(), 0);
    EXPECT_LE(f.failed_column(), bad);
}

// The kernels for this CPU and the baseline ones solve alike (to round-off: FMA and wider
// vectors sum in another order), and each names its set; forced, the baseline is the baseline.
TEST(SupernodalCholesky, TheFastKernelsSolveAsTheBaselineOnes) {
    const SparseMatrix K = body_matrix(3, 0);
    const SparseMatrix lower = K.triangularView<Eigen::Lower>();
    TrailingCholesky reference(K, {});
    std::vector<int> position(static_cast<size_t>(K.rows()));
    for (Eigen::Index i = 0; i < K.rows(); ++i)
        position[static_cast<size_t>(i)] = reference.position(static_cast<int>(i));
    SupernodalCholesky baseline(lower, position, true), fast(lower, position);
    EXPECT_STREQ(baseline.kernel_set(), "baseline");
    EXPECT_STREQ(fast.kernel_set(), supernodal_kernels().name);
    ASSERT_TRUE(baseline.factor(lower));
    ASSERT_TRUE(fast.factor(lower));
    const Eigen::VectorXd b = Eigen::VectorXd::Random(K.rows());
    Eigen::VectorXd x, y;
    baseline.solve(b, x);
    fast.solve(b, y);
    EXPECT_LE((x - y).lpNorm<Eigen::Infinity>(), 1e-12 * x.lpNorm<Eigen::Infinity>()) << fast.kernel_set();
}
