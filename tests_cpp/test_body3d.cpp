// A 3D body (issue 55): tetrahedra from a Gmsh file through the same Mesh, assembly, stepper
// and static start as the 2D body. The box [0, W] x [0, H] x [0, D], each cube of its grid
// split into six tetrahedra (Kuhn's, conforming across faces), is written here as MSH 2.2 by
// hand: bottom face "contact", top face "clamp".
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <Eigen/SparseCholesky>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <cstdio>
#include <fstream>
#include <functional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "assembly/discretization.hpp"
#include "body/stepper.hpp"
#include "contact/friction_law.hpp"
#include "linalg/held_operator.hpp"
#include "linalg/trailing_cholesky.hpp"
#include "mesh/gmsh.hpp"
#include "output/field_output.hpp"
#include "reduced/modal_basis.hpp"
#include "reduced/reduced_stepper.hpp"
#include "simulation/simulation.hpp"

namespace contactbody {
namespace {

struct Box {
    int nx = 2, ny = 5, nz = 2;
    double width = 0.1, height = 0.1, depth = 0.1;
    double angle = 0;       // rotation about y (radians) of the whole box
    bool mirrored = false;  // every tetrahedron's nodes listed in the other orientation
    int folded = -1;        // this tetrahedron alone listed in the other orientation
    bool contact_as_lines = false;
};

std::string box_file(const Box& b, const std::string& name) {
    const auto node = [&](int i, int j, int k) { return 1 + i + (b.nx + 1) * (j + (b.ny + 1) * k); };
    std::string nodes, elements;
    int count = 0, tag = 0;
    char line[256];
    const double c = std::cos(b.angle), s = std::sin(b.angle);
    for (int k = 0; k <= b.nz; ++k)
        for (int j = 0; j <= b.ny; ++j)
            for (int i = 0; i <= b.nx; ++i) {
                const double x = i * b.width / b.nx, y = j * b.height / b.ny, z = k * b.depth / b.nz;
                std::snprintf(line, sizeof line, "%d %.17g %.17g %.17g\n", node(i, j, k), c * x + s * z, y,
                              -s * x + c * z);
                nodes += line;
                ++count;
            }
    const auto element = [&](int type, int physical, std::vector<int> n) {
        std::string e =
            std::to_string(++tag) + " " + std::to_string(type) + " 2 " + std::to_string(physical) + " 1";
        for (int v : n) e += " " + std::to_string(v);
        elements += e + "\n";
    };
    // Kuhn: the six paths from corner 000 to 111, one axis at a time.
    const int paths[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
    int tet = 0;
    for (int k = 0; k < b.nz; ++k)
        for (int j = 0; j < b.ny; ++j)
            for (int i = 0; i < b.nx; ++i)
                for (const auto& path : paths) {
                    int at[3] = {i, j, k};
                    std::vector<int> n = {node(at[0], at[1], at[2])};
                    for (int axis : path) {
                        ++at[axis];
                        n.push_back(node(at[0], at[1], at[2]));
                    }
                    // Orient positively: the sign of the path's permutation decides.
                    const bool odd = path[0] == 0 ? path[1] == 2 : path[0] == 1 ? path[1] == 0 : path[1] == 1;
                    bool swap = odd;
                    if (b.mirrored) swap = !swap;
                    if (tet == b.folded) swap = !swap;
                    if (swap) std::swap(n[1], n[2]);
                    ++tet;
                    element(4, 3, n);
                }
    for (int k = 0; k < b.nz; ++k)
        for (int i = 0; i < b.nx; ++i)
            for (int face = 0; face < 2; ++face) {  // bottom (contact) and top (clamp) squares
                const int j = face == 0 ? 0 : b.ny;
                const int n00 = node(i, j, k), n10 = node(i + 1, j, k), n01 = node(i, j, k + 1),
                          n11 = node(i + 1, j, k + 1);
                if (face == 0 && b.contact_as_lines) {
                    element(1, 1, {n00, n10});
                    element(1, 1, {n00, n01});
                } else {
                    element(2, face + 1, {n00, n10, n11});
                    element(2, face + 1, {n00, n11, n01});
                }
            }
    std::string text = "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$PhysicalNames\n3\n";
    text += std::string(b.contact_as_lines ? "1" : "2") +
            " 1 \"contact\"\n2 2 \"clamp\"\n3 3 \"body\"\n$EndPhysicalNames\n";
    text += "$Nodes\n" + std::to_string(count) + "\n" + nodes + "$EndNodes\n";
    text += "$Elements\n" + std::to_string(tag) + "\n" + elements + "$EndElements\n";
    // Each test its own file: ctest runs the tests in parallel processes.
    const std::string path =
        ::testing::TempDir() + ::testing::UnitTest::GetInstance()->current_test_info()->name() + "_" + name;
    FILE* f = std::fopen(path.c_str(), "wb");
    std::fputs(text.c_str(), f);
    std::fclose(f);
    return path;
}

Mesh read_box(const Box& b, std::vector<std::string>& notes) {
    return read_gmsh_mesh(box_file(b, "box3d.msh"), 1000000, notes);
}

SceneParameters box_scene(const Box& b, const std::string& name, MassVariant variant) {
    SceneParameters p;
    p.mesh = box_file(b, name);
    p.dimension = 3;
    p.friction_coefficient = 0;
    p.mass_matrix = variant;
    return p;
}

std::string thrown(const std::function<void()>& f) {
    try {
        f();
    } catch (const std::invalid_argument& e) {
        return e.what();
    }
    return "";
}

// The box's top pressed down at 0.5 m/s from -2e-5 m, and its start: the paper's profile
// with the clamp already moving at that rate (a clamp whose velocity jumps changes the kinetic
// energy of its own mass without work).
SubstepLoad pressing(int k, double dt) {
    SubstepLoad load;
    load.top_start = -2e-5 - 0.5 * k * dt;
    load.top_end = -2e-5 - 0.5 * (k + 1) * dt;
    load.top_rate = -0.5;
    return load;
}

State pressing_start(const Stepper& body) {
    State s = body.initial_state(-2e-5);
    for (int dof : body.discretization().clamped_dofs)
        if (body.discretization().mesh.component(dof) == Mesh::normal) s.v[dof] = -0.5;
    return s;
}

// Measured on the Kuhn box, as the rectangle's ny rule was in 2D: M_r is the least change in
// the Frobenius norm from ny = 5 cells across the height, the least relative change at ny = 4,
// and not positive definite at ny <= 3 (refused, with the advice), whatever nx = nz.
TEST(Body3D, RedistributedMassNeedsFiveCellsAcrossTheBoxHeight) {
    for (int n : {2, 3}) {
        for (int ny : {3, 4, 5, 8}) {
            SCOPED_TRACE(std::to_string(n) + " x " + std::to_string(ny));
            std::vector<std::string> notes;
            Box b;
            b.nx = b.nz = n;
            b.ny = ny;
            const Mesh m = read_box(b, notes);
            const SparseMatrix M = scalar_mass_matrix(m, 1000);
            if (ny <= 3) {
                EXPECT_NE(thrown([&] { redistributed_mass(m, M, notes); }).find("cannot carry M_r"),
                          std::string::npos);
                continue;
            }
            redistributed_mass(m, M, notes);
            EXPECT_EQ(notes.size(), ny == 4 ? 1u : 0u);
        }
    }
}

// M_r's positive definiteness is decided by certificates where they can, without a
// factorization (docs/decisions.md, "M_r's positive definiteness by certificates"). On the
// consistent mass with each off-diagonal pair changed by a random fraction of itself up to f:
// below 1/(D+2) it is proved definite, and what the certificates (entries, 2x2 minors, the
// cells' blocks) prove or refute at larger f a Cholesky confirms.
TEST(Body3D, MassDefinitenessCertificatesAgreeWithACholesky) {
    std::vector<std::string> notes;
    Box b;
    b.nx = 3, b.ny = 3, b.nz = 3;
    const Mesh meshes[] = {read_box(b, notes), make_structured_mesh(0.1, 0.1, 6, 5)};
    std::srand(7);
    int proved = 0, refuted = 0, undecided = 0;
    for (const Mesh& mesh : meshes) {
        const SparseMatrix consistent = scalar_mass_matrix(mesh, 1000);
        std::vector<std::array<int, 4>> cells(mesh.num_cells());
        for (size_t e = 0; e < cells.size(); ++e) {
            cells[e].fill(-1);
            std::copy(mesh.cell(e), mesh.cell(e) + mesh.nodes_per_cell(), cells[e].begin());
        }
        const double bound = 1.0 / (mesh.dim + 2);
        for (double f : {0.99 * bound, 0.5, 1.0, 3.0})
            for (int trial = 0; trial < 20; ++trial) {
                SparseMatrix m = consistent;
                double largest = 0;
                for (int j = 0; j < m.outerSize(); ++j)
                    for (SparseMatrix::InnerIterator it(m, j); it; ++it)
                        if (it.row() < j) {
                            const double change = f * (2.0 * std::rand() / RAND_MAX - 1.0);
                            largest = std::max(largest, std::abs(change));
                            it.valueRef() *= 1 + change;
                            m.coeffRef(j, it.row()) = it.value();
                        }
                const MassCertificate c = mass_definiteness_certificate(m, largest, mesh.dim, cells);
                const bool cholesky = Eigen::SimplicialLLT<SparseMatrix>(m).info() == Eigen::Success;
                if (f < bound) {
                    EXPECT_EQ(c, MassCertificate::definite) << "f " << f;
                }
                if (c != MassCertificate::undecided) {
                    EXPECT_EQ(cholesky, c == MassCertificate::definite) << "f " << f << ", dim " << mesh.dim;
                }
                proved += c == MassCertificate::definite;
                refuted += c == MassCertificate::indefinite;
                undecided += c == MassCertificate::undecided;
            }
    }
    EXPECT_GT(proved, 0);
    EXPECT_GT(refuted, 0);
    EXPECT_GT(undecided, 0);
}

TEST(Body3D, ReadsTetrahedraAndTheContactFaces) {
    std::vector<std::string> notes;
    const Mesh m = read_box(Box{}, notes);
    EXPECT_EQ(m.dim, 3);
    EXPECT_EQ(m.num_cells(), 6u * 20u);
    EXPECT_EQ(m.num_dofs(), 3 * 54);
    EXPECT_EQ(m.contact_nodes.size(), 9u);
    EXPECT_EQ(m.top_nodes.size(), 9u);
    double total = 0;
    for (double s : m.contact_shares) total += s;
    EXPECT_NEAR(total, 0.1 * 0.1, 1e-15);  // the contact face's area, shared among its nodes
    for (double h : m.contact_heights) EXPECT_EQ(h, 0.0);
    EXPECT_TRUE(notes.empty()) << notes.front();
}

TEST(Body3D, StiffnessKernelIsExactlyTheSixRigidMotions) {
    std::vector<std::string> notes;
    const Mesh m = read_box(Box{}, notes);
    const Eigen::MatrixXd A = Eigen::MatrixXd(stiffness_matrix(m, 300e6, 150e6));
    const double scale = A.cwiseAbs().maxCoeff();
    EXPECT_LE((A - A.transpose()).cwiseAbs().maxCoeff(), 1e-14 * scale);
    Eigen::MatrixXd rigid = Eigen::MatrixXd::Zero(m.num_dofs(), 6);
    for (int n = 0; n < m.num_nodes(); ++n) {
        const Point p = m.point(n);
        for (int c = 0; c < 3; ++c) rigid(m.dof(n, c), c) = 1;
        rigid.row(m.dof(n, 0)).tail(3) << 0, p.z, -p.y;  // rotations about x, y, z
        rigid.row(m.dof(n, 1)).tail(3) << -p.z, 0, p.x;
        rigid.row(m.dof(n, 2)).tail(3) << p.y, -p.x, 0;
    }
    EXPECT_LE((A * rigid).cwiseAbs().maxCoeff(), 1e-12 * scale);
    const Eigen::VectorXd ev = Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(A).eigenvalues();
    for (int k = 0; k < 6; ++k) EXPECT_LE(std::abs(ev[k]), 1e-10 * ev.maxCoeff());
    EXPECT_GT(ev[6], 1e-6 * ev.maxCoeff());
}

TEST(Body3D, StrainEnergyIsTheQuadraticFormAndZeroForTranslations) {
    std::vector<std::string> notes;
    const Mesh m = read_box(Box{}, notes);
    const SparseMatrix A = stiffness_matrix(m, 300e6, 150e6);
    const StrainEnergy energy(m, 300e6, 150e6);
    const Eigen::VectorXd u = 1e-4 * Eigen::VectorXd::Random(m.num_dofs());
    const double form = 0.5 * u.dot(A * u);
    EXPECT_NEAR(energy(u), form, 1e-12 * form);
    Eigen::VectorXd t(m.num_dofs());
    for (int n = 0; n < m.num_nodes(); ++n) t.segment(3 * n, 3) << 1e3, -2e3, 3e3;
    EXPECT_EQ(energy(t), 0.0);
}

TEST(Body3D, MassAndRedistributedMassKeepTheTenMoments) {
    std::vector<std::string> notes;
    Box b;
    b.nx = b.nz = 3;
    b.ny = 5;
    const Mesh m = read_box(b, notes);
    const SparseMatrix M = scalar_mass_matrix(m, 1000);
    const std::vector<double> before = mass_moments(m, M);
    ASSERT_EQ(before.size(), 10u);
    EXPECT_NEAR(before[0], 1000 * 0.1 * 0.1 * 0.1, 1e-13);  // rho V, summed over 1620 entries
    const SparseMatrix Mr = redistributed_mass(m, M, notes);
    const std::vector<double> after = mass_moments(m, Mr);
    for (int k = 0; k < 10; ++k) EXPECT_LE(std::abs(after[k] - before[k]), 1e-12 * std::abs(before[0])) << k;
    const Eigen::MatrixXd dense(Mr);
    for (int n : m.contact_nodes) EXPECT_EQ(dense.row(n).cwiseAbs().maxCoeff(), 0.0);
    // Positive definite off the contact nodes.
    std::vector<int> keep;
    for (int n = 0; n < m.num_nodes(); ++n)
        if (std::find(m.contact_nodes.begin(), m.contact_nodes.end(), n) == m.contact_nodes.end())
            keep.push_back(n);
    Eigen::MatrixXd kept(keep.size(), keep.size());
    for (size_t i = 0; i < keep.size(); ++i)
        for (size_t j = 0; j < keep.size(); ++j) kept(i, j) = dense(keep[i], keep[j]);
    EXPECT_EQ(Eigen::LLT<Eigen::MatrixXd>(kept).info(), Eigen::Success);
}

TEST(Body3D, MirroredMeshIsTurnedOverAndItsBodyIsTheSame) {
    std::vector<std::string> notes;
    const Mesh a = read_box(Box{}, notes);
    Box mirrored;
    mirrored.mirrored = true;
    const Mesh b = read_gmsh_mesh(box_file(mirrored, "mirrored.msh"), 1000000, notes);
    ASSERT_EQ(notes.size(), 1u);
    EXPECT_NE(notes[0].find("every tetrahedron had negative volume"), std::string::npos) << notes[0];
    EXPECT_EQ(Eigen::MatrixXd(stiffness_matrix(a, 3e8, 1.5e8)),
              Eigen::MatrixXd(stiffness_matrix(b, 3e8, 1.5e8)));
}

TEST(Body3D, BadTetrahedralFilesAreRefusedWithTheirLine) {
    std::vector<std::string> notes;
    Box folded;
    folded.folded = 5;
    EXPECT_NE(thrown([&] { read_box(folded, notes); }).find("tetrahedron 6 is inverted"), std::string::npos)
        << thrown([&] { read_box(folded, notes); });
    Box lines;
    lines.contact_as_lines = true;
    const std::string lines_error = thrown([&] { read_box(lines, notes); });
    EXPECT_NE(lines_error.find("must be a group of boundary surfaces (dimension 2), not of lines"),
              std::string::npos)
        << lines_error;
    EXPECT_NE(lines_error.find(", line "), std::string::npos);
    // A second-order tetrahedron (type 11) is named as such.
    const std::string text =
        "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n1\n1 0 0 0\n$EndNodes\n"
        "$Elements\n1\n1 11 2 3 1 1 1 1 1 1 1 1 1 1 1\n$EndElements\n";
    const std::string path = ::testing::TempDir() + "second_order.msh";
    FILE* f = std::fopen(path.c_str(), "wb");
    std::fputs(text.c_str(), f);
    std::fclose(f);
    const std::string second = thrown([&] { read_gmsh_mesh(path, 1000000, notes); });
    EXPECT_NE(second.find("line 10: element 1 is a 10-node (second-order) tetrahedron"), std::string::npos)
        << second;
}

TEST(Body3D, ATwoDimensionalModelRefusesATetrahedralMeshAndAZVelocity) {
    SceneParameters p = box_scene(Box{}, "box_2d_model.msh", MassVariant::redistributed_normal);
    p.dimension = 2;
    EXPECT_NE(thrown([&] { discretize(p); }).find("it holds tetrahedra, a 3D body"), std::string::npos);
    p.dimension = 3;
    p.mesh.clear();
    EXPECT_NE(thrown([&] { check_parameters(p); }).find("a 3D body comes from a Gmsh file"),
              std::string::npos);
    // A 2D body (the rectangle) has no z: neither a z velocity of its foundation nor of itself.
    SceneParameters planar;
    planar.nx = planar.ny = 4;
    planar.initial_velocity[2] = 1;
    EXPECT_NE(thrown([&] { check_parameters(planar); }).find("initial_velocity_z must be 0 for a 2D body"),
              std::string::npos);
    planar.initial_velocity[2] = 0;
    Simulation sim(planar, -1e-5);
    StepInputs in;
    in.foundation_velocity[1] = 0.5;
    EXPECT_NE(
        thrown([&] { sim.do_step(1e-5, in); }).find("a 2D body (plane strain in x-y) has no z direction"),
        std::string::npos);
}

// Isotropic friction (Remark 4.4): a box pressed on a foundation sliding in the direction
// `heading` (radians from x towards z) at 20 m/s, the box itself turned about y by `turn`.
struct Sliding {
    double normal = 0, friction_x = 0, friction_z = 0, energy = 0, dissipation = 0, balance = 0;
    int slipping = 0, sticking = 0;
    double worst_cone = 0, worst_direction = 0;  // |lambda_T| / F lambda_N - 1 at slipping nodes, etc.
    // | |lambda_T| - F lambda_N | at slipping nodes over the largest multiplier (the scale of
    // the solver's tolerance, relative to max |lambda|)
    double worst_law = 0;
    double least_substep_dissipation = 0;  // friction never creates energy: >= 0 in every substep
};

Sliding slide(MassVariant variant, double heading, double turn, double F, int substeps,
              double static_ratio = 1, double damping = 0, double speed = 20, double heading_rate = 0,
              double stribeck_velocity = 0, double viscous_friction = 0) {
    const double dt = 2e-6;
    Box b;
    b.angle = turn;
    SceneParameters p = box_scene(b, "box_sliding.msh", variant);
    p.friction_coefficient = F;
    p.static_friction_ratio = static_ratio;
    p.damping_stiffness = damping;
    p.stribeck_velocity = stribeck_velocity;
    p.viscous_friction = viscous_friction;
    ContactProblem::RateLaw law = rate_law(p);  // slip_time 1: coefficient(F, |v|) is F(v)
    Stepper body(p);
    const Discretization& d = body.discretization();
    const Mesh& mesh = d.mesh;
    const auto energy = [&](const State& state) {
        const auto [kinetic, strain] = body.kinetic_and_strain_energy(state);
        return kinetic + strain;
    };
    State s = body.initial_state(-2e-5);
    const double E0 = energy(s);
    Works works;
    Sliding out;
    SubstepLoad load;
    load.top_start = load.top_end = -2e-5;
    load.foundation_velocity[0] = speed * std::cos(heading);
    load.foundation_velocity[1] = speed * std::sin(heading);
    const int nc = static_cast<int>(mesh.contact_nodes.size());
    double scale = E0;
    for (int k = 0; k < substeps; ++k) {
        const State before = s;
        const double angle = heading + heading_rate * k * dt;  // the foundation's path turns
        load.foundation_velocity[0] = speed * std::cos(angle);
        load.foundation_velocity[1] = speed * std::sin(angle);
        const SubstepReport r = body.substep(s, dt, load);
        works += r.work;
        out.least_substep_dissipation = std::min(out.least_substep_dissipation, r.work.friction_dissipation);
        scale =
            std::max({scale, std::abs(works.clamp), std::abs(works.friction), std::abs(works.foundation)});
        out.normal += r.normal_force;
        out.friction_x += r.friction_force[0];
        out.friction_z += r.friction_force[1];
        // The law at every node: |lambda_T| <= F p, and a slipping node's friction is F p
        // against its slip (the substep's mean slip rate relative to the foundation).
        const auto& status = body.contact_solver().status();
        for (int i = 0; i < nc; ++i) {
            const double pressure = -s.lambda[i], tx = s.lambda[nc + i], tz = s.lambda[2 * nc + i];
            const double size = std::hypot(tx, tz);
            if (pressure <= 0) continue;
            const int node = mesh.contact_nodes[static_cast<size_t>(i)];
            const double sx =
                s.u[mesh.dof(node, 0)] - before.u[mesh.dof(node, 0)] - load.foundation_velocity[0] * dt;
            const double sz =
                s.u[mesh.dof(node, 2)] - before.u[mesh.dof(node, 2)] - load.foundation_velocity[1] * dt;
            const double slip = std::hypot(sx, sz);
            // A node that stuck in the substep before holds with the static coefficient; with
            // a slip-rate law F is the law's at the slip speed |slip| / dt.
            const double Fi = law.active() ? law.coefficient(F, slip / dt)
                                           : F * (before.sticking[i] != 0 ? static_ratio : 1.0);
            out.worst_cone = std::max(out.worst_cone, size / (Fi * pressure) - 1);
            if (status[i] != NodeStatus::slip) {
                ++out.sticking;
                continue;
            }
            ++out.slipping;
            out.worst_cone = std::max(out.worst_cone, std::abs(size / (Fi * pressure) - 1));
            out.worst_law =
                std::max(out.worst_law, std::abs(size - Fi * pressure) / s.lambda.lpNorm<Eigen::Infinity>());
            // friction along -slip: cos of the angle between lambda_T and -slip is 1
            out.worst_direction = std::max(out.worst_direction, 1 + (tx * sx + tz * sz) / (size * slip));
        }
    }
    out.energy = energy(s);
    out.dissipation = works.friction_dissipation;
    out.balance =
        std::abs(out.energy - E0 - (works.clamp + works.normal_contact + works.friction - works.damping)) /
        scale;
    return out;
}

// E - E(0) = the works with isotropic friction, in every variant, static friction and damping
// included; friction dissipates; every node obeys the law on the disc.
TEST(Body3D, IsotropicFrictionClosesTheEnergyBalanceAndObeysTheLawInEveryVariant) {
    for (int v = 0; v < num_mass_variants; ++v) {
        SCOPED_TRACE(v);
        const Sliding r =
            slide(static_cast<MassVariant>(v), 0.6, 0, 0.5, 200, v == 1 ? 1.5 : 1.0, v == 2 ? 1e-7 : 0);
        EXPECT_LT(r.balance, 1e-9);
        EXPECT_GT(r.slipping, 100);
        EXPECT_GT(r.dissipation, 0);
        EXPECT_LT(r.worst_cone, 1e-8);
        EXPECT_LT(r.worst_direction, 1e-8);
        EXPECT_GE(r.least_substep_dissipation, -1e-12 * std::abs(r.dissipation));
    }
}

// The slip-rate law with isotropic friction: F(|v|) = F_d + (F_s - F_d) exp(-|v| / v_s) + c_v |v|
// of the slip speed, taken implicitly. Sliding at 20 m/s and creeping under a turning
// foundation at 5 cm/s (where the Stribeck drop acts), in the variants with tangential mass:
// every slipping node carries F(|v|) p against its slip, and the balance closes.
TEST(Body3D, SlipRateLawOnTheDiscClosesTheBalanceAndObeysTheLaw) {
    for (int v : {0, 1, 3, 4}) {
        SCOPED_TRACE(v);
        const Sliding fast = slide(static_cast<MassVariant>(v), 0.6, 0, 0.4, 200, 1.5, 0, 20, 0, 1.0, 0.01);
        EXPECT_LT(fast.balance, 1e-9);
        EXPECT_GT(fast.slipping, 100);
        EXPECT_GT(fast.dissipation, 0);
        EXPECT_LT(fast.worst_cone, 1e-8);
        EXPECT_LT(fast.worst_direction, 1e-8);
        const int substeps = 300;
        const Sliding slow = slide(static_cast<MassVariant>(v), 0, 0, 0.4, substeps, 1.5, 0, 0.05,
                                   (M_PI / 2) / (substeps * 2e-6), 0.02, 0.5);
        EXPECT_LT(slow.balance, 1e-9);
        EXPECT_GT(slow.slipping, 50);
        EXPECT_GE(slow.dissipation, 0);
        // Creeping nodes carry small pressures: the law is met to the solver's tolerance,
        // which is relative to the largest multiplier (measured 2e-8 relative to the node's own).
        EXPECT_LT(slow.worst_law, 1e-9);
        EXPECT_LT(slow.worst_direction, 1e-8);
        EXPECT_GE(fast.least_substep_dissipation, -1e-12 * fast.dissipation);
        EXPECT_GE(slow.least_substep_dissipation, -1e-12 * std::abs(slow.dissipation));
    }
}

// The sparse contact solve with isotropic friction (sparse_contact.hpp: slipping nodes loaded
// along their slip direction, a fixed point carried by the Newton iterations) against the
// condensed one on W: sliding along 0.6 rad at 20 m/s, and creeping at 5 cm/s under a heading
// that turns a right angle with static friction (stick and slip), variants 1 and 4. Every
// substep's normal force, friction force (x, z) and clamp reactions agree to 1e-8 of the normal
// force, the works to 1e-9; the sparse path's balance closes to 1e-9.
// A slip-rate law's contact solve that fails at every substep size (here forced: no iteration
// allowed) names the law's steep drop as the cause, and the settings that run such scenes,
// not "Reduce internal_step": on a 3D body (the disc and its node-by-node fallback) as on a
// 2D one.
TEST(Body3D, AFailedSlipRateSolveNamesTheDropAndSettingsThatRun) {
    Box b;
    SceneParameters p3 = box_scene(b, "box3d_failing.msh", MassVariant::redistributed_normal);
    SceneParameters p2;
    for (SceneParameters* p : {&p3, &p2}) {
        SCOPED_TRACE(p->dimension);
        p->friction_coefficient = 0.3;
        p->static_friction_ratio = 1.6;
        p->stribeck_velocity = 0.3;
        p->min_internal_step = 1e-7;
        Simulation sim(*p, -2.5e-5);
        StepInputs in;
        in.foundation_velocity = {2, p->dimension == 3 ? -1.5 : 0.0};
        in.top_displacement = -2.5e-5;
        sim.do_step(1e-5, in);  // pressed and sliding
        ContactSolverOptions& options = sim.body().contact_options();
        options.max_iterations = 0;
        options.max_sweeps = 0;
        try {
            sim.do_step(1e-5, in);
            FAIL() << "the step should fail";
        } catch (const NumericalFailure& e) {
            const std::string what = e.what();
            EXPECT_NE(what.find("Cause: friction that drops with the slip rate (static_friction_ratio = 1.6 "
                                "over stribeck_velocity = 0.3 m/s)"),
                      std::string::npos)
                << what;
            EXPECT_NE(what.find("mass_matrix = 4"), std::string::npos) << what;
            EXPECT_EQ(what.find("Reduce internal_step"), std::string::npos) << what;
        }
    }
}

TEST(Body3D, SparseContactSolveWithIsotropicFrictionIsTheCondensedOne) {
    const double dt = 2e-6;
    for (auto v : {MassVariant::redistributed_normal, MassVariant::redistributed_implicit_contact}) {
        for (const bool creeping : {false, true}) {
            SCOPED_TRACE(std::to_string(static_cast<int>(v)) + (creeping ? " creeping" : " sliding"));
            Box box;  // 64 contact nodes: more slips than GCR's kept directions span
            box.nx = box.nz = 7;
            SceneParameters p = box_scene(box, "box_paths.msh", v);
            p.friction_coefficient = 0.4;
            p.static_friction_ratio = creeping ? 1.3 : 1.0;
            Stepper sparse(p), condensed(p), gcr(p);
            sparse.set_contact_path(Stepper::ContactPath::sparse);
            condensed.set_contact_path(Stepper::ContactPath::condensed);
            gcr.set_contact_path(Stepper::ContactPath::sparse_gcr);
            State a = sparse.initial_state(-2e-5), b = condensed.initial_state(-2e-5),
                  c = gcr.initial_state(-2e-5);
            int held_slips = 0;  // substeps whose factor held slipping rows
            const auto energy = [&](Stepper& body, const State& state) {
                const auto [kinetic, strain] = body.kinetic_and_strain_energy(state);
                return kinetic + strain;
            };
            const double E0 = energy(sparse, a);
            Works wa, wb;
            double worst = 0, worst_work = 0, scale = 0, work_scale = E0, least_dissipation = 0;
            int slipping = 0, sticking = 0, iterations = 0;
            const int substeps = 300;
            const double speed = creeping ? 0.05 : 20, rate = creeping ? (M_PI / 2) / (substeps * dt) : 0;
            for (int k = 0; k < substeps; ++k) {
                SubstepLoad load;
                load.top_start = load.top_end = -2e-5;
                const double heading = creeping ? rate * k * dt : 0.6;
                load.foundation_velocity[0] = speed * std::cos(heading);
                load.foundation_velocity[1] = speed * std::sin(heading);
                const SubstepReport ra = sparse.substep(a, dt, load);
                const SubstepReport rb = condensed.substep(b, dt, load);
                const SubstepReport rc = gcr.substep(c, dt, load);
                const std::vector<double>& held = sparse.contact_factorization().slip;
                held_slips += std::any_of(held.begin(), held.end(), [](double x) { return x != 0; });
                worst = std::max(worst, std::abs(rc.normal_force - rb.normal_force));
                wa += ra.work;
                wb += rb.work;
                least_dissipation =
                    std::min({least_dissipation, ra.work.friction_dissipation, rb.work.friction_dissipation});
                scale = std::max(scale, std::abs(rb.normal_force));
                work_scale = std::max(
                    {work_scale, std::abs(wb.clamp), std::abs(wb.friction), std::abs(wb.foundation)});
                worst = std::max({worst, std::abs(ra.normal_force - rb.normal_force),
                                  std::abs(ra.friction_force[0] - rb.friction_force[0]),
                                  std::abs(ra.friction_force[1] - rb.friction_force[1]),
                                  std::abs(ra.top_reaction[0] - rb.top_reaction[0]),
                                  std::abs(ra.top_reaction[1] - rb.top_reaction[1]),
                                  std::abs(ra.top_reaction[2] - rb.top_reaction[2])});
                worst_work = std::max({worst_work, std::abs(wa.friction - wb.friction),
                                       std::abs(wa.friction_dissipation - wb.friction_dissipation),
                                       std::abs(wa.normal_contact - wb.normal_contact)});
                slipping += rb.slipping_nodes;
                sticking += rb.active_nodes - rb.slipping_nodes;
                iterations += ra.contact_iterations;
            }
            EXPECT_TRUE(sparse.sparse_contact());
            EXPECT_FALSE(condensed.sparse_contact());
            EXPECT_GT(slipping, 100);
            // The slipping rows in the factor (docs/decisions.md, "A 3D body's factor holds its
            // slipping nodes"): held where more nodes slip than GCR's kept directions span (the
            // box's slipping nodes fall from 64 to about 40 as it bounces), with fewer held solves
            // than the slips left to GCR, and no slip held by the GCR path.
            EXPECT_TRUE(gcr.contact_factorization().slip.empty());
            RecordProperty(creeping ? "creeping_held_solves" : "sliding_held_solves",
                           std::to_string(sparse.sparse_solver().solves()) + " against " +
                               std::to_string(gcr.sparse_solver().solves()) + " by GCR");
            RecordProperty(creeping ? "creeping_refactorizations" : "sliding_refactorizations",
                           std::to_string(sparse.sparse_refactorizations()));
            if (!creeping) {
                RecordProperty("held_slips", held_slips);
                EXPECT_GT(held_slips, substeps / 10);
                EXPECT_LT(sparse.sparse_solver().solves(), gcr.sparse_solver().solves());
            }
            if (creeping) EXPECT_GT(sticking, 100);
            EXPECT_LT(worst / scale, 1e-8);
            EXPECT_LT(worst_work / work_scale, 1e-9);
            const double balance =
                std::abs(energy(sparse, a) - E0 - (wa.clamp + wa.normal_contact + wa.friction - wa.damping));
            EXPECT_LT(balance / work_scale, 1e-9);
            EXPECT_GE(least_dissipation, -1e-12 * work_scale);  // friction never creates energy
            RecordProperty(creeping ? "creeping_newton_iterations" : "sliding_newton_iterations", iterations);
        }
    }
}

// A static start's load step from rest (the top to -2e-5 m in dt = 1e3 s, contact at the end
// of the step, as the load paths of a curved body run it), on the sparse and on the condensed
// contact solve.
struct LoadStep {
    explicit LoadStep(const SceneParameters& p) : sparse(p), condensed(p) {
        sparse.set_contact_path(Stepper::ContactPath::sparse);
        condensed.set_contact_path(Stepper::ContactPath::condensed);
        a = sparse.initial_state(0);
        b = condensed.initial_state(0);
        a.v.setZero();
        b.v.setZero();
        SubstepLoad load;
        load.top_start = 0;
        load.top_end = -2e-5;
        ra = sparse.substep(a, 1e3, load);
        rb = condensed.substep(b, 1e3, load);
    }
    Stepper sparse, condensed;
    State a, b;
    SubstepReport ra, rb;
};

// The load step with friction: the box pressed onto the foundation spreads under
// Poisson, so its rim slips outwards in every direction of the plane at once, and its middle
// sticks. A slipping node's direction depends on its neighbours' through the body, so a fixed
// point in the directions converged slowly or not at all (a 2.7k-node hemisphere's static
// start failed after 100 iterations); the Newton step in the directions converges as the
// condensed solve does, to the same solution.
TEST(Body3D, SparseContactSolveConvergesOnAQuasiStaticLoadStepWithFriction) {
    Box b;
    b.nx = b.nz = 6;
    SceneParameters p = box_scene(b, "box_load_step.msh", MassVariant::standard_implicit_contact);
    p.friction_coefficient = 0.3;
    LoadStep step(p);
    const SubstepReport &ra = step.ra, &rb = step.rb;
    EXPECT_TRUE(step.sparse.sparse_contact());
    EXPECT_GT(rb.slipping_nodes, 8);
    EXPECT_GT(rb.active_nodes - rb.slipping_nodes, 4);
    EXPECT_EQ(ra.slipping_nodes, rb.slipping_nodes);
    RecordProperty("newton_iterations", ra.contact_iterations);
    EXPECT_LT(ra.contact_iterations, 20);
    EXPECT_NEAR(ra.normal_force, rb.normal_force, 1e-8 * rb.normal_force);
    EXPECT_NEAR(ra.friction_force[0], rb.friction_force[0], 1e-8 * rb.normal_force);
    EXPECT_NEAR(ra.friction_force[1], rb.friction_force[1], 1e-8 * rb.normal_force);
    EXPECT_NEAR((step.a.u - step.b.u).lpNorm<Eigen::Infinity>(), 0,
                1e-8 * step.b.u.lpNorm<Eigen::Infinity>());
}

// A 3D body's held operator with slipping rows: a held solve satisfies K's rows where free,
// the held values, and r_T = F r_y t on each slipping node (r = K x - b, t its unit slip
// direction), which is what the sparse contact solve reads of it; with the slips dropped it is
// the Cholesky's solve again.
TEST(Body3D, SlippingRowsHoldTheDiscsSlipLaw) {
    Box box;
    box.nx = box.nz = 6;
    SceneParameters p = box_scene(box, "box_held_slips.msh", MassVariant::redistributed_normal);
    p.friction_coefficient = 0.3;
    const Stepper body(p);
    const Discretization& d = body.discretization();
    const double dt = 1e-6;
    const SparseMatrix K = (4.0 / (dt * dt)) * d.M_free + d.A_free;
    HeldOperator held(K, d.contact_unknowns(), 3);
    held.set_slip_coefficient(0.3);
    ASSERT_EQ(held.slip_coefficient(), 0.3);  // the node's x, y and z columns share their rows
    const Eigen::Index n = held.unknowns() / 3;
    std::vector<char> hold(static_cast<size_t>(3 * n), 0);
    std::vector<double> slip(static_cast<size_t>(2 * n), 0.0);
    for (Eigen::Index i = 0; i < n; ++i) {  // open, sticking, slipping along a heading, pressed
        hold[static_cast<size_t>(i)] = i % 4 != 0;
        hold[static_cast<size_t>(n + i)] = hold[static_cast<size_t>(2 * n + i)] = i % 4 == 1;
        if (i % 4 == 2) {
            slip[static_cast<size_t>(i)] = std::cos(0.7 * static_cast<double>(i));
            slip[static_cast<size_t>(n + i)] = std::sin(0.7 * static_cast<double>(i));
        }
    }
    held.hold(hold, slip);
    ASSERT_EQ(held.slip(), slip);  // the LU found its pivots
    Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(K.rows(), -1e3, 2e3), values(3 * n), x;
    for (Eigen::Index j = 0; j < 3 * n; ++j) values[j] = 1e-6 * static_cast<double>(j % 5 - 2);
    const Eigen::VectorXd rhs = b;
    held.impose(b, values);
    held.solve(b, x);
    const Eigen::VectorXd r = K * x - rhs;
    const double tol = 1e-9 * rhs.norm();
    std::vector<char> contact(static_cast<size_t>(K.rows()), 0);
    for (Eigen::Index j = 0; j < 3 * n; ++j) contact[static_cast<size_t>(held.dof(j))] = 1;
    for (Eigen::Index k = 0; k < K.rows(); ++k)
        if (!contact[static_cast<size_t>(k)]) EXPECT_NEAR(r[k], 0, tol) << "free row " << k;
    int slipping = 0;
    for (Eigen::Index i = 0; i < n; ++i) {
        const int y = held.dof(i);
        if (hold[static_cast<size_t>(i)])
            EXPECT_DOUBLE_EQ(x[y], values[i]);
        else
            EXPECT_NEAR(r[y], 0, tol);
        for (Eigen::Index c = 1; c <= 2; ++c) {
            const int t = held.dof(c * n + i);
            if (hold[static_cast<size_t>(c * n + i)])
                EXPECT_DOUBLE_EQ(x[t], values[c * n + i]);
            else
                EXPECT_NEAR(r[t] - 0.3 * slip[static_cast<size_t>((c - 1) * n + i)] * r[y], 0, tol)
                    << "node " << i << ", tangent " << c;
        }
        slipping += slip[static_cast<size_t>(i)] != 0;
    }
    EXPECT_GT(slipping, 8);
    // Without the slips: K held at the same dofs, symmetric again.
    held.hold(hold);
    EXPECT_TRUE(std::all_of(held.slip().begin(), held.slip().end(), [](double s) { return s == 0; }));
    b = rhs;
    held.impose(b, values);
    held.solve(b, x);
    const Eigen::VectorXd r2 = K * x - rhs;
    for (Eigen::Index j = n; j < 3 * n; ++j)
        if (!hold[static_cast<size_t>(j)]) EXPECT_NEAR(r2[held.dof(j)], 0, tol);
}

// Where a refactorization costs more held solves than GCR may take (a tetrahedral body of a
// few thousand nodes), a pattern that differs from the factor's held set is solved on that
// factor first: a frictionless box pressed from rest in one quasi-static step (every contact
// node held, none held by the factor) needs no refactorization, and gives the condensed
// solve's state. Before, it refactored at the first pattern of more than 64 dofs.
TEST(Body3D, ACostlyFactorSolvesAPatternOnTheFactorItHas) {
    Box b;
    b.nx = b.nz = 16;
    b.ny = 10;
    SceneParameters p = box_scene(b, "box_costly_factor.msh", MassVariant::standard_implicit_contact);
    LoadStep step(p);
    const SubstepReport &ra = step.ra, &rb = step.rb;
    const TrailingCholesky& factor = step.sparse.last_factor();
    // HeldOperator::refactorization_in_solves of the stepper's held operator
    const double refactorization = factor.factor_flops() / (4 * factor.factor_nonzeros());
    RecordProperty("refactorization_in_solves", std::to_string(refactorization));
    ASSERT_GT(refactorization, SparseContactSolver::max_directions);
    EXPECT_EQ(ra.active_nodes, (b.nx + 1) * (b.nz + 1));
    EXPECT_EQ(step.sparse.sparse_refactorizations(), 0);
    EXPECT_NEAR(ra.normal_force, rb.normal_force, 1e-8 * rb.normal_force);
    EXPECT_NEAR((step.a.u - step.b.u).lpNorm<Eigen::Infinity>(), 0,
                1e-8 * step.b.u.lpNorm<Eigen::Infinity>());
}

// Stick and slip under a foundation that creeps and turns its heading by a right angle over
// the run: nodes stick, break loose with the static coefficient, slip in a turning direction;
// the balance and the law hold throughout.
TEST(Body3D, IsotropicFrictionSticksSlipsAndFollowsATurningFoundation) {
    for (auto v : {MassVariant::redistributed_normal, MassVariant::redistributed_implicit_contact}) {
        SCOPED_TRACE(static_cast<int>(v));
        const int substeps = 400;
        const double rate = (M_PI / 2) / (substeps * 2e-6);
        const Sliding r = slide(v, 0, 0, 0.4, substeps, 1.3, 0, 0.05, rate);
        EXPECT_LT(r.balance, 1e-9);
        EXPECT_GT(r.sticking, 100);
        EXPECT_GT(r.slipping, 100);
        EXPECT_GE(r.dissipation, 0);
        EXPECT_LT(r.worst_cone, 1e-8);
        EXPECT_LT(r.worst_direction, 1e-8);
        EXPECT_GT(std::abs(r.friction_z), 0.1 * std::abs(r.friction_x));  // it turned
    }
}

// Nothing depends on x as a direction: the box turned about y by 0.9 rad, the foundation's
// velocity turned with it, gives the same normal force and energy, and the friction force
// turned by the same angle.
TEST(Body3D, IsotropicFrictionDoesNotDependOnTheDirection) {
    const double heading = 0.3, turn = 0.9;
    const Sliding a = slide(MassVariant::redistributed_normal, heading, 0, 0.5, 150);
    // The turned box: x' = c x + s z, z' = -s x + c z; its foundation's heading turns by -turn.
    const Sliding b = slide(MassVariant::redistributed_normal, heading - turn, turn, 0.5, 150);
    EXPECT_GT(a.slipping, 100);
    EXPECT_NEAR(b.normal, a.normal, 1e-9 * a.normal);
    EXPECT_NEAR(b.energy, a.energy, 1e-9 * a.energy);
    const double c = std::cos(turn), s = std::sin(turn);
    const double size = std::hypot(a.friction_x, a.friction_z);
    EXPECT_NEAR(b.friction_x, c * a.friction_x + s * a.friction_z, 1e-9 * size);
    EXPECT_NEAR(b.friction_z, -s * a.friction_x + c * a.friction_z, 1e-9 * size);
}

// E - E(0) = the works, in every variant, on a box pressed down at its top and moving down.
TEST(Body3D, EnergyBalanceClosesInEveryVariant) {
    const double dt = 2e-6;
    for (int v = 0; v < num_mass_variants; ++v) {
        SCOPED_TRACE(v);
        Box b;
        SceneParameters p = box_scene(b, "box_energy.msh", static_cast<MassVariant>(v));
        p.initial_velocity[1] = -1;
        p.damping_stiffness = v == 2 ? 1e-7 : 0;
        Stepper body(p);
        const auto energy = [&](const State& state) {
            const auto [kinetic, strain] = body.kinetic_and_strain_energy(state);
            return kinetic + strain;
        };
        State s = pressing_start(body);
        const double E0 = energy(s);
        Works works;
        int touching = 0;
        double scale = E0;
        for (int k = 0; k < 300; ++k) {
            const SubstepReport r = body.substep(s, dt, pressing(k, dt));
            works += r.work;
            touching += r.active_nodes > 0;
            scale = std::max({scale, std::abs(works.clamp), std::abs(works.normal_contact)});
        }
        EXPECT_GT(touching, 100);
        const double balance = energy(s) - E0 - (works.clamp + works.normal_contact - works.damping);
        EXPECT_LT(std::abs(balance) / scale, 1e-9);
    }
}

// The static start's load against the top's reaction, and a box rotated about y (with no
// friction nothing may depend on the direction in the foundation's plane).
TEST(Body3D, StaticStartIsInBalanceAndDoesNotDependOnTheBodysTurn) {
    std::vector<double> loads, energies;
    for (double angle : {0.0, 0.7}) {
        Box b;
        b.angle = angle;
        SceneParameters p = box_scene(b, "box_static.msh", MassVariant::redistributed_normal);
        p.static_initial_state = true;
        Simulation sim(p, -2e-5);
        const Observables& o = sim.observables();
        EXPECT_GT(o.normal_force, 0);
        EXPECT_NEAR(o.normal_force, -o.top_reaction[1], 1e-9 * o.normal_force);
        EXPECT_EQ(o.active_contact_nodes, 9);  // the whole 3 x 3 contact face
        loads.push_back(o.normal_force);
        energies.push_back(o.strain_energy);
    }
    EXPECT_NEAR(loads[1], loads[0], 1e-10 * loads[0]);
    EXPECT_NEAR(energies[1], energies[0], 1e-10 * energies[0]);
}

// The refactorable factor's kernels (TrailingCholesky::Kernel) solve the same systems, K and K
// with dofs held (rows and columns the identity's), as the sparse contact solve uses them: the
// supernodal Cholesky and the supernodal LU it replaced as the simplicial Cholesky does.
TEST(Body3D, SupernodalKernelsSolveAsTheSimplicialCholeskyDoes) {
    const Discretization d = discretize(box_scene(Box{}, "box_kernels.msh", MassVariant::standard));
    SparseMatrix K = d.A_free + (4 / 1e-12) * d.M_free;
    K.makeCompressed();
    SparseMatrix held = K.triangularView<Eigen::Lower>();
    held.makeCompressed();
    TrailingCholesky cholesky(K, {}, true, TrailingCholesky::Kernel::simplicial);
    EXPECT_FALSE(cholesky.supernodal());
    EXPECT_LT(cholesky.factor_flops(), TrailingCholesky::supernodal_flops);  // automatic: Cholesky
    const Eigen::VectorXd b = Eigen::VectorXd::Random(K.rows());
    Eigen::VectorXd x, y;
    // Hold every contact node's y dof.
    SparseMatrix held_values = held;
    for (int dof : d.contact_y)
        for (Eigen::Index col = 0; col < held_values.outerSize(); ++col)
            for (SparseMatrix::InnerIterator it(held_values, col); it; ++it)
                if (it.row() == dof || it.col() == dof) it.valueRef() = it.row() == it.col() ? 1.0 : 0.0;
    for (auto kernel : {TrailingCholesky::Kernel::supernodal, TrailingCholesky::Kernel::supernodal_lu}) {
        TrailingCholesky other(K, {}, true, kernel);
        EXPECT_TRUE(other.supernodal());
        EXPECT_EQ(other.kernel(), kernel);
        TrailingCholesky fresh(K, {}, true, TrailingCholesky::Kernel::simplicial);
        fresh.solve(b, x);
        other.solve(b, y);
        EXPECT_LE((x - y).norm(), 1e-12 * x.norm());
        EXPECT_LE((K * y - b).norm(), 1e-10 * b.norm());
        fresh.refactor(held_values);
        other.refactor(held_values);
        fresh.solve(b, x);
        other.solve(b, y);
        EXPECT_LE((x - y).norm(), 1e-12 * x.norm());
        for (int dof : d.contact_y) EXPECT_NEAR(y[dof], b[dof], 1e-12 * std::abs(b[dof]));
        other.refactor(held);  // and back: K again
        other.solve(b, y);
        EXPECT_LE((K * y - b).norm(), 1e-10 * b.norm());
    }
}

// The reduced 3D body with every finite mode of its clamped interior is the full body, in
// both of its contact edges and the variants whose edge is massless in y (as in 2D; variant 2
// is refused on a reduced 3D body for now).
TEST(Body3D, ReducedBodyWithEveryModeIsTheFullBody) {
    // Pressed, without friction and with isotropic friction under a foundation sliding along
    // 0.6 rad in the x-z plane, both edges (variant 2 has no tangential mass: massless only):
    // the normal, friction and clamp forces in x, y and z are the full body's to 1e-10.
    const double dt = 2e-6;
    struct Case {
        MassVariant variant;
        ReducedEdge edge;
        double friction;
    };
    std::vector<Case> cases;
    for (double F : {0.0, 0.4}) {
        for (auto v : {MassVariant::redistributed_normal, MassVariant::redistributed_implicit_contact})
            for (auto edge : {ReducedEdge::massless, ReducedEdge::tangential_mass})
                cases.push_back({v, edge, F});
        cases.push_back({MassVariant::redistributed_both, ReducedEdge::massless, F});
    }
    for (const Case& c : cases) {
        SCOPED_TRACE(std::to_string(static_cast<int>(c.variant)) + " " +
                     std::to_string(static_cast<int>(c.edge)) + " F = " + std::to_string(c.friction));
        SceneParameters p = box_scene(Box{}, "box_reduced.msh", c.variant);
        p.initial_velocity[1] = -1;
        p.reduced_edge = c.edge;
        p.friction_coefficient = c.friction;
        Stepper full(p);
        const bool tangential = c.edge == ReducedEdge::tangential_mass;
        ReducedStepper reduced(p, finite_mode_count(discretize(p), tangential));
        State s = pressing_start(full);
        ReducedState r = reduced.from_full(s);
        double scale = 0, worst = 0, friction = 0;
        int touching = 0;
        for (int k = 0; k < 300; ++k) {
            SubstepLoad load = pressing(k, dt);
            load.foundation_velocity[0] = 2 * std::cos(0.6);
            load.foundation_velocity[1] = 2 * std::sin(0.6);
            const SubstepReport a = full.substep(s, dt, load);
            const SubstepReport b = reduced.substep(r, dt, load);
            scale = std::max(scale, std::abs(a.normal_force));
            worst = std::max({worst, std::abs(a.normal_force - b.normal_force),
                              std::abs(a.friction_force[0] - b.friction_force[0]),
                              std::abs(a.friction_force[1] - b.friction_force[1]),
                              std::abs(a.top_reaction[0] - b.top_reaction[0]),
                              std::abs(a.top_reaction[1] - b.top_reaction[1]),
                              std::abs(a.top_reaction[2] - b.top_reaction[2]),
                              std::abs(a.work.friction_dissipation - b.work.friction_dissipation) / dt});
            friction = std::max(friction, std::hypot(a.friction_force[0], a.friction_force[1]));
            touching += a.active_nodes > 0;
        }
        EXPECT_GT(touching, 100);
        if (c.friction > 0) EXPECT_GT(friction, 0.1 * scale * c.friction);
        EXPECT_LT(worst / scale, 1e-10);
        State back;
        reduced.to_full(r, back);
        EXPECT_LT((back.u - s.u).cwiseAbs().maxCoeff() / s.u.cwiseAbs().maxCoeff(), 1e-10);
    }
}

// Field output of a 3D body: the tetrahedra as VTK_TETRA cells, every node's point.
TEST(Body3D, FieldOutputWritesTetrahedra) {
    Box b;
    SceneParameters p = box_scene(b, "box_field.msh", MassVariant::redistributed_normal);
    Stepper body(p);
    const Mesh& mesh = body.discretization().mesh;
    const std::string folder = ::testing::TempDir() + "field3d";
    FieldWriter writer(mesh, folder);
    writer.write(body.initial_state(-2e-5));
    std::ifstream in(folder + "/" + writer.file_name(0));
    std::stringstream text;
    text << in.rdbuf();
    EXPECT_NE(text.str().find("NumberOfPoints=\"" + std::to_string(mesh.num_nodes()) + "\" NumberOfCells=\"" +
                              std::to_string(mesh.num_cells()) + "\""),
              std::string::npos);
    EXPECT_EQ(mesh.num_cells(), 120u);
}

}  // namespace
}  // namespace contactbody
