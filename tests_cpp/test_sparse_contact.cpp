// The sparse contact solve (sparse_contact.hpp) against the condensed one (contact_solver.hpp)
// on the same substeps: the rectangle and three mesh bodies, every variant, with and without
// friction, static friction, damping, force control and the static start.
#include <gtest/gtest.h>

#include <algorithm>
#include <limits>
#include <memory>
#include <string>

#include "contact/sparse_contact.hpp"
#include "linalg/pattern_lu.hpp"
#include "linalg/trailing_cholesky.hpp"
#include "simulation/simulation.hpp"

using namespace contactbody;

namespace {

std::unique_ptr<Stepper> stepper_on(const SceneParameters& p, Stepper::ContactPath path) {
    auto s = std::make_unique<Stepper>(p);
    s->set_contact_path(path);
    return s;
}

struct Case {
    std::string name, mesh;
    int variant;
    double friction, static_ratio, beta;
    bool force_control, static_start;
};

void PrintTo(const Case& c, std::ostream* os) { *os << c.name; }

std::string data(const std::string& file) { return std::string(CONTACTBODY_TEST_DATA) + "/" + file; }

class SparseAgainstCondensed : public ::testing::TestWithParam<Case> {};

// Both paths from the same start (the static start each computes, or the paper's), then 40
// steps of 4 substeps (sliding, the top lifting and pressing again), each from the condensed
// path's state (the standard-mass variants amplify differences along a trajectory): the
// contact forces agree within 10 contact tolerances of the largest force so far (each solve
// meets the tolerance on its own residual, so two solutions can differ by a few; and where
// the body barely touches, its forces are a round-off of the inertia forces beside them),
// the energies within 1e-9 of the largest.
TEST_P(SparseAgainstCondensed, SameSolutions) {
    const Case& c = GetParam();
    SceneParameters p;
    p.mesh = c.mesh;
    if (c.mesh.empty()) p.nx = p.ny = 12;
    p.mass_matrix = static_cast<MassVariant>(c.variant);
    p.friction_coefficient = c.friction;
    p.static_friction_ratio = c.static_ratio;
    p.damping_stiffness = c.beta;
    p.internal_step = 2.5e-6;
    p.force_control = c.force_control;
    p.static_initial_state = c.static_start;
    const double top = -2.5e-5, force = 2e5;
    Simulation sparse(stepper_on(p, Stepper::ContactPath::sparse), top, 0, force);
    Simulation condensed(stepper_on(p, Stepper::ContactPath::condensed), top, 0, force);
    StepInputs in;
    in.foundation_velocity[0] = 5;
    in.top_force = force;
    int pressed = 0;
    double scale = 0;
    for (int k = 0; k < 40; ++k) {
        in.top_displacement = top * (1 - 0.6 * std::sin(0.15 * k));
        in.top_force = force * (1 + 0.5 * std::sin(0.15 * k));
        if (k > 0) sparse.restore(condensed.snapshot());
        sparse.do_step(1e-5, in);
        condensed.do_step(1e-5, in);
        const State& a = sparse.state();
        const State& b = condensed.state();
        ASSERT_EQ(a.lambda.size(), b.lambda.size());
        pressed += b.lambda.cwiseAbs().maxCoeff() > 0;
        scale = std::max(scale, b.lambda.cwiseAbs().maxCoeff());
        EXPECT_LE((a.lambda - b.lambda).cwiseAbs().maxCoeff(), 10 * p.contact_tolerance * scale)
            << c.name << " step " << k;
        const Observables& oa = sparse.observables();
        const Observables& ob = condensed.observables();
        const double energy =
            std::max({std::abs(ob.energy), std::abs(ob.kinetic_energy), std::abs(ob.strain_energy), 1e-30});
        EXPECT_LE(std::abs(oa.energy - ob.energy), 1e-9 * energy) << c.name << " step " << k;
        EXPECT_LE(std::abs(oa.kinetic_energy - ob.kinetic_energy), 1e-9 * energy) << c.name << " step " << k;
        EXPECT_LE(std::abs(oa.strain_energy - ob.strain_energy), 1e-9 * energy) << c.name << " step " << k;
        if (HasFailure()) return;
    }
    EXPECT_GE(pressed, 5) << c.name;  // the comparison saw contact
    EXPECT_TRUE(dynamic_cast<const Stepper&>(sparse.body()).sparse_contact());
    EXPECT_FALSE(dynamic_cast<const Stepper&>(condensed.body()).sparse_contact());
}

// The held factor's set and the kept GCR directions (and the last patterns) decide a sparse
// solve's last bits: a saved state keeps the one, saving or restoring a state drops the
// other, and a new factor starts at the state's own. So a restored state replays bit for bit
// in another simulation, and a restarted one computes a new one's bits.
TEST(SparseContactSolve, ReplaysBitForBit) {
    SceneParameters p;
    p.nx = p.ny = 12;
    p.friction_coefficient = 0.3;
    p.damping_stiffness = 4e-6;
    p.internal_step = 2.5e-6;
    const double top = -2.5e-5;
    const auto inputs = [&](int k) {
        StepInputs in;
        in.foundation_velocity[0] = 5;
        // Steady sliding (the kept directions last) until step 20, then lifting and pressing.
        in.top_displacement = k < 20 ? top : top * (1 - 0.8 * std::sin(0.3 * (k - 20)));
        return in;
    };
    Simulation a(stepper_on(p, Stepper::ContactPath::sparse), top);
    for (int k = 0; k < 15; ++k) a.do_step(1e-5, inputs(k));
    const SimulationSnapshot saved = a.snapshot();
    ASSERT_FALSE(saved.contact_factorization.pattern.empty());
    const std::vector<signed char>& held = saved.contact_factorization.pattern;  // slipping rows too
    ASSERT_TRUE(std::any_of(held.begin(), held.end(), [](signed char x) { return x == 3 || x == -3; }));
    for (int k = 15; k < 40; ++k) a.do_step(1e-5, inputs(k));
    Simulation b(stepper_on(p, Stepper::ContactPath::sparse), top);
    b.do_step(1e-5, inputs(7));  // another history: another held set and kept directions
    b.restore(saved);
    for (int k = 15; k < 40; ++k) b.do_step(1e-5, inputs(k));
    EXPECT_EQ(a.state().u, b.state().u);
    EXPECT_EQ(a.state().v, b.state().v);
    EXPECT_EQ(a.state().lambda, b.state().lambda);

    a.restart(p, top);
    Simulation c(stepper_on(p, Stepper::ContactPath::sparse), top);
    for (int k = 0; k < 25; ++k) {
        a.do_step(1e-5, inputs(k));
        c.do_step(1e-5, inputs(k));
    }
    EXPECT_EQ(a.state().u, c.state().u);
    EXPECT_EQ(a.state().lambda, c.state().lambda);
}

// What a benchmark takes as a substep's floor (bench_contact_scaling): one solve with the last
// substep's factor is a solve with the substep's matrix 4/dt^2 M + A + 2/dt C, on either path,
// where the body does not touch (no dof held).
TEST(Stepper, LastFactorSolvesTheSubstepMatrix) {
    SceneParameters p;
    p.nx = p.ny = 12;
    p.damping_stiffness = 4e-6;
    p.internal_step = 2.5e-6;
    p.initial_gap = 1e-3;
    for (const auto path : {Stepper::ContactPath::sparse, Stepper::ContactPath::condensed}) {
        auto owned = stepper_on(p, path);
        Stepper& stepper = *owned;
        EXPECT_THROW(stepper.last_factor(), std::logic_error);
        Simulation sim(std::move(owned), 0.0);
        StepInputs in;
        in.foundation_velocity[0] = 5;
        sim.do_step(1e-5, in);
        ASSERT_EQ(stepper.sparse_contact(), path == Stepper::ContactPath::sparse);
        const Discretization& d = stepper.discretization();
        const double dt = p.internal_step;
        const SparseMatrix K = (4 / (dt * dt)) * d.M_free + d.A_free + (2 / dt) * d.C_free;
        const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(K.rows(), -1, 2);
        Eigen::VectorXd x(K.rows());
        stepper.last_factor().solve(b, x);
        EXPECT_LT((K * x - b).norm(), 1e-12 * b.norm());
    }
}

INSTANTIATE_TEST_SUITE_P(
    Bodies, SparseAgainstCondensed,
    ::testing::Values(
        Case{"rectangle_v0", "", 0, 1.2, 1, 0, false, false},
        Case{"rectangle_v1", "", 1, 1.2, 1, 0, false, false},
        Case{"rectangle_v2", "", 2, 0.3, 1, 4e-6, false, false},
        Case{"rectangle_v3", "", 3, 0.3, 1.5, 0, false, false},
        Case{"rectangle_v4", "", 4, 0.0, 1, 0, false, false},
        Case{"rectangle_static", "", 1, 0.3, 1.5, 4e-6, false, true},
        Case{"rectangle_force", "", 1, 0.3, 1, 4e-6, true, false},
        Case{"tilted", data("outside/shape_20250629.msh"), 1, 0.3, 1, 4e-6, false, true},
        Case{"tilted_frictionless", data("outside/shape_20250629.msh"), 1, 0.0, 1, 4e-6, false, true},
        Case{"wavy", data("outside/shape_20250646.msh"), 3, 0.3, 1.5, 0, false, false},
        Case{"shape_20250651", data("outside/shape_20250651.msh"), 4, 0.6, 1, 4e-6, false, true}),
    [](const ::testing::TestParamInfo<Case>& info) { return info.param.name; });

}  // namespace

