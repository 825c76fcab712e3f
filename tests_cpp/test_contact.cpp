// The condensed contact solve: the paper's section 6 example and failures.
#include <gtest/gtest.h>

#include <random>
#include <tuple>

#include "contact/contact_solver.hpp"
#include "contact/elementary_example.hpp"
#include "contact/friction_law.hpp"
#include "contact/sliding_product.hpp"

using namespace contactbody;

namespace {

// Section 6 with lambda = mu = 1, dt = 1, u_tau_old = 0.1: a, b, c from (m1, m2).
ElementaryExample elementary(double m1, double m2, double F) {
    return ElementaryExample::from_material(1, 1, 1, m1, m2, F, 0.1);
}

// The region (1-4) whose closed form holds at f, or 0 within `margin` of a region boundary.
int single_region(const ElementaryExample& e, const Eigen::Vector2d& f, double margin) {
    int region = 0;
    for (int i = 1; i <= 4; ++i)
        if (e.in_sigma(i, f, -margin)) {
            if (region != 0 || !e.in_sigma(i, f, margin)) return 0;
            region = i;
        }
    return region;
}

}  // namespace

TEST(ElementaryExample, LocalSolveMatchesClosedFormInRegionsS1ToS4) {
    // m1 = 0 (normal mass removed), m2 = 0.25 > 0: c/b = 3.
    for (double F : {0.3, 1.2, 2.5}) {
        const ElementaryExample e = elementary(0, 0.25, F);
        ASSERT_LT(F, e.c() / e.b());
        std::mt19937 rng(42);
        std::uniform_real_distribution<double> f(-3, 3);
        int seen[5] = {0, 0, 0, 0, 0};
        ContactSolver solver;
        for (int trial = 0; trial < 20000; ++trial) {
            const Eigen::Vector2d load(f(rng), f(rng));
            const int r = single_region(e, load, 1e-6);
            if (r == 0) continue;
            ++seen[r];
            const ContactProblem p = e.problem(load);
            Eigen::VectorXd lambda = Eigen::VectorXd::Zero(2);
            solver.solve(p, ContactSolverOptions{1e-12, 100}, lambda);
            const Eigen::VectorXd u = p.a + p.W * lambda;
            const Eigen::Vector4d got(u[0], u[1], lambda[0], lambda[1]);
            const Eigen::Vector4d want = e.closed_form(r, load);
            EXPECT_LE((got - want).cwiseAbs().maxCoeff(), 1e-10 * (1 + want.cwiseAbs().maxCoeff()))
                << "F = " << F << ", region S" << r << ", f = " << load.transpose();
        }
        for (int r = 1; r <= 4; ++r) EXPECT_GT(seen[r], 50) << "region S" << r << " sampled";
    }
}

// The transcription of the paper: S_i(f) solves (23) exactly when f is in sigma_i.
TEST(ElementaryExample, ClosedFormSolvesTheStepExactlyOnItsSet) {
    for (const ElementaryExample& e : {elementary(0, 0.25, 2.5), elementary(0.25, 0, 2.5),
                                       elementary(0, 0, 0.5), elementary(0.25, 0, 4)}) {
        std::mt19937 rng(7);
        std::uniform_real_distribution<double> f(-3, 3);
        int inside[5] = {0, 0, 0, 0, 0};
        for (int trial = 0; trial < 20000; ++trial) {
            const Eigen::Vector2d load(f(rng), f(rng));
            for (int i = 1; i <= 4; ++i) {
                const double violation = e.violation(load, e.closed_form(i, load));
                if (e.in_sigma(i, load, 1e-6)) {
                    ++inside[i];
                    EXPECT_LE(violation, 1e-12) << "S" << i << " at " << load.transpose();
                } else if (!e.in_sigma(i, load, -1e-6)) {
                    EXPECT_GT(violation, 1e-9) << "S" << i << " at " << load.transpose();
                }
            }
        }
        for (int i = 1; i <= 4; ++i) EXPECT_GT(inside[i], 50) << "sigma_" << i << " sampled";
    }
}

