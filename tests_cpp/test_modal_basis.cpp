// The reduced body's basis (solver/reduced/modal_basis.cpp): the identities of the construction in
// docs/decisions.md, "The reduced body", on the FMU's own matrices, and Spectra against a
// dense solve.
#include <gtest/gtest.h>

#include "reduced/modal_basis.hpp"

using namespace contactbody;

namespace {

SceneParameters scene(int n, MassVariant variant) {
    SceneParameters p;
    p.nx = p.ny = n;
    p.mass_matrix = variant;
    return p;
}

// Largest |entry| of x relative to the largest |entry| of scale.
double relative(const Eigen::MatrixXd& x, const Eigen::MatrixXd& scale) {
    return x.cwiseAbs().maxCoeff() / scale.cwiseAbs().maxCoeff();
}

Eigen::MatrixXd contact_transpose(const Discretization& d) {  // B^T: N = -e_y, T = +e_x
    const Eigen::Index nc = static_cast<Eigen::Index>(d.contact_tangential[0].size());
    Eigen::MatrixXd Bt = Eigen::MatrixXd::Zero(d.A_free.rows(), 2 * nc);
    for (Eigen::Index i = 0; i < nc; ++i) {
        Bt(d.contact_y[static_cast<size_t>(i)], i) = -1;
        Bt(d.contact_tangential[0][static_cast<size_t>(i)], nc + i) = 1;
    }
    return Bt;
}

void expect_identities(const Discretization& d, const ModalBasis& b) {
    const Eigen::MatrixXd A(d.A_free), M(d.M_free);
    const Eigen::Index m = b.modes.cols(), k = b.residual.cols();
    const Eigen::MatrixXd I = Eigen::MatrixXd::Identity(m, m);
    EXPECT_LT(relative(b.modes.transpose() * M * b.modes - I, I), 1e-9);
    const Eigen::MatrixXd W2 = b.omega2.asDiagonal();
    EXPECT_LT(relative(b.modes.transpose() * A * b.modes - W2, W2), 1e-9);
    if (k > 0) {
        const Eigen::MatrixXd Ik = Eigen::MatrixXd::Identity(k, k);
        EXPECT_LT(relative(b.residual.transpose() * A * b.residual - Ik, Ik), 1e-9);
        const Eigen::MatrixXd coupling_A = b.modes.transpose() * A * b.residual;
        EXPECT_LT(coupling_A.cwiseAbs().maxCoeff() / std::sqrt(b.omega2.maxCoeff()), 1e-9);
        const Eigen::MatrixXd coupling_M = b.modes.transpose() * M * b.residual;
        EXPECT_LT(coupling_M.cwiseAbs().maxCoeff() * std::sqrt(b.omega2.minCoeff()), 1e-9);
    }
    // The edge's static response to contact forces is the full body's, whatever m.
    Eigen::MatrixXd T(A.rows(), m + k);
    T << b.modes, b.residual;
    const Eigen::MatrixXd Bt = contact_transpose(d);
    const Eigen::MatrixXd exact = A.llt().solve(Bt);
    const Eigen::MatrixXd reduced = T * (T.transpose() * A * T).llt().solve(T.transpose() * Bt);
    EXPECT_LT(relative(reduced - exact, exact), 1e-9);
    // The lift: A_ff S + A_fc e = 0.
    Eigen::VectorXd e = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(d.clamped_dofs.size()));
    for (size_t j = 0; j < d.clamped_dofs.size(); ++j)
        e[static_cast<Eigen::Index>(j)] = d.clamped_dofs[j] % 2;
    const Eigen::VectorXd load = d.A_free_clamped * e;
    EXPECT_LT(relative(A * b.lift + load, load), 1e-9);
}

}  // namespace