// A structurally symmetric matrix with other values below and above the diagonal, in a given
// order: the LU solves it to round-off, and says where a pivot is missing.
TEST(PatternLu, SolvesAMatrixOfSymmetricPatternInAGivenOrder) {
    const int n = 60;
    std::vector<Eigen::Triplet<double>> entries;
    for (int i = 0; i < n; ++i) entries.emplace_back(i, i, 10 + std::sin(i));
    for (int k = 0; k < 150; ++k) {
        const int i = (37 * k) % n, j = (11 * k + 5) % n;
        if (i == j) continue;
        entries.emplace_back(i, j, std::cos(k));
        entries.emplace_back(j, i, std::sin(3 * k));
    }
    SparseMatrix A(n, n);
    A.setFromTriplets(entries.begin(), entries.end());
    A.makeCompressed();
    std::vector<int> position(n);
    for (int i = 0; i < n; ++i) position[static_cast<size_t>(i)] = (7 * i) % n;  // 7 and 60 coprime
    PatternLu lu(A, position);
    ASSERT_TRUE(lu.factor(A.valuePtr()));
    const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(n, -1, 2);
    Eigen::VectorXd x;
    lu.solve(b, x);
    EXPECT_LT((Eigen::MatrixXd(A) * x - b).norm(), 1e-13 * b.norm());
    SparseMatrix singular = A;
    singular.coeffRef(0, 0) = 0;  // position 0 is factored first: no pivot there
    EXPECT_FALSE(lu.factor(singular.valuePtr()));
}