// Section 6's point: with the tangential mass removed (m1 > 0, m2 = 0) and F > c/b the step has
// three solutions inside sigma_4 = sigma_1 cap sigma_2, and the contact solver reaches each of
// them from some start; with m1 = 0, m2 > 0 (this FMU's redistributed_normal) the same F and
// load give one solution, whatever the start.
TEST(ElementaryExample, SeveralSolutionsOnlyWithoutTangentialMass) {
    const double F = 2.5;
    const ElementaryExample without_tangential = elementary(0.25, 0, F);  // c/b = 2
    const ElementaryExample without_normal = elementary(0, 0.25, F);      // c/b = 3
    ASSERT_GT(F, without_tangential.c() / without_tangential.b());
    ASSERT_LT(F, without_normal.c() / without_normal.b());
    ContactSolver solver;
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> f(-3, 3);
    int multiple = 0;
    for (int trial = 0; trial < 10000; ++trial) {
        const Eigen::Vector2d load(f(rng), f(rng));
        const auto many = without_tangential.solver_solutions(load, solver);
        const auto closed = without_tangential.closed_form_solutions(load);
        if (without_tangential.in_sigma(4, load, 1e-3)) {
            ++multiple;
            ASSERT_EQ(closed.size(), 3u) << load.transpose();
            ASSERT_EQ(many.size(), 3u) << load.transpose();
            int regions = 0;
            for (const ElementarySolution& s : many) {
                regions |= 1 << s.region;
                EXPECT_LE(without_tangential.violation(load, s.x), 1e-9);
            }
            EXPECT_EQ(regions, (1 << 1) | (1 << 2) | (1 << 4)) << load.transpose();
        } else if (!without_tangential.in_sigma(4, load, -1e-3)) {
            EXPECT_EQ(many.size(), 1u) << load.transpose();
        }
        EXPECT_EQ(without_normal.solver_solutions(load, solver).size(), 1u) << load.transpose();
    }
    EXPECT_GT(multiple, 100);
}

// F = c/b: on the half-line sigma_5 the solutions form the segment S_5 between S_1 and S_2;
// different starts reach different points of it, and each solves (23).
TEST(ElementaryExample, CriticalFrictionGivesASegmentOfSolutions) {
    const ElementaryExample e = elementary(0.25, 0, 2);  // c/b = 2
    ASSERT_EQ(e.friction() * e.b(), e.c());
    ContactSolver solver;
    for (double fn : {0.0, 0.5, 2.0}) {
        const Eigen::Vector2d load(fn, -e.c() / e.b() * fn);
        ASSERT_TRUE(e.in_sigma5(load, 1e-12));
        const auto found = e.solver_solutions(load, solver);
        EXPECT_GE(found.size(), 2u) << load.transpose();
        for (const ElementarySolution& s : found) {
            EXPECT_LE(e.violation(load, s.x), 1e-9);
            EXPECT_GE(s.x[1], -fn / e.b() - 1e-9);  // u_tau within [-f_nu / b, u_tau_old]
            EXPECT_LE(s.x[1], e.u_tau_old() + 1e-9);
        }
    }
}

TEST(ContactSolver, NonConvergenceIsAnError) {
    const ElementaryExample e(2, 1, 3, 0.5, 0.1);
    const ContactProblem p = e.problem({1, 2});  // region S3: needs iterations from zero
    Eigen::VectorXd lambda = Eigen::VectorXd::Zero(2);
    ContactSolver solver;
    EXPECT_THROW(solver.solve(p, ContactSolverOptions{1e-10, 0, 0}, lambda), ContactSolveError);
}

TEST(ContactSolver, OpenContactNeedsNoIteration) {
    const ElementaryExample e(2, 1, 3, 0.5, 0.1);
    const ContactProblem p = e.problem({-1, 0.5});  // region S1: lambda = 0
    Eigen::VectorXd lambda = Eigen::VectorXd::Zero(2);
    ContactSolver solver;
    EXPECT_EQ(solver.solve(p, ContactSolverOptions{1e-10, 0}, lambda).iterations, 0);
    EXPECT_EQ(lambda.cwiseAbs().maxCoeff(), 0.0);
}

