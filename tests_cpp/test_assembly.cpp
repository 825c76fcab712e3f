// A, M and M_r (paper section 3).
#include <gtest/gtest.h>

#include <Eigen/Dense>

#include "assembly/assembly.hpp"

using namespace contactbody;

namespace {

Eigen::MatrixXd dense(const SparseMatrix& m) { return Eigen::MatrixXd(m); }

struct MeshCase {
    double width, height;
    int nx, ny;
};

const MeshCase mesh_cases[] = {{0.1, 0.1, 20, 20}, {0.1, 0.1, 5, 5},  {1.0, 2.0, 1, 2},
                               {0.1, 0.1, 16, 40}, {0.05, 0.2, 9, 5}, {0.2, 0.1, 40, 10}};

}  // namespace

TEST(Stiffness, SymmetricWithRigidMotionsAsKernel) {
    const Mesh mesh = make_structured_mesh(0.1, 0.08, 5, 4);
    const Eigen::MatrixXd A = dense(stiffness_matrix(mesh, 300e6, 150e6));
    const double scale = A.cwiseAbs().maxCoeff();
    EXPECT_LE((A - A.transpose()).cwiseAbs().maxCoeff(), 1e-14 * scale);

    Eigen::MatrixXd rigid(mesh.num_dofs(), 3);
    for (int n = 0; n < mesh.num_nodes(); ++n) {
        const Point p = mesh.point(n);
        rigid.row(mesh.dof(n, 0)) << 1, 0, -p.y;
        rigid.row(mesh.dof(n, 1)) << 0, 1, p.x;
    }
    EXPECT_LE((A * rigid).cwiseAbs().maxCoeff(), 1e-12 * scale);

    // Exactly three zero eigenvalues: the kernel is the rigid motions and nothing more.
    Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(A);
    const Eigen::VectorXd ev = eig.eigenvalues();
    for (int k = 0; k < 3; ++k) EXPECT_LE(std::abs(ev[k]), 1e-10 * ev.maxCoeff());
    EXPECT_GT(ev[3], 1e-6 * ev.maxCoeff());
}

TEST(Mass, ConsistentMassIsTheBodyMass) {
    const Mesh mesh = make_structured_mesh(0.1, 0.1, 20, 20);
    const auto m = mass_moments(mesh, scalar_mass_matrix(mesh, 1000));
    EXPECT_NEAR(m[0], 1000 * 0.1 * 0.1, 1e-12 * 10);
    EXPECT_NEAR(m[1], 10 * 0.05, 1e-12);  // centre of mass at (W/2, H/2)
}

TEST(RedistributedMass, KeepsTotalMassFirstAndSecondMoments) {
    for (const MeshCase& c : mesh_cases) {
        const Mesh mesh = make_structured_mesh(c.width, c.height, c.nx, c.ny);
        const SparseMatrix M = scalar_mass_matrix(mesh, 1000);
        std::vector<std::string> notes;
        const auto before = mass_moments(mesh, M);
        const auto after = mass_moments(mesh, redistributed_mass(mesh, M, notes));
        for (int k = 0; k < 6; ++k)
            EXPECT_LE(std::abs(after[k] - before[k]), 1e-12 * std::abs(before[k]))
                << "moment " << k << " on mesh " << c.nx << "x" << c.ny;
    }
}

TEST(RedistributedMass, KernelIsExactlyTheContactNodes) {
    for (const MeshCase& c : mesh_cases) {
        const Mesh mesh = make_structured_mesh(c.width, c.height, c.nx, c.ny);
        std::vector<std::string> notes;
        const Eigen::MatrixXd Mr = dense(redistributed_mass(mesh, scalar_mass_matrix(mesh, 1000), notes));
        EXPECT_EQ((Mr - Mr.transpose()).cwiseAbs().maxCoeff(), 0.0) << "exactly symmetric";

        std::vector<char> contact(mesh.num_nodes(), 0);
        for (int n : mesh.contact_nodes) contact[n] = 1;
        std::vector<int> rest;
        for (int n = 0; n < mesh.num_nodes(); ++n) {
            if (contact[n]) {
                EXPECT_EQ(Mr.row(n).cwiseAbs().maxCoeff(), 0.0);
                EXPECT_EQ(Mr.col(n).cwiseAbs().maxCoeff(), 0.0);
            } else {
                rest.push_back(n);
            }
        }
        // Positive definite on the complement of the contact nodes.
        Eigen::MatrixXd Mrest(rest.size(), rest.size());
        for (size_t i = 0; i < rest.size(); ++i)
            for (size_t j = 0; j < rest.size(); ++j) Mrest(i, j) = Mr(rest[i], rest[j]);
        Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(Mrest);
        EXPECT_GT(eig.eigenvalues()[0], 1e-8 * eig.eigenvalues().maxCoeff())
            << "mesh " << c.nx << "x" << c.ny;
    }
}

TEST(RedistributedMass, RejectsAMeshTooCoarseForTheMoments) {
    const Mesh mesh = make_structured_mesh(0.1, 0.1, 4, 1);
    std::vector<std::string> notes;
    EXPECT_THROW(redistributed_mass(mesh, scalar_mass_matrix(mesh, 1000), notes), std::invalid_argument);
}

TEST(RedistributedMass, RejectsAnIndefiniteCorrection) {
    // Three elongated rows: removing the bottom row's mass needs a correction so large that
    // the least-squares M_r is indefinite; it is refused, not returned.
    const Mesh mesh = make_structured_mesh(0.3, 0.07, 7, 3);
    std::vector<std::string> notes;
    EXPECT_THROW(redistributed_mass(mesh, scalar_mass_matrix(mesh, 1000), notes), std::invalid_argument);
}

TEST(Mesh, DiagonalsAlternateAsGetFEMRegularSimplices) {
    const Mesh mesh = make_structured_mesh(1, 1, 2, 2);
    // Cell (0,0): diagonal (0,0)-(1,1); cell (1,0): diagonal (2,0)-(1,1).
    EXPECT_EQ(std::vector<int>(mesh.cell(0), mesh.cell(0) + 3), (std::vector<int>{0, 1, 4}));
    EXPECT_EQ(std::vector<int>(mesh.cell(2), mesh.cell(2) + 3), (std::vector<int>{1, 2, 4}));
    EXPECT_EQ(mesh.contact_nodes.size(), 3u);
    EXPECT_EQ(mesh.top_nodes.front(), 6);
}