// Factoring again after a few values changed redoes only their columns and the columns above
// them in the elimination tree, and gives the bits that factoring all of them gives; after a
// factor that failed, all columns are factored again.
TEST(PatternLu, FactorsAgainOnlyWhatTheChangedValuesReach) {
    const int n = 400;  // a path graph in natural order: column j's ancestors are j + 1, ...
    std::vector<Eigen::Triplet<double>> entries;
    for (int i = 0; i < n; ++i) {
        entries.emplace_back(i, i, 4 + std::sin(i));
        if (i + 1 < n)
            entries.emplace_back(i, i + 1, std::cos(i)), entries.emplace_back(i + 1, i, std::sin(2 * i));
    }
    SparseMatrix A(n, n);
    A.setFromTriplets(entries.begin(), entries.end());
    A.makeCompressed();
    std::vector<int> position(n);
    for (int i = 0; i < n; ++i) position[static_cast<size_t>(i)] = i;
    PatternLu lu(A, position);
    ASSERT_TRUE(lu.factor(A.valuePtr()));
    EXPECT_EQ(lu.columns_factored(), n);
    ASSERT_TRUE(lu.factor(A.valuePtr()));
    EXPECT_EQ(lu.columns_factored(), 0);
    SparseMatrix changed = A;
    changed.coeffRef(n - 10, n - 11) *= 1.5;  // column n - 11 of A: it and the 10 after it
    ASSERT_TRUE(lu.factor(changed.valuePtr()));
    EXPECT_EQ(lu.columns_factored(), 11);
    PatternLu fresh(A, position);
    ASSERT_TRUE(fresh.factor(changed.valuePtr()));
    const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(n, -1, 2);
    Eigen::VectorXd x, y;
    lu.solve(b, x);
    fresh.solve(b, y);
    EXPECT_EQ(x, y);
    SparseMatrix singular = changed;
    singular.coeffRef(n - 1, n - 1) = 0;  // the last pivot: L and U all made before it fails
    singular.coeffRef(n - 1, n - 2) = 0;
    singular.coeffRef(n - 2, n - 1) = 0;
    EXPECT_FALSE(lu.factor(singular.valuePtr()));
    ASSERT_TRUE(lu.factor(changed.valuePtr()));
    EXPECT_EQ(lu.columns_factored(), n);
    lu.solve(b, x);
    EXPECT_EQ(x, y);
}