TEST(ContactSolver, FrictionlessProblemHasNoTangentialUnknowns) {
    ContactProblem p;
    p.W = Eigen::MatrixXd::Identity(3, 3) * 2;
    p.W(0, 1) = p.W(1, 0) = 0.5;
    p.a = Eigen::Vector3d(1, -1, 0.5);
    p.gap_limit = Eigen::VectorXd::Zero(3);
    p.slip_origin = Eigen::VectorXd::Zero(3);
    ASSERT_FALSE(p.has_friction());
    Eigen::VectorXd lambda;
    ContactSolver solver;
    solver.solve(p, ContactSolverOptions{1e-12, 50}, lambda);
    const Eigen::VectorXd u = p.a + p.W * lambda;
    for (int i = 0; i < 3; ++i) {
        EXPECT_LE(lambda[i], 0);
        EXPECT_LE(u[i], 1e-12);
        EXPECT_LE(std::abs(lambda[i] * u[i]), 1e-12);
    }
}

// A slip-rate law on a random 6-node problem (W symmetric positive definite, nodes
// pressed and driven to slip). Newton with the full Jacobian and the Gauss-Seidel fallback
// (forced by max_iterations = 0) reach the same solution, and at it every slipping node's
// friction is F(v) at its own slip rate, every sticking node's within F(0).
TEST(ContactSolver, SlipRateLawSolvedByNewtonAndByGaussSeidel) {
    const int n = 6;
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> u(-1, 1);
    Eigen::MatrixXd R(2 * n, 2 * n);
    for (int i = 0; i < 2 * n; ++i)
        for (int j = 0; j < 2 * n; ++j) R(i, j) = u(rng);
    ContactProblem p;
    p.W = 0.1 * R * R.transpose() + Eigen::MatrixXd::Identity(2 * n, 2 * n);
    p.a.resize(2 * n);
    for (int i = 0; i < n; ++i) {
        p.a[i] = 0.5 + 0.2 * u(rng);                      // pressed
        p.a[n + i] = (i % 3 == 0 ? 0.05 : 2.0) * u(rng);  // some stick, most slip
    }
    p.gap_limit = Eigen::VectorXd::Zero(n);
    p.slip_origin = Eigen::VectorXd::Zero(n);
    p.friction = Eigen::VectorXd::Constant(n, 0.3);
    p.rate.excess = 0.2;
    p.rate.stribeck_velocity = 0.5;
    p.rate.viscous = 0.05;
    p.rate.slip_time = 0.1;
    ASSERT_TRUE(p.rate_dependent());

    ContactSolver newton_solver, gs_solver;
    Eigen::VectorXd newton = Eigen::VectorXd::Zero(2 * n), gs = newton;
    const ContactSolveInfo a = newton_solver.solve(p, ContactSolverOptions{1e-13, 100, 0}, newton);
    EXPECT_EQ(a.sweeps, 0);
    const ContactSolveInfo b = gs_solver.solve(p, ContactSolverOptions{1e-13, 0, 100000}, gs);
    EXPECT_GT(b.sweeps, 0);
    EXPECT_LE((newton - gs).lpNorm<Eigen::Infinity>(), 1e-10 * newton.lpNorm<Eigen::Infinity>());

    const Eigen::VectorXd uh = p.a + p.W * newton;
    int slipping = 0, sticking = 0;
    for (int i = 0; i < n; ++i) {
        const double N = -newton[i], T = newton[n + i], slip = uh[n + i] - p.slip_origin[i];
        ASSERT_GT(N, 0);
        EXPECT_NEAR(uh[i], p.gap_limit[i], 1e-12);
        if (std::abs(slip) > 1e-12) {
            ++slipping;
            EXPECT_NEAR(std::abs(T), p.coefficient(i, slip) * N, 1e-11);
            EXPECT_LT(T * slip, 0);  // friction opposes the slip
        } else {
            ++sticking;
            EXPECT_LE(std::abs(T), p.coefficient(i, 0) * N + 1e-11);
        }
    }
    EXPECT_GT(slipping, 0);
    EXPECT_GT(sticking, 0);
}

