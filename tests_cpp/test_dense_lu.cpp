// The contact Newton systems' dense factors (linalg/dense_lu.hpp): the leading block's LU, and
// the Woodbury update of a few rows and columns against a fresh LU of the changed matrix.
#include <gtest/gtest.h>

#include <random>

#include "linalg/dense_lu.hpp"

using namespace contactbody;

TEST(DenseLu, TheLeadingBlockSolvesInABufferSizedOnceAndAZeroPivotIsReported) {
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> u(-1, 1);
    LeadingLu lu;
    lu.reserve(30);
    for (int k : {30, 12, 25}) {
        Eigen::MatrixXd A(k, k);
        for (int i = 0; i < k; ++i)
            for (int j = 0; j < k; ++j) A(i, j) = u(rng) + (i == j ? 3.0 : 0.0);
        lu.matrix(k) = A;
        ASSERT_TRUE(lu.factor(k));
        Eigen::VectorXd b = Eigen::VectorXd::Random(k), x = b;
        lu.solve_in_place(x);
        EXPECT_LE((A * x - b).lpNorm<Eigen::Infinity>(), 1e-12);
        EXPECT_EQ(lu.capacity(), 30);
    }
    lu.matrix(4).setZero();
    EXPECT_FALSE(lu.factor(4));
}

TEST(DenseLu, AnUpdateOfAFewRowsAndColumnsSolvesAsTheChangedMatrixDoes) {
    const int m = 40;
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> u(-1, 1);
    Eigen::MatrixXd J0(m, m);
    for (int i = 0; i < m; ++i)
        for (int j = 0; j < m; ++j) J0(i, j) = u(rng) + (i == j ? 4.0 : 0.0);
    LeadingLu base;
    base.reserve(m);
    base.matrix(m) = J0;
    ASSERT_TRUE(base.factor(m));
    RowColumnUpdate update;
    update.reserve(m, 8);
    update.changed() = {3, 17, 29};
    Eigen::MatrixXd J = J0;
    for (int j : update.changed()) {
        for (int b = 0; b < m; ++b) J(j, b) = u(rng) + (b == j ? 4.0 : 0.0);
        for (int a = 0; a < m; ++a) J(a, j) = (a == j) ? J(j, j) : u(rng);
    }
    const Eigen::MatrixXd D = J - J0;
    auto rows = update.rows();
    auto columns = update.columns();
    columns.setZero();
    for (Eigen::Index i = 0; i < update.size(); ++i) {
        const int j = update.changed()[static_cast<size_t>(i)];
        rows.row(i) = D.row(j);
        for (int a = 0; a < m; ++a)
            if (a != 3 && a != 17 && a != 29) columns(a, i) = D(a, j);
    }
    ASSERT_TRUE(update.prepare([&](auto&& x) { base.solve_in_place(x); }));
    const Eigen::VectorXd b = Eigen::VectorXd::Random(m);
    Eigen::VectorXd x = b;
    update.solve(x, [&](auto&& y) { base.solve_in_place(y); });
    const Eigen::VectorXd expected = J.partialPivLu().solve(b);
    EXPECT_LE((x - expected).lpNorm<Eigen::Infinity>(), 1e-11 * expected.lpNorm<Eigen::Infinity>());
    Eigen::VectorXd y = b;
    base.solve_in_place(y);  // J0's solution: the update changed it
    EXPECT_GT((y - expected).lpNorm<Eigen::Infinity>(), 1e-3 * expected.lpNorm<Eigen::Infinity>());
}