// The held operator with slipping rows: a held solve satisfies every equation of its system,
// K's rows where free, the held values, and r_x = sf r_y on each slipping node (r = K x - b),
// which is what the sparse contact solve reads of it.
TEST(HeldOperator, SlippingRowsHoldTheirSlipLaw) {
    SceneParameters p;
    p.nx = p.ny = 6;
    p.friction_coefficient = 0.3;
    const Stepper body(p);
    const Discretization& d = body.discretization();
    const double dt = 1e-6;
    const SparseMatrix K = (4.0 / (dt * dt)) * d.M_free + d.A_free;
    HeldOperator held(K, d.contact_unknowns(), 2);
    held.set_slip_coefficient(0.3);
    const Eigen::Index n = held.unknowns() / 2;
    std::vector<char> hold(static_cast<size_t>(2 * n), 0);
    std::vector<double> slip(static_cast<size_t>(n), 0.0);
    for (Eigen::Index i = 0; i < n; ++i) {  // open, sticking, slipping either way, pressed
        hold[static_cast<size_t>(i)] = i % 4 != 0;
        hold[static_cast<size_t>(n + i)] = i % 4 == 1;
        slip[static_cast<size_t>(i)] = i % 4 == 2 ? 1 : i % 4 == 3 ? -1 : 0;
    }
    held.hold(hold, slip);
    ASSERT_EQ(held.slip(), slip);  // the LU found its pivots
    Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(K.rows(), -1e3, 2e3), values(2 * n), x;
    for (Eigen::Index j = 0; j < 2 * n; ++j) values[j] = 1e-6 * (j % 5 - 2);
    const Eigen::VectorXd rhs = b;
    held.impose(b, values);
    held.solve(b, x);
    const Eigen::VectorXd r = K * x - rhs;
    std::vector<char> contact(static_cast<size_t>(K.rows()), 0);
    for (Eigen::Index j = 0; j < 2 * n; ++j) contact[static_cast<size_t>(held.dof(j))] = 1;
    for (Eigen::Index k = 0; k < K.rows(); ++k)
        if (!contact[static_cast<size_t>(k)]) EXPECT_NEAR(r[k], 0, 1e-9 * rhs.norm()) << "free row " << k;
    for (Eigen::Index i = 0; i < n; ++i) {
        const int y = held.dof(i), xdof = held.dof(n + i);
        if (hold[static_cast<size_t>(i)])
            EXPECT_DOUBLE_EQ(x[y], values[i]);
        else
            EXPECT_NEAR(r[y], 0, 1e-9 * rhs.norm());
        if (hold[static_cast<size_t>(n + i)])
            EXPECT_DOUBLE_EQ(x[xdof], values[n + i]);
        else
            EXPECT_NEAR(r[xdof] - slip[static_cast<size_t>(i)] * 0.3 * r[y], 0, 1e-9 * rhs.norm())
                << "node " << i;
    }
}

