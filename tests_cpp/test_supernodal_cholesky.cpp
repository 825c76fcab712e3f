// The supernodal Cholesky (linalg/supernodal_cholesky.hpp) against the body's factor: the same
// solutions of K x = b on a 2D and a 3D body's K in the factor's own order, a factor that
// groups its columns into far fewer supernodes, and a matrix that is not positive definite
// reported with its column.
#include <gtest/gtest.h>

#include <cmath>
#include <numeric>

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

// Each unknown's place in f's order (CHOLMOD's fill-reducing one).
std::vector<int> factor_order(const TrailingCholesky& f) {
    std::vector<int> position(static_cast<size_t>(f.size()));
    for (Eigen::Index i = 0; i < f.size(); ++i)
        position[static_cast<size_t>(i)] = f.position(static_cast<int>(i));
    return position;
}

}  // namespace

TEST(SupernodalCholesky, SolvesAsTheBodysFactorOn2DAnd3DBodies) {
    for (const auto& [dimension, n] : {std::pair{2, 24}, std::pair{3, 0}}) {
        const SparseMatrix K = body_matrix(dimension, n);
        const SparseMatrix lower = K.triangularView<Eigen::Lower>();
        TrailingCholesky reference(K, {});
        const std::vector<int> position = factor_order(reference);
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
    const std::vector<int> position = factor_order(reference);
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

// Every kernel set this CPU runs (x86-64-v3 and x86-64-v4 where it has them) computes each
// kernel as the baseline does, to round-off, on blocks wider than Eigen's register blocks and
// with leading dimensions beyond their rows; and the sets listed are those the CPU reports.
TEST(SupernodalCholesky, EveryKernelSetThisCpuRunsComputesAsTheBaseline) {
    const auto& sets = supernodal_kernel_sets();
    ASSERT_FALSE(sets.empty());
    EXPECT_STREQ(sets.front()->name, "baseline");
    EXPECT_EQ(&supernodal_kernels(), sets.back());
#if defined(__x86_64__)
    __builtin_cpu_init();
    const bool v3 = __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma");
    const bool v4 = v3 && __builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512dq") &&
                    __builtin_cpu_supports("avx512vl") && __builtin_cpu_supports("avx512bw");
    EXPECT_EQ(sets.size(), 1u + v3 + v4);
#endif
    const std::ptrdiff_t n = 203, rows = 157, ld = 211;
    Eigen::MatrixXd g = Eigen::MatrixXd::Random(n, n);
    Eigen::MatrixXd spd = Eigen::MatrixXd::Zero(ld, n);
    spd.topRows(n) = g * g.transpose() + n * Eigen::MatrixXd::Identity(n, n);
    const Eigen::MatrixXd x = Eigen::MatrixXd::Random(ld, n), b = Eigen::MatrixXd::Random(ld, n);
    struct Results { Eigen::MatrixXd chol, solved, syrk, gemm, lu, updated, panel; };
    const auto run = [&](const SupernodalKernels& k) {
        Results r{spd, x, Eigen::MatrixXd::Zero(ld, rows), Eigen::MatrixXd::Zero(ld, rows), spd, b,
                  Eigen::MatrixXd::Zero(n + rows, 1)};
        EXPECT_EQ(k.cholesky(r.chol.data(), n, ld), -1) << k.name;
        k.solve_right(r.chol.data(), n, ld, r.solved.data(), rows, ld);
        k.lower_product(x.data(), ld, rows, n, r.syrk.data(), ld);
        k.product(x.data(), ld, b.data(), ld, rows, rows, n, r.gemm.data(), ld);
        EXPECT_EQ(k.lu(r.lu.data(), n, ld), -1) << k.name;
        k.subtract_product(x.data(), ld, b.data(), ld, rows, rows, n, r.updated.data(), ld);
        // A panel of n + rows rows: the Cholesky block over the solved rows, forward then backward.
        Eigen::MatrixXd panel(n + rows, n);
        panel.topRows(n) = r.chol.topRows(n).triangularView<Eigen::Lower>();
        panel.bottomRows(rows) = r.solved.topRows(rows);
        Eigen::VectorXd y = b.col(0).head(n), gathered(rows);
        k.forward_panel(panel.data(), n + rows, n, y.data(), gathered.data());
        k.backward_panel(panel.data(), n + rows, n, y.data(), gathered.data());
        r.panel << y, gathered;
        return r;
    };
    const Results expected = run(*sets.front());
    for (const SupernodalKernels* k : sets) {
        const Results got = run(*k);
        const auto close = [&](const Eigen::MatrixXd& a, const Eigen::MatrixXd& e, const char* what) {
            EXPECT_LE((a - e).lpNorm<Eigen::Infinity>(), 1e-12 * e.lpNorm<Eigen::Infinity>()) << k->name << " " << what;
        };
        close(got.chol.triangularView<Eigen::Lower>(), expected.chol.triangularView<Eigen::Lower>(), "cholesky");
        close(got.solved, expected.solved, "solve_right");
        close(got.syrk.triangularView<Eigen::Lower>(), expected.syrk.triangularView<Eigen::Lower>(), "lower_product");
        close(got.gemm, expected.gemm, "product");
        close(got.lu, expected.lu, "lu");
        close(got.updated, expected.updated, "subtract_product");
        close(got.panel, expected.panel, "panels");
    }
    // The baseline's own answers are right, not merely shared: L L^T = K and the GEMM.
    const Eigen::MatrixXd l = expected.chol.topRows(n).triangularView<Eigen::Lower>();
    EXPECT_LE((l * l.transpose() - spd.topRows(n)).lpNorm<Eigen::Infinity>(), 1e-12 * spd.lpNorm<Eigen::Infinity>());
    EXPECT_LE((expected.gemm.topRows(rows) - x.topRows(rows) * b.topRows(rows).transpose()).lpNorm<Eigen::Infinity>(),
              1e-12 * expected.gemm.lpNorm<Eigen::Infinity>());
}

namespace {

// The 7-point Laplacian of an n^3 grid plus a shift: its separators (n^2 unknowns) give panels
// wider than SupernodalCholesky's blocks, so their blocked factor and updates run.
SparseMatrix grid_laplacian(int n) {
    const auto index = [n](int i, int j, int k) { return (i * n + j) * n + k; };
    std::vector<Eigen::Triplet<double>> entries;
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j)
            for (int k = 0; k < n; ++k) {
                const int p = index(i, j, k);
                entries.emplace_back(p, p, 6.01);
                if (i + 1 < n) entries.emplace_back(index(i + 1, j, k), p, -1.0);
                if (j + 1 < n) entries.emplace_back(index(i, j + 1, k), p, -1.0);
                if (k + 1 < n) entries.emplace_back(index(i, j, k + 1), p, -1.0);
            }
    SparseMatrix lower(n * n * n, n * n * n);
    lower.setFromTriplets(entries.begin(), entries.end());
    return lower;
}

}  // namespace

// One thread and several factor the same bits (the subtrees' groups and the panels' blocks do
// not depend on the threads), on a body's K and on a grid whose panels exceed the blocks; and
// they solve K x = b.
TEST(SupernodalCholesky, AnyNumberOfThreadsFactorsTheSameBits) {
    const SparseMatrix body = body_matrix(3, 0);
    for (const SparseMatrix& lower :
         {SparseMatrix(body.triangularView<Eigen::Lower>()), grid_laplacian(22)}) {
        const SparseMatrix K = lower.selfadjointView<Eigen::Lower>();
        TrailingCholesky reference(K, {});
        const std::vector<int> position = factor_order(reference);
        const Eigen::VectorXd b = Eigen::VectorXd::Random(K.rows());
        Eigen::VectorXd one;
        for (int threads : {1, 2, 3}) {
            SupernodalCholesky f(lower, position, false, threads);
            ASSERT_TRUE(f.factor(lower));
            EXPECT_EQ(f.threads(), threads);
            EXPECT_GT(f.top_share(), 0.0);
            EXPECT_LT(f.top_share(), 1.0);
            Eigen::VectorXd x;
            f.solve(b, x);
            EXPECT_LE((K * x - b).lpNorm<Eigen::Infinity>(), 1e-10 * b.lpNorm<Eigen::Infinity>() * K.rows());
            if (threads == 1)
                one = x;
            else
                EXPECT_TRUE(x == one)
                    << threads << " threads, largest difference " << (x - one).lpNorm<Eigen::Infinity>();
        }
    }
}

// A matrix that is not positive definite is reported at the same column on any number of threads.
TEST(SupernodalCholesky, AFailureIsReportedAtTheSameColumnOnAnyNumberOfThreads) {
    SparseMatrix lower = grid_laplacian(14);
    const Eigen::Index bad = lower.rows() / 3;
    lower.coeffRef(bad, bad) = -1;
    std::vector<int> position(static_cast<size_t>(lower.rows()));
    std::iota(position.begin(), position.end(), 0);
    Eigen::Index one = -2;
    for (int threads : {1, 2}) {
        SupernodalCholesky f(lower, position, false, threads);
        EXPECT_FALSE(f.factor(lower));
        EXPECT_GE(f.failed_column(), 0);
        if (threads == 1) one = f.failed_column();
        EXPECT_EQ(f.failed_column(), one);
    }
}

// The LU without pivoting of a matrix with K's pattern but values that are not symmetric (K's
// entries above the diagonal scaled by up to 30 %, as the held operator's slipping rows make
// it): A x = b to round-off on the grid, whose panels exceed the blocks, and on the 3D body;
// with K's own values, the Cholesky's solution; a Cholesky after it; a zero pivot reported.
TEST(SupernodalCholesky, TheLuSolvesAMatrixWithoutSymmetricValues) {
    for (const int which : {0, 1}) {
        SCOPED_TRACE(which == 0 ? "grid" : "3D body");
        SparseMatrix K = which == 0 ? grid_laplacian(22) : body_matrix(3, 0);
        if (which == 0) K = SparseMatrix(SparseMatrix(K).selfadjointView<Eigen::Lower>());  // both triangles
        K.makeCompressed();
        const SparseMatrix lower = K.triangularView<Eigen::Lower>();
        TrailingCholesky reference(K, {});
        const std::vector<int> position = factor_order(reference);
        SupernodalCholesky f(lower, position);
        const Eigen::VectorXd b = Eigen::VectorXd::Random(K.rows());
        Eigen::VectorXd x, expected;
        ASSERT_TRUE(f.factor_lu(K, K.valuePtr()));
        EXPECT_TRUE(f.lu());
        f.solve(b, x);
        reference.solve(b, expected);
        EXPECT_LE((x - expected).lpNorm<Eigen::Infinity>(), 1e-10 * expected.lpNorm<Eigen::Infinity>());
        // Not symmetric: each stored entry (r, c) above the diagonal scaled by 1 + 0.3 sin(r + 2c).
        SparseMatrix A = K;
        for (Eigen::Index c = 0; c < A.outerSize(); ++c)
            for (SparseMatrix::InnerIterator it(A, c); it; ++it)
                if (it.row() < c) it.valueRef() *= 1 + 0.3 * std::sin(static_cast<double>(it.row() + 2 * c));
        ASSERT_GT((SparseMatrix(A.transpose()) - A).norm(), 1e-3 * A.norm());
        ASSERT_TRUE(f.factor_lu(A, A.valuePtr()));
        f.solve(b, x);
        EXPECT_LE((A * x - b).lpNorm<Eigen::Infinity>(),
                  1e-9 * b.lpNorm<Eigen::Infinity>() * A.norm() / std::sqrt(static_cast<double>(A.rows())));
        // A Cholesky again after the LU: the symmetric solve.
        ASSERT_TRUE(f.factor(lower));
        EXPECT_FALSE(f.lu());
        f.solve(b, x);
        EXPECT_LE((x - expected).lpNorm<Eigen::Infinity>(), 1e-10 * expected.lpNorm<Eigen::Infinity>());
        // A zero pivot: its row and column cleared (the diagonal too).
        SparseMatrix Z = A;
        const Eigen::Index zero = K.rows() / 2;
        for (Eigen::Index c = 0; c < Z.outerSize(); ++c)
            for (SparseMatrix::InnerIterator it(Z, c); it; ++it)
                if (it.row() == zero || c == zero) it.valueRef() = 0;
        EXPECT_FALSE(f.factor_lu(Z, Z.valuePtr()));
        EXPECT_GE(f.failed_column(), 0);
        EXPECT_LE(f.failed_column(), position[static_cast<size_t>(zero)]);
    }
}

namespace {

// lower (or both triangles) with unknowns `held` as the identity's rows and columns, as the
// sparse contact solve holds them: the same pattern, values changed in their columns only.
SparseMatrix held_copy(const SparseMatrix& matrix, const std::vector<int>& held) {
    SparseMatrix H = matrix;
    std::vector<char> is_held(static_cast<size_t>(H.rows()), 0);
    for (int i : held) is_held[static_cast<size_t>(i)] = 1;
    for (Eigen::Index c = 0; c < H.outerSize(); ++c)
        for (SparseMatrix::InnerIterator it(H, c); it; ++it)
            if (is_held[static_cast<size_t>(it.row())] || is_held[static_cast<size_t>(c)])
                it.valueRef() = it.row() == c ? 1.0 : 0.0;
    return H;
}

}  // namespace

// A factorization after one of the same kind redoes only the supernodes its changed values
// reach (the columns of newly held unknowns and their ancestors), with the same bits as a
// factor made whole: on the grid (blocked panels and updates) and the 3D body, for the
// Cholesky on one and two threads and for the LU; after a failure it factors whole again.
TEST(SupernodalCholesky, ARefactorizationRedoesOnlyWhatChangedWithTheSameBits) {
    for (const int which : {0, 1}) {
        SCOPED_TRACE(which == 0 ? "grid" : "3D body");
        SparseMatrix K = which == 0 ? grid_laplacian(22) : body_matrix(3, 0);
        if (which == 0) K = SparseMatrix(SparseMatrix(K).selfadjointView<Eigen::Lower>());
        K.makeCompressed();
        const SparseMatrix lower = K.triangularView<Eigen::Lower>();
        TrailingCholesky reference(K, {});
        const std::vector<int> position = factor_order(reference);
        // Hold the three unknowns first in the factor's order, then also two in its middle.
        std::vector<int> by_place(position.size());
        for (size_t i = 0; i < position.size(); ++i)
            by_place[static_cast<size_t>(position[i])] = static_cast<int>(i);
        const std::vector<int> first_held{by_place[0], by_place[1], by_place[2]};
        std::vector<int> more_held = first_held;
        more_held.push_back(by_place[by_place.size() / 2]);
        more_held.push_back(by_place[by_place.size() / 2 + 1]);
        const Eigen::VectorXd b = Eigen::VectorXd::Random(K.rows());
        for (int threads : {1, 2}) {
            SupernodalCholesky f(lower, position, false, threads);
            ASSERT_TRUE(f.factor(lower));
            EXPECT_EQ(f.refactored_share(), 1.0);
            for (const std::vector<int>& held : {first_held, more_held, first_held}) {
                const SparseMatrix H = held_copy(lower, held);
                ASSERT_TRUE(f.factor(H));
                EXPECT_GT(f.refactored_share(), 0.0);
                EXPECT_LT(f.refactored_share(), which == 0 ? 0.9 : 1.0) << held.size() << " held";
                SupernodalCholesky whole(lower, position, false, threads);
                ASSERT_TRUE(whole.factor(H));
                Eigen::VectorXd x, expected;
                f.solve(b, x);
                whole.solve(b, expected);
                EXPECT_TRUE(x == expected)
                    << threads << " threads, " << held.size() << " held, largest difference "
                    << (x - expected).lpNorm<Eigen::Infinity>();
            }
        }
        // The LU: the same values with the entries above the diagonal scaled, then held.
        SparseMatrix A = K;
        for (Eigen::Index c = 0; c < A.outerSize(); ++c)
            for (SparseMatrix::InnerIterator it(A, c); it; ++it)
                if (it.row() < c) it.valueRef() *= 1 + 0.3 * std::sin(static_cast<double>(it.row() + 2 * c));
        SupernodalCholesky f(lower, position);
        ASSERT_TRUE(f.factor_lu(A, A.valuePtr()));
        for (const std::vector<int>& held : {first_held, more_held}) {
            const SparseMatrix H = held_copy(A, held);
            ASSERT_TRUE(f.factor_lu(H, H.valuePtr()));
            EXPECT_LT(f.refactored_share(), which == 0 ? 0.9 : 1.0) << held.size() << " held";
            SupernodalCholesky whole(lower, position);
            ASSERT_TRUE(whole.factor_lu(H, H.valuePtr()));
            Eigen::VectorXd x, expected;
            f.solve(b, x);
            whole.solve(b, expected);
            EXPECT_TRUE(x == expected) << "LU, " << held.size() << " held, largest difference "
                                       << (x - expected).lpNorm<Eigen::Infinity>();
        }
        // A failed factorization leaves nothing to redo from: the next one is whole.
        SparseMatrix bad = lower;
        bad.coeffRef(by_place[0], by_place[0]) = -1;
        SupernodalCholesky g(lower, position);
        ASSERT_TRUE(g.factor(lower));
        EXPECT_FALSE(g.factor(bad));
        ASSERT_TRUE(g.factor(lower));
        EXPECT_EQ(g.refactored_share(), 1.0);
        Eigen::VectorXd x, expected;
        g.solve(b, x);
        reference.solve(b, expected);
        EXPECT_LE((x - expected).lpNorm<Eigen::Infinity>(), 1e-10 * expected.lpNorm<Eigen::Infinity>());
    }
}

// The rule (TrailingCholesky::supernodal_pays, docs/decisions.md "The rule on whole substeps"):
// below 1e9 flops the refactorable factor is the supernodal one only where its panels are
// dense. A 3D grid between 1e8 and 1e9 flops takes it; the 2D rectangle at nx = 160, as many
// flops on thin panels (on which the 2D pad's substeps measured slower), keeps CHOLMOD's one.
TEST(SupernodalCholesky, TheRuleTakesTheSupernodalFactorBelow1e9FlopsOnlyOnDensePanels) {
    const SparseMatrix grid = grid_laplacian(22);
    const SparseMatrix rectangle = body_matrix(2, 160);
    for (const auto& [matrix, dense] : {std::pair{&grid, true}, std::pair{&rectangle, false}}) {
        const TrailingCholesky f(*matrix, {}, true);
        const double flops = f.factor_flops();
        SCOPED_TRACE(dense ? "grid" : "rectangle");
        ASSERT_GE(flops, TrailingCholesky::dense_supernodal_flops);
        ASSERT_LT(flops, TrailingCholesky::supernodal_flops);
        RecordProperty(dense ? "grid_flops_per_nonzero" : "rectangle_flops_per_nonzero",
                       std::to_string(flops / f.factor_nonzeros()));
        EXPECT_EQ(f.kernel(), dense ? TrailingCholesky::Kernel::supernodal : TrailingCholesky::Kernel::simplicial);
    }
}