// Isotropic friction (3D): where Newton fails (here: allowed no iteration), the node-by-node
// fallback solves the disc problem exactly, with Coulomb's law and with the slip-rate law at
// each node's own slip; both give Newton's multipliers. Before, a failed 3D Newton had no
// fallback: the substep was halved, and where halving did not help, the step failed.
TEST(ContactSolver, DiscProblemSolvedByNewtonAndNodeByNode) {
    const int n = 6, m = 3 * n;
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> u(-1, 1);
    Eigen::MatrixXd R(m, m);
    for (int i = 0; i < m; ++i)
        for (int j = 0; j < m; ++j) R(i, j) = u(rng);
    for (const bool rate : {false, true}) {
        SCOPED_TRACE(rate);
        ContactProblem p;
        p.tangents = 2;
        p.W = 0.1 * R * R.transpose() + Eigen::MatrixXd::Identity(m, m);
        p.a.resize(m);
        for (int i = 0; i < n; ++i) {
            p.a[i] = 0.5 + 0.2 * u(rng);                  // pressed
            const double size = i % 3 == 0 ? 0.05 : 2.0;  // some stick, most slip
            p.a[n + i] = size * u(rng);
            p.a[2 * n + i] = size * u(rng);
        }
        p.gap_limit = Eigen::VectorXd::Zero(n);
        p.slip_origin = Eigen::VectorXd::Zero(2 * n);
        p.friction = Eigen::VectorXd::Constant(n, 0.3);
        if (rate) {
            p.rate.excess = 0.2;
            p.rate.stribeck_velocity = 0.5;
            p.rate.viscous = 0.05;
            p.rate.slip_time = 0.1;
        }
        ASSERT_EQ(p.rate_dependent(), rate);
        ContactSolver newton_solver, node_solver;
        Eigen::VectorXd newton = Eigen::VectorXd::Zero(m), nodes = newton;
        const ContactSolveInfo a = newton_solver.solve(p, ContactSolverOptions{1e-13, 100, 0}, newton);
        EXPECT_EQ(a.sweeps, 0);
        const ContactSolveInfo b = node_solver.solve(p, ContactSolverOptions{1e-13, 0, 100000}, nodes);
        EXPECT_GT(b.sweeps, 0);
        EXPECT_LE(b.residual, 1e-13);
        EXPECT_LE((newton - nodes).lpNorm<Eigen::Infinity>(), 1e-10 * newton.lpNorm<Eigen::Infinity>());
        const Eigen::VectorXd uh = p.a + p.W * nodes;
        int slipping = 0, sticking = 0;
        for (int i = 0; i < n; ++i) {
            const double N = -nodes[i];
            const Eigen::Vector2d T(nodes[n + i], nodes[2 * n + i]), slip(uh[n + i], uh[2 * n + i]);
            ASSERT_GT(N, 0);
            EXPECT_NEAR(uh[i], 0, 1e-12);
            if (slip.norm() > 1e-12) {
                ++slipping;
                EXPECT_NEAR(T.norm(), p.coefficient(i, slip.norm()) * N, 1e-11);
                EXPECT_NEAR(T.dot(slip), -T.norm() * slip.norm(), 1e-11);  // opposite the slip
            } else {
                ++sticking;
                EXPECT_LE(T.norm(), p.coefficient(i, 0) * N + 1e-11);
            }
        }
        EXPECT_GT(slipping, 0);
        EXPECT_GT(sticking, 0);
    }
}