TEST(ModalBasis, SpectraAgreesWithTheDenseSolve) {
    const Discretization d = discretize(scene(8, MassVariant::redistributed_normal));
    const ModalBasis spectra = build_modal_basis(d, 10, false, 0);
    const ModalBasis dense = build_modal_basis(d, 10);
    ASSERT_FALSE(spectra.dense);
    ASSERT_TRUE(dense.dense);
    EXPECT_GT(spectra.operator_applications, 0);
    EXPECT_LT(relative(spectra.omega2 - dense.omega2, dense.omega2), 1e-9);
    const Eigen::MatrixXd M(d.M_free);
    const Eigen::MatrixXd overlap = spectra.modes.transpose() * M * dense.modes;
    for (int j = 0; j < 10; ++j) EXPECT_NEAR(std::abs(overlap(j, j)), 1.0, 1e-7) << j;
    expect_identities(d, spectra);
    expect_identities(d, dense);
}

TEST(ModalBasis, IdentitiesHoldForEveryVariant) {
    for (int v = 0; v < num_mass_variants; ++v) {
        const Discretization d = discretize(scene(6, static_cast<MassVariant>(v)));
        SCOPED_TRACE(v);
        expect_identities(d, build_modal_basis(d, 6));
    }
}

// With every finite mode the basis is square and regular and the residual carries no mass:
// the reduced body with a massless residual is the full body in other coordinates. What is
// left of the residual is exactly the massless contact dofs: the normal ones (variants 1 and
// 4), normal and tangential (2), none (0 and 3).
TEST(ModalBasis, AllModesSpanTheBodyWithAMasslessResidual) {
    const int n = 4, nc = n + 1;
    const std::pair<MassVariant, int> cases[] = {{MassVariant::standard, 0},
                                                 {MassVariant::redistributed_normal, nc},
                                                 {MassVariant::redistributed_both, 2 * nc},
                                                 {MassVariant::standard_implicit_contact, 0},
                                                 {MassVariant::redistributed_implicit_contact, nc}};
    for (const auto& [variant, massless] : cases) {
        SCOPED_TRACE(static_cast<int>(variant));
        const Discretization d = discretize(scene(n, variant));
        const int finite = finite_mode_count(d);
        EXPECT_EQ(finite, d.A_free.rows() - massless);
        const ModalBasis b = build_modal_basis(d, finite);
        EXPECT_EQ(b.residual.cols(), massless);
        Eigen::MatrixXd T(d.A_free.rows(), b.modes.cols() + b.residual.cols());
        T << b.modes, b.residual;
        ASSERT_EQ(T.cols(), T.rows());
        EXPECT_EQ(Eigen::FullPivLU<Eigen::MatrixXd>(T).rank(), T.rows());
        if (massless > 0) {  // dimensionless: the residual's mass against the stiffest mode's
            const Eigen::MatrixXd M(d.M_free);
            const double mass = (b.residual.transpose() * M * b.residual).cwiseAbs().maxCoeff();
            EXPECT_LT(mass * b.omega2.maxCoeff(), 1e-9);
        }
        expect_identities(d, b);
    }
    // With fewer modes the residual carries mass: it is taken massless by choice.
    const Discretization d = discretize(scene(n, MassVariant::redistributed_normal));
    const ModalBasis few = build_modal_basis(d, 3);
    const Eigen::MatrixXd M(d.M_free);
    const double mass = (few.residual.transpose() * M * few.residual).cwiseAbs().maxCoeff();
    EXPECT_GT(mass * few.omega2.maxCoeff(), 1e-3);
}

TEST(ModalBasis, RefusesForceControlAndCountsOutOfRange) {
    SceneParameters p = scene(4, MassVariant::redistributed_normal);
    const Discretization d = discretize(p);
    EXPECT_THROW(build_modal_basis(d, 0), std::invalid_argument);
    EXPECT_THROW(build_modal_basis(d, finite_mode_count(d) + 1), std::invalid_argument);
    p.force_control = true;
    EXPECT_THROW(build_modal_basis(discretize(p), 3), std::invalid_argument);
    // Counts the eigensolver would take minutes for (lowest_modes): refused before solving.
    const Discretization large = discretize(scene(32, MassVariant::redistributed_normal));
    ASSERT_GT(large.A_free.rows(), max_dense_modes_dofs);
    EXPECT_THROW(build_modal_basis(large, max_lanczos_modes + 1), std::invalid_argument);
    EXPECT_THROW(build_modal_basis(large, static_cast<int>(large.A_free.rows() / 4) + 1),
                 std::invalid_argument);
}