namespace {
// Steady sliding on the 40 x 40 rectangle (forced onto the sparse solve), 11 steps of 10
// substeps from a static start; with snapshots, a state saved before each step (as an importer
// that can go back a step does), which drops GCR's kept directions there.
struct SlidingRun {
    long solves = 0, iterations = 0, krylov = 0, warm = 0;  // over the steps
    Eigen::VectorXd lambda;
    std::vector<signed char> factor_pattern;
};

SlidingRun slide_rectangle(Stepper::ContactPath path, bool snapshots) {
    SceneParameters p;
    p.nx = p.ny = 40;
    p.friction_coefficient = 0.3;
    p.damping_stiffness = 4e-6;
    p.internal_step = 1e-6;
    p.static_initial_state = true;
    const double top = -5e-6;
    StepInputs in;
    in.foundation_velocity[0] = 20;
    in.top_displacement = top;
    auto owned = stepper_on(p, path);
    const Stepper& body = *owned;
    Simulation sim(std::move(owned), top);
    SlidingRun run;
    const long solves = body.sparse_solver().solves(), krylov = body.sparse_solver().krylov_iterations(),
               warm = body.sparse_solver().warm_starts();
    for (int step = 0; step < 11; ++step) {
        if (snapshots) sim.snapshot();
        sim.do_step(1e-5, in);
        run.iterations += sim.statistics().contact_iterations;
    }
    run.solves = body.sparse_solver().solves() - solves;
    run.krylov = body.sparse_solver().krylov_iterations() - krylov;
    run.warm = body.sparse_solver().warm_starts() - warm;
    run.lambda = sim.state().lambda;
    run.factor_pattern = body.contact_factorization().pattern;
    return run;
}
// The 156-contact-node hemisphere sliding undamped at F = 0.3 from the static start (under a
// top displacement of -2e-4 m).
SceneParameters hemisphere_sliding() {
    SceneParameters p;
    p.mesh = data("hemisphere_156.msh");
    p.dimension = 3;
    p.friction_coefficient = 0.3;
    p.internal_step = 1e-6;
    p.static_initial_state = true;
    return p;
}
}  // namespace

// A 2D body's factor holds its slipping rows: steady sliding leaves GCR only what differs
// from the factor's pattern. Where GCR's directions go at every step (a state saved at each),
// the rectangle made 119 held solves in its 11 steps against 571 with the slips left to GCR;
// the same states either way. And a Newton iteration costs one held solve and one for each
// GCR iteration: the solution after GCR is its directions' solutions combined, not solved
// again (it was: 161 = 113 iterations + 8 GCR + 40 such solves, and 693 with the slips left to
// GCR; then 121 = 113 + 8, and 577 = 117 + 460), except where the combination would lose
// digits (allowed here in a tenth of the iterations); and a Newton iteration after the first
// on the same factor starts from the last one's solution, without a held solve of its own
// (now 119 = 113 - 2 warm + 8, and 571 = 115 - 5 + 460 + 1).
TEST(SparseContactSolve, SlippingRowsInTheFactorSaveMostHeldSolves) {
    SlidingRun runs[2];
    int k = 0;
    for (const auto path : {Stepper::ContactPath::sparse, Stepper::ContactPath::sparse_gcr}) {
        const SlidingRun& run = runs[k++] = slide_rectangle(path, true);
        EXPECT_GE(run.solves, run.iterations - run.warm + run.krylov);
        EXPECT_LE(10 * (run.solves - run.iterations + run.warm - run.krylov), run.iterations);
        const std::vector<signed char>& pattern = run.factor_pattern;
        EXPECT_EQ(
            std::any_of(pattern.begin(), pattern.end(), [](signed char x) { return x == 3 || x == -3; }),
            path == Stepper::ContactPath::sparse);
    }
    EXPECT_LT(2 * runs[0].solves, runs[1].solves);
    EXPECT_LE((runs[0].lambda - runs[1].lambda).cwiseAbs().maxCoeff(),
              10 * SceneParameters{}.contact_tolerance * runs[1].lambda.cwiseAbs().maxCoeff());
}