// Solves that follow each other as in a substep sequence (one W, the load drifting so that
// a few nodes change state between solves): the solver that updates its factorization
// (update_factorization) reaches the same multipliers as the one that refactors, in as many
// Newton iterations, with most of its factorizations replaced by updates; so does the one
// that also projects slipping nodes onto their Coulomb bound (project_slip), whose solves a
// fresh solver repeats bit for bit once told the factored pattern (factor_at), and so does the
// full generalized Jacobian's Newton (reduced_newton false, the method of two tangents), which
// factors at every iteration. W is scaled as a compliance (1e-9), so that the update cannot
// lean on entries of order one.
TEST(ContactSolver, UpdatedFactorizationAndProjectedSlipSolveAsARefactoredOne) {
    const int n = 160;
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> u(-1, 1);
    Eigen::MatrixXd R(2 * n, 2 * n);
    for (int i = 0; i < 2 * n; ++i)
        for (int j = 0; j < 2 * n; ++j) R(i, j) = u(rng);
    ContactProblem p;
    const double scale = 1e-9;
    p.W = scale * (0.02 * R * R.transpose() + Eigen::MatrixXd::Identity(2 * n, 2 * n));
    p.revision = ContactProblem::next_revision();
    p.gap_limit = Eigen::VectorXd::Zero(n);
    p.slip_origin = Eigen::VectorXd::Zero(n);
    p.friction = Eigen::VectorXd::Constant(n, 0.3);
    p.a.resize(2 * n);
    Eigen::VectorXd phase(n);
    for (int i = 0; i < n; ++i) phase[i] = 3 * u(rng);

    ContactSolver refactoring, updating, projecting, full;
    ContactSolverOptions refactor_options{1e-12, 100}, update_options{1e-12, 100}, full_options{1e-12, 100};
    full_options.reduced_newton = false;
    update_options.update_factorization = true;
    ContactSolverOptions project_options = update_options;
    project_options.project_slip = true;
    Eigen::VectorXd a_lambda = Eigen::VectorXd::Zero(2 * n), b_lambda = a_lambda, c_lambda = a_lambda,
                    d_lambda = a_lambda;
    long a_iterations = 0, b_iterations = 0, c_iterations = 0, d_iterations = 0, replayed = 0;
    for (int step = 0; step < 200; ++step) {
        const double t = 0.004 * step;
        for (int i = 0; i < n; ++i) {
            p.a[i] = scale * (0.6 * std::sin(t + phase[i]) + 0.3);        // pressed, or lifting off
            p.a[n + i] = scale * 0.3 * std::cos(1.3 * t + 2 * phase[i]);  // sticking or slipping
        }
        // A solver with no past, given the projecting one's factored pattern and warm start,
        // repeats its solve bit for bit (what a restored state relies on).
        const std::vector<signed char> base = projecting.factored_pattern(p.revision);
        Eigen::VectorXd replay = c_lambda;
        a_iterations += refactoring.solve(p, refactor_options, a_lambda).iterations;
        b_iterations += updating.solve(p, update_options, b_lambda).iterations;
        c_iterations += projecting.solve(p, project_options, c_lambda).iterations;
        d_iterations += full.solve(p, full_options, d_lambda).iterations;
        ASSERT_LE((a_lambda - d_lambda).lpNorm<Eigen::Infinity>(), 1e-10 * a_lambda.lpNorm<Eigen::Infinity>())
            << "step " << step;
        ASSERT_LE((a_lambda - b_lambda).lpNorm<Eigen::Infinity>(), 1e-10 * a_lambda.lpNorm<Eigen::Infinity>())
            << "step " << step;
        ASSERT_LE((a_lambda - c_lambda).lpNorm<Eigen::Infinity>(), 1e-10 * a_lambda.lpNorm<Eigen::Infinity>())
            << "step " << step;
        if (step % 20 == 7 && !base.empty()) {
            ContactSolver fresh;
            fresh.factor_at(base);
            fresh.solve(p, project_options, replay);
            ASSERT_TRUE(replay == c_lambda) << "step " << step;
            ++replayed;
        }
    }
    EXPECT_EQ(a_iterations, b_iterations);
    EXPECT_EQ(a_iterations, c_iterations);
    EXPECT_GT(d_iterations, 0);
    EXPECT_EQ(full.factorizations(), d_iterations);
    EXPECT_LT(refactoring.factorizations(), d_iterations / 2);  // the reduced system's LU is reused
    EXPECT_GT(replayed, 5);
    EXPECT_EQ(refactoring.factorization_updates(), 0);
    EXPECT_GT(updating.factorization_updates(), 100);  // measured: 95 against 21 and 176 updates
    EXPECT_LT(updating.factorizations(), refactoring.factorizations() / 3);
    // The projection skips the explicit part's product and reads half of W while nodes slide,
    // with as many residual evaluations.
    EXPECT_EQ(projecting.residual_evaluations(), updating.residual_evaluations());
}

