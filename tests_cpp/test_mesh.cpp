// The two sources of a Mesh: the rectangle and a Gmsh file (MSH 4.1 and 2.2 ASCII, written
// here by hand; python_tests/test_mesh_file.py reads files the real Gmsh wrote).
#include <gtest/gtest.h>

#include <cstdio>
#include <numeric>
#include <stdexcept>
#include <string>

#include "assembly/discretization.hpp"
#include "mesh/gmsh.hpp"

namespace contactbody {
namespace {

std::string write_file(const std::string& name, const std::string& text) {
    const std::string path = ::testing::TempDir() + name;
    FILE* f = std::fopen(path.c_str(), "wb");
    std::fputs(text.c_str(), f);
    std::fclose(f);
    return path;
}

// A trapezoid: bottom nodes 1 (0,0), 2 (0.2,0), 5 (0.1,0.01) a raised middle node, top 3, 4.
// Node tags are not in order along x, and node 5 is higher than 1 and 2.
const char* msh41 = R"($MeshFormat
4.1 0 8
$EndMeshFormat
$PhysicalNames
3
1 10 "contact"
1 11 "clamp"
2 12 "body"
$EndPhysicalNames
$Entities
0 2 1 0
1 0 0 0 0.2 0.01 0 1 10 0
2 0 0.1 0 0.2 0.1 0 1 11 0
1 0 0 0 0.2 0.1 0 1 12 0
$EndEntities
$Nodes
1 5 1 5
2 1 0 5
1
2
3
4
5
0 0 0
0.2 0 0
0.2 0.1 0
0 0.1 0
0.1 0.01 0
$EndNodes
$Elements
3 6 1 6
1 1 1 2
1 1 5
2 5 2
1 2 1 1
3 3 4
2 1 2 3
4 1 5 4
5 5 2 3
6 5 3 4
$EndElements
)";

const char* msh22 = R"($MeshFormat
2.2 0 8
$EndMeshFormat
$PhysicalNames
3
1 10 "contact"
1 11 "clamp"
2 12 "body"
$EndPhysicalNames
$Nodes
5
1 0 0 0
2 0.2 0 0
3 0.2 0.1 0
4 0 0.1 0
5 0.1 0.01 0
$EndNodes
$Elements
6
1 1 2 10 1 1 5
2 1 2 10 1 5 2
3 1 2 11 2 3 4
4 2 2 12 1 1 5 4
5 2 2 12 1 5 2 3
6 2 2 12 1 5 3 4
$EndElements
)";

TEST(Mesh, TheRectangleKeepsItsSizesSharesAndFlatEdge) {
    const Mesh m = make_structured_mesh(0.3, 0.07, 3, 2);
    EXPECT_TRUE(m.is_rectangle());
    EXPECT_EQ(m.num_nodes(), 12);
    EXPECT_EQ(m.width(), 0.3);
    EXPECT_EQ(m.clamp_height(), 0.07);
    ASSERT_EQ(m.contact_shares.size(), 4u);
    EXPECT_EQ(m.contact_shares[0], 0.5 * (0.3 / 3));
    EXPECT_EQ(m.contact_shares[1], 0.3 / 3);
    for (double h : m.contact_heights) EXPECT_EQ(h, 0.0);
    EXPECT_EQ(m.point(m.contact_nodes[3]).x, 0.3);
}

TEST(Mesh, GmshFilesOfBothVersionsGiveTheSameMesh) {
    std::vector<std::string> notes41, notes22;
    const Mesh a = read_gmsh_mesh(write_file("trapezoid41.msh", msh41), max_nodes, notes41);
    const Mesh b = read_gmsh_mesh(write_file("trapezoid22.msh", msh22), max_nodes, notes22);
    for (const Mesh* m : {&a, &b}) {
        EXPECT_FALSE(m->is_rectangle());
        ASSERT_EQ(m->num_nodes(), 5);
        ASSERT_EQ(m->contact_nodes, (std::vector<int>{0, 4, 1}));  // by x: tags 1, 5, 2
        EXPECT_EQ(m->top_nodes, (std::vector<int>{2, 3}));
        EXPECT_DOUBLE_EQ(m->contact_shares[0], 0.05);  // half of each line's x extent
        EXPECT_DOUBLE_EQ(m->contact_shares[1], 0.1);
        EXPECT_DOUBLE_EQ(m->contact_heights[1], 0.01);
        EXPECT_EQ(m->contact_heights[0], 0.0);
        EXPECT_EQ(m->contact_y, 0.0);
        EXPECT_EQ(m->clamp_y, 0.1);
        EXPECT_EQ(m->num_cells(), 3u);
    }
    EXPECT_EQ(a.cells, b.cells);
    EXPECT_TRUE(notes41.empty());
}

TEST(Mesh, AClockwiseFileIsTurnedOverAndTheNoteSaysSo) {
    std::string text = msh41;
    for (const auto& [from, to] : {std::pair<std::string, std::string>{"4 1 5 4", "4 1 4 5"},
                                   {"5 5 2 3", "5 5 3 2"},
                                   {"6 5 3 4", "6 5 4 3"}})
        text.replace(text.find(from), from.size(), to);
    std::vector<std::string> notes;
    const Mesh m = read_gmsh_mesh(write_file("clockwise.msh", text), max_nodes, notes);
    ASSERT_EQ(notes.size(), 1u);
    EXPECT_NE(notes[0].find("every triangle was clockwise"), std::string::npos);
    std::vector<std::string> unused;
    const Mesh reference = read_gmsh_mesh(write_file("ccw.msh", msh41), max_nodes, unused);
    const SparseMatrix A = stiffness_matrix(m, 3e8, 1.5e8), B = stiffness_matrix(reference, 3e8, 1.5e8);
    EXPECT_LT((Eigen::MatrixXd(A) - Eigen::MatrixXd(B)).norm(), 1e-6 * Eigen::MatrixXd(B).norm());
}

TEST(Mesh, ErrorsNameTheFileAndTheLine) {
    std::vector<std::string> notes;
    std::string text = msh41;
    text.replace(text.find("0.1 0.01 0"), 10, "0.1 0.01 1");  // z != 0 on line 28
    try {
        read_gmsh_mesh(write_file("z.msh", text), max_nodes, notes);
        FAIL() << "accepted a node out of the plane";
    } catch (const std::invalid_argument& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find("z.msh, line 28: node 5 has z = 1"), std::string::npos) << what;
    }
    EXPECT_THROW(read_gmsh_mesh(write_file("cut.msh", std::string(msh41).substr(0, 300)), max_nodes, notes),
                 std::invalid_argument);
}

TEST(Mesh, AMeshFileIsAssembledAsTheRectangleIs) {
    // The stiffness annihilates translations, the mass sums to rho x area, and the
    // redistributed mass keeps the consistent one's moments without the contact nodes' entries.
    std::vector<std::string> notes;
    const Mesh m = read_gmsh_mesh(write_file("assembled.msh", msh41), max_nodes, notes);
    const SparseMatrix A = stiffness_matrix(m, 3e8, 1.5e8);
    Eigen::VectorXd t = Eigen::VectorXd::Zero(m.num_dofs());
    for (int n = 0; n < m.num_nodes(); ++n) t[m.dof(n, 0)] = 1;
    EXPECT_LT((A * t).norm(), 1e-6);
    const SparseMatrix M = scalar_mass_matrix(m, 1000);
    const double area = 0.2 * 0.1 - 0.5 * 0.2 * 0.01;
    EXPECT_NEAR(Eigen::MatrixXd(M).sum(), 1000 * area, 1e-12);
}

}  // namespace
}  // namespace contactbody