// Undamped 3D sliding, where many slipping nodes have a rho above max_held_ratio: a solve's
// first Newton iteration (no iterate's rho yet) holds the slips the factor holds. It held every
// slip there, and the next iteration's rho dropped most of them: two refactorizations a
// substep (80 in 40 substeps on this 156-contact-node hemisphere, the substep 8x slower;
// docs/decisions.md, "A 3D body's factor holds its slipping nodes"). The mesh is
// contactbody.meshes.hemisphere(radius=0.05, contact_size=7e-4, far_size=2.5e-2,
// fine_distance=0.0045, refine_distance=0.015, contact_angle=12.0).
TEST(SparseContactSolve, UndampedSlidingKeepsItsFactor) {
    const SceneParameters p = hemisphere_sliding();
    const double top = -2e-4;
    std::unique_ptr<Stepper> automatic = stepper_on(p, Stepper::ContactPath::automatic);
    std::unique_ptr<Stepper> gcr = stepper_on(p, Stepper::ContactPath::sparse_gcr);
    const Stepper &a = *automatic, &g = *gcr;
    Simulation sa(std::move(automatic), top), sg(std::move(gcr), top);
    StepInputs in;
    in.foundation_velocity[0] = 20;
    in.top_displacement = top;
    const long before = a.sparse_refactorizations();
    for (int k = 0; k < 4; ++k) {
        sa.do_step(1e-5, in);
        sg.do_step(1e-5, in);
    }
    EXPECT_TRUE(a.sparse_contact());
    EXPECT_GT(sa.observables().normal_force, 0);
    EXPECT_NEAR(sa.observables().normal_force, sg.observables().normal_force,
                1e-8 * sg.observables().normal_force);
    RecordProperty("refactorizations", std::to_string(a.sparse_refactorizations() - before) +
                                           " in 40 substeps, " + std::to_string(g.sparse_refactorizations()) +
                                           " by GCR");
    EXPECT_LE(a.sparse_refactorizations() - before, 4);
}

// A hemisphere pressed from rest in one quasi-static load step (a static start's load path):
// the first iterate pushes twice the contact zone through the foundation, and Newton's
// patterns shrink to it over several iterations. Solved loosely where the last iteration
// changed the pattern (ContactSolverOptions::inexact_forcing), they take fewer held solves
// than solved to the tolerance, to the same solution (docs/decisions.md, "The static start's
// load path solves its early patterns loosely").
TEST(SparseContactSolve, ChangingPatternsSolvedLooselyReachTheSameSolution) {
    SceneParameters p;
    p.mesh = data("hemisphere_156.msh");
    p.dimension = 3;
    p.mass_matrix = MassVariant::standard_implicit_contact;
    struct Run {
        State s;
        SubstepReport report;
        long solves;
    };
    const auto press = [&](Stepper::ContactPath path, double forcing) {
        Stepper body(p);
        body.set_contact_path(path);
        body.contact_options().inexact_forcing = forcing;
        Run r{body.initial_state(0), {}, 0};
        r.s.v.setZero();
        SubstepLoad load;
        load.top_start = 0;
        load.top_end = -2e-4;
        r.report = body.substep(r.s, 1e3, load);
        r.solves = body.sparse_solver().solves();
        return r;
    };
    const Run loose = press(Stepper::ContactPath::sparse, 0.1);
    const Run tight = press(Stepper::ContactPath::sparse, 0);
    const Run condensed = press(Stepper::ContactPath::condensed, 0.1);
    RecordProperty("held_solves", std::to_string(loose.solves) + " loosely, " + std::to_string(tight.solves) +
                                      " to the tolerance");
    EXPECT_GE(tight.report.contact_iterations, 4);
    EXPECT_LT(loose.solves, tight.solves);
    for (const Run* r : {&loose, &tight}) {
        EXPECT_EQ(r->report.active_nodes, condensed.report.active_nodes);
        EXPECT_NEAR(r->report.normal_force, condensed.report.normal_force, 1e-8 * condensed.report.normal_force);
        EXPECT_NEAR((r->s.u - condensed.s.u).lpNorm<Eigen::Infinity>(), 0,
                    1e-8 * condensed.s.u.lpNorm<Eigen::Infinity>());
    }
}