// rate_solutions() finds the solutions directly (the slip equation's roots); with no rate
// dependence it must give the paper's closed forms S1-S4, load by load, for the three mass
// distributions of Figs. 3-4.
// M lambda through M_C = M_N - M_T diag(s): equal to the plain product within round-off; its
// bits a function of lambda alone (the same lambda after another history gives the same bits);
// declined where many corrections are nonzero.
TEST(SlidingProduct, EqualsThePlainProductAndDependsOnLambdaAlone) {
    constexpr Eigen::Index n = 24, rows = 40;
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> u(-1, 1);
    const Eigen::MatrixXd M = Eigen::MatrixXd::NullaryExpr(rows, 2 * n, [&] { return u(rng); });
    const Eigen::VectorXd F = Eigen::VectorXd::Constant(n, 0.3);
    const auto multipliers = [&](int stuck) {  // nodes slide (lambda_T = -+F lambda_N) but `stuck`
        Eigen::VectorXd l(2 * n);
        for (Eigen::Index i = 0; i < n; ++i) {
            l[i] = -1 - u(rng) * u(rng);
            l[n + i] = (i % 2 ? F[i] : -F[i]) * l[i];
            if (i < stuck) l[n + i] = 0.1 * u(rng) * l[i];
        }
        if (stuck == 0) l[3] = l[n + 3] = 0;  // an open node: it keeps its s
        return l;
    };
    SlidingProduct sliding;
    Eigen::VectorXd y(rows);
    const Eigen::VectorXd first = multipliers(2), second = multipliers(0);
    for (const Eigen::VectorXd* l : {&first, &second, &first}) {
        ASSERT_TRUE(sliding.apply(M, F, *l, y));
        EXPECT_LE((y - M * *l).lpNorm<Eigen::Infinity>(), 1e-13 * (M * *l).lpNorm<Eigen::Infinity>());
    }
    SlidingProduct fresh;  // the first lambda with no history: the same bits
    Eigen::VectorXd z(rows);
    ASSERT_TRUE(fresh.apply(M, F, first, z));
    EXPECT_TRUE((z.array() == y.array()).all());
    const Eigen::VectorXd shortened = 0.5 * first + 0.5 * multipliers(n);  // no node on its bound
    z.setConstant(7);
    EXPECT_FALSE(sliding.apply(M, F, shortened, z));
    EXPECT_TRUE((z.array() == 7).all());  // untouched
}

TEST(ElementaryExample, RateSolutionsWithoutRateDependenceAreTheClosedForms) {
    for (const auto& [m1, m2, F] :
         {std::tuple{0.0, 1.0, 2.5}, std::tuple{1.0, 0.0, 2.5}, std::tuple{0.0, 0.0, 1.0}}) {
        const ElementaryExample e = elementary(m1, m2, F);
        int compared = 0;
        for (int i = 0; i <= 20; ++i)
            for (int j = 0; j <= 20; ++j) {
                const Eigen::Vector2d f(-2 + 0.2 * i + 0.013, -4 + 0.4 * j + 0.017);  // off boundaries
                const auto closed = e.closed_form_solutions(f);
                const auto direct = e.rate_solutions(f);
                ASSERT_EQ(direct.size(), closed.size()) << f.transpose();
                for (const ElementarySolution& s : closed) {
                    double best = 1e300;
                    for (const ElementarySolution& t : direct)
                        best = std::min(best, (s.x - t.x).lpNorm<Eigen::Infinity>());
                    EXPECT_LT(best, 1e-9) << f.transpose();
                }
                ++compared;
            }
        EXPECT_EQ(compared, 441);
    }
}

// Velocity weakening without tangential mass: a load with three solutions of one step
// (stick, and two slipping states), each reached by ContactSolver from some start.
TEST(ElementaryExample, VelocityWeakeningWithoutTangentialMassHasSeveralSolutions) {
    ElementaryExample e = ElementaryExample::from_material(2, 1, 0.01, 0, 0, 0.5, 0.1);
    ContactProblem::RateLaw law;
    law.excess = 0.5;
    law.stribeck_velocity = 0.1;
    law.slip_time = 0.005;
    e.set_rate_law(law);
    const Eigen::Vector2d f(0.4, -0.2);
    const auto direct = e.rate_solutions(f);
    ASSERT_EQ(direct.size(), 3u);
    for (const ElementarySolution& s : direct) EXPECT_LT(e.violation(f, s.x), 1e-12);
    ContactSolver solver;
    const auto found = e.solver_solutions(f, solver);
    EXPECT_GE(found.size(), 2u);
    for (const ElementarySolution& s : found) EXPECT_LT(e.violation(f, s.x), 1e-10);
}
