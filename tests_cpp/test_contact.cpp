// The condensed contact solve: the paper's section 6 example (issue 2 item 5) and failures.
#include <gtest/gtest.h>

#include <random>

#include "contact_solver.hpp"

using namespace contactbody;

namespace {

// Section 6: one P1 triangle, midpoint step, eq. (23), nu = (1, 0), tau = (0, 1):
//   a u_nu - b u_tau = f_nu + lambda_nu,  -b u_nu + c u_tau = f_tau + lambda_tau.
struct Elementary {
    double a, b, c, friction, u_tau_old;

    ContactProblem problem(double f_nu, double f_tau) const {
        Eigen::Matrix2d K;
        K << a, -b, -b, c;
        ContactProblem p;
        p.W = K.inverse();  // B = identity
        p.a = p.W * Eigen::Vector2d(f_nu, f_tau);
        p.gap_limit = Eigen::VectorXd::Zero(1);
        p.slip_origin = Eigen::VectorXd::Constant(1, u_tau_old);
        p.friction = friction;
        return p;
    }

    // Closed forms S1-S4 of the paper, (u_nu, u_tau, lambda_nu, lambda_tau), for F < c/b.
    // Returns the region index (1-4), or 0 when f is within `margin` of a region boundary.
    int region(double fn, double ft, double margin) const {
        const double F = friction, ut = u_tau_old;
        const double s = c * fn + b * ft;
        if (s < -margin) return 1;
        if (s <= margin) return 0;
        const double lo = (c - b * F) * ut - F * fn, hi = (c + b * F) * ut + F * fn;
        if (fn > -b * ut + margin && ft > lo + margin && ft < hi - margin) return 2;
        if (ft > hi + margin) return 3;
        if (fn > -b * ut + margin && ft < lo - margin) return 4;
        return 0;
    }

    Eigen::Vector4d closed_form(int region, double fn, double ft) const {
        const double F = friction, ut = u_tau_old, s = c * fn + b * ft;
        switch (region) {
            case 1: return {s / (a * c - b * b), (a * ft + b * fn) / (a * c - b * b), 0, 0};
            case 2: return {0, ut, -(fn + b * ut), c * ut - ft};
            case 3: return {0, (ft - F * fn) / (c + b * F), -s / (c + b * F), -F * s / (c + b * F)};
            default: return {0, (ft + F * fn) / (c - b * F), -s / (c - b * F), F * s / (c - b * F)};
        }
    }
};

}  // namespace

TEST(ElementaryExample, LocalSolveMatchesClosedFormInRegionsS1ToS4) {
    // lambda = mu = 1, dt = 1; m1 = 0 (normal mass removed), m2 = 0.25 > 0.
    const double lame = 1, mu = 1, dt = 1, m1 = 0, m2 = 0.25;
    for (double F : {0.3, 1.2, 2.5}) {  // c/b = 3 here: all F < c/b
        Elementary e{4 / (dt * dt) * m1 + (lame + 3 * mu) / 2, (lame + mu) / 2,
                     4 / (dt * dt) * m2 + (lame + 3 * mu) / 2, F, 0.1};
        ASSERT_LT(F, e.c / e.b);
        std::mt19937 rng(42);
        std::uniform_real_distribution<double> f(-3, 3);
        int seen[5] = {0, 0, 0, 0, 0};
        ContactSolver solver;
        for (int trial = 0; trial < 20000; ++trial) {
            const double fn = f(rng), ft = f(rng);
            const int r = e.region(fn, ft, 1e-6);
            if (r == 0) continue;
            ++seen[r];
            const ContactProblem p = e.problem(fn, ft);
            Eigen::VectorXd lambda = Eigen::VectorXd::Zero(2);
            solver.solve(p, ContactSolverOptions{1e-12, 100}, lambda);
            const Eigen::VectorXd u = p.a + p.W * lambda;
            const Eigen::Vector4d got(u[0], u[1], lambda[0], lambda[1]);
            const Eigen::Vector4d want = e.closed_form(r, fn, ft);
            EXPECT_LE((got - want).cwiseAbs().maxCoeff(), 1e-10 * (1 + want.cwiseAbs().maxCoeff()))
                << "F = " << F << ", region S" << r << ", f = (" << fn << ", " << ft << ")";
        }
        for (int r = 1; r <= 4; ++r) EXPECT_GT(seen[r], 50) << "region S" << r << " sampled";
    }
}

TEST(ContactSolver, NonConvergenceIsAnError) {
    Elementary e{2, 1, 3, 0.5, 0.1};
    const ContactProblem p = e.problem(1, 2);  // region S3: needs iterations from zero
    Eigen::VectorXd lambda = Eigen::VectorXd::Zero(2);
    ContactSolver solver;
    EXPECT_THROW(solver.solve(p, ContactSolverOptions{1e-10, 0}, lambda), ContactSolveError);
}

TEST(ContactSolver, OpenContactNeedsNoIteration) {
    Elementary e{2, 1, 3, 0.5, 0.1};
    const ContactProblem p = e.problem(-1, 0.5);  // region S1: lambda = 0
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