// A frictionless static start on a curved boundary is one quasi-static substep whose early
// patterns are solved loosely. residual() measures the contact law at a solved iterate and
// takes its body equation as exact, so a loosely solved iterate that met the tolerance ended
// the solve out of balance by up to the loose goal: the 156-node hemisphere's start was
// refused at these clamp displacements (the contact carried 557.887 N, the top 557.890 N at
// -0.2 mm) until such an iterate was solved once more to the tolerance.
TEST(SparseContactSolve, AStaticStartWhoseLastPatternWasSolvedLooselyIsInBalance) {
    for (const double top : {-1e-4, -2e-4, -3e-4}) {
        SceneParameters p;
        p.mesh = data("hemisphere_156.msh");
        p.dimension = 3;
        p.friction_coefficient = 0;
        p.static_initial_state = true;
        std::unique_ptr<Simulation> sim;
        ASSERT_NO_THROW(sim = std::make_unique<Simulation>(p, top)) << "top " << top;
        const Observables& o = sim->observables();
        EXPECT_GT(o.normal_force, 0);
        EXPECT_NEAR(o.normal_force, -o.top_reaction[1], 1e-10 * o.normal_force) << "top " << top;
    }
}

// GCR's kept directions outlast a communication step: they go only where a state is saved or
// restored, which replays the same way (ReplaysBitForBit). Left with the slips (most of its
// directions), GCR made 571 held solves in the 11 steps with a state saved before each (460 in
// GCR), and 153 without (42 in GCR), to the same state within the contact tolerance.
TEST(SparseContactSolve, KeptDirectionsOutlastCommunicationSteps) {
    const SlidingRun kept = slide_rectangle(Stepper::ContactPath::sparse_gcr, false);
    const SlidingRun dropped = slide_rectangle(Stepper::ContactPath::sparse_gcr, true);
    EXPECT_LT(2 * kept.solves, dropped.solves);
    EXPECT_LT(2 * kept.krylov, dropped.krylov);
    EXPECT_LE((kept.lambda - dropped.lambda).cwiseAbs().maxCoeff(),
              10 * SceneParameters{}.contact_tolerance * dropped.lambda.cwiseAbs().maxCoeff());
}

// On a supernodal factor of options.wide_span_nonzeros nonzeros or more GCR keeps up to
// wide_span_directions directions instead of max_directions, so that once they span the
// slipping nodes' unknowns a Newton iteration needs few held solves, and their images are
// orthonormalized all at once in the factor's dense kernels (orthonormalize_all;
// docs/decisions.md, "GCR's kept directions span the slips"). Undamped sliding on the 156-node
// hemisphere, whose slips have a rho above max_held_ratio (GCR's), its factor made supernodal:
// the same normal force and energies as with max_directions, in fewer held solves.
TEST(SparseContactSolve, AWideSpanOfKeptDirectionsSolvesTheSlipsInFewerHeldSolves) {
    const SceneParameters p = hemisphere_sliding();
    const double top = -2e-4;
    struct Run {
        long solves;
        Observables observables;
    };
    const auto slide = [&](double wide_span_nonzeros) {
        auto owned = stepper_on(p, Stepper::ContactPath::automatic);
        owned->set_supernodal_factor(true);
        owned->contact_options().wide_span_nonzeros = wide_span_nonzeros;
        Stepper& body = *owned;
        Simulation sim(std::move(owned), top);
        StepInputs in;
        in.foundation_velocity[0] = 20;
        in.top_displacement = top;
        sim.do_step(1e-5, in);  // the start of sliding
        const long before = body.sparse_solver().solves();
        for (int k = 0; k < 6; ++k) sim.do_step(1e-5, in);
        EXPECT_TRUE(body.sparse_contact());
        EXPECT_EQ(body.last_factor().kernel(), TrailingCholesky::Kernel::supernodal);
        return Run{body.sparse_solver().solves() - before, sim.observables()};
    };
    const Run wide = slide(0), narrow = slide(std::numeric_limits<double>::infinity());
    RecordProperty("held_solves", std::to_string(wide.solves) + " with the wide span, " +
                                      std::to_string(narrow.solves) + " with max_directions");
    EXPECT_GT(narrow.observables.normal_force, 0);
    EXPECT_NEAR(wide.observables.normal_force, narrow.observables.normal_force,
                1e-8 * narrow.observables.normal_force);
    const double energy = std::abs(narrow.observables.energy);
    EXPECT_NEAR(wide.observables.energy, narrow.observables.energy, 1e-9 * energy);
    EXPECT_NEAR(wide.observables.friction_dissipation, narrow.observables.friction_dissipation, 1e-9 * energy);
    EXPECT_LT(3 * wide.solves, 2 * narrow.solves);
}
