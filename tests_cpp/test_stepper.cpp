// The midpoint stepper on the paper's scene: the contact law holds at every substep
// and a failed solve is an error that leaves the state as it was.
#include <gtest/gtest.h>

#include <string>

#include "simulation/simulation.hpp"

using namespace contactbody;

namespace {

// Checks the contact law on the last substep's quantities, recomputed from u^{k+1/2},
// to the relative tolerance eps: forces relative to max |lambda|, displacements relative to
// the displacement that force causes (diag W * max |lambda|).
void expect_contact_law(const ContactSnapshot& c, double F, double eps, const std::string& where) {
    const Eigen::Index n = c.lambda_N.size();
    const double force = std::max(c.lambda_N.cwiseAbs().maxCoeff(), c.lambda_T[0].cwiseAbs().maxCoeff());
    const double dn = c.delassus_diagonal.head(n).maxCoeff() * force;
    const double dt = c.delassus_diagonal.tail(n).maxCoeff() * force;
    for (Eigen::Index i = 0; i < n; ++i) {
        const double lN = c.lambda_N[i], lT = c.lambda_T[0][i];
        const double gap = c.normal_displacement[i] - c.gap_limit[i];  // must be <= 0
        ASSERT_LE(lN, eps * force) << where << " node " << i << ": lambda_N <= 0";
        ASSERT_LE(gap, eps * dn) << where << " node " << i << ": u_N <= gap";
        ASSERT_LE(std::abs(lN * gap), eps * force * dn) << where << " node " << i << ": complementarity";
        ASSERT_LE(std::abs(lT), -F * lN + eps * force) << where << " node " << i << ": Coulomb cone";
        if (F == 0) continue;
        if (std::abs(c.slip[i]) > eps * dt) {  // slipping: friction opposes the slip at the bound
            const double sign = c.slip[i] > 0 ? 1.0 : -1.0;
            ASSERT_LE(std::abs(lT - F * lN * sign), eps * force) << where << " node " << i << ": slip law";
        }
        if (std::abs(lT) < -F * lN - eps * force) {  // strictly inside the cone: sticking
            ASSERT_LE(std::abs(c.slip[i]), eps * dt) << where << " node " << i << ": stick law";
        }
    }
}

}  // namespace

// The condensed contact solve, and the sparse one (sparse_contact.hpp).
class ContactLaw : public ::testing::TestWithParam<std::tuple<int, double, bool>> {};

TEST_P(ContactLaw, HoldsAtEverySubstep) {
    const auto [variant, F, sparse] = GetParam();
    SceneParameters p;
    p.mass_matrix = static_cast<MassVariant>(variant);
    p.friction_coefficient = F;
    Stepper stepper(p);
    stepper.set_contact_path(sparse ? Stepper::ContactPath::sparse : Stepper::ContactPath::condensed);
    State s = stepper.initial_state(-2.5e-5);
    SubstepLoad load{-2.5e-5, -2.5e-5, 0, 20};
    int contact_substeps = 0;
    for (int k = 0; k < 600; ++k) {
        stepper.substep(s, 4e-6, load);
        const ContactSnapshot& c = stepper.last_contact();
        contact_substeps += c.lambda_N.minCoeff() < 0;
        expect_contact_law(c, F, p.contact_tolerance,
                           "variant " + std::to_string(variant) + " substep " + std::to_string(k));
        if (HasFatalFailure()) return;
    }
    EXPECT_GT(contact_substeps, 100);  // the check saw real contact
}

INSTANTIATE_TEST_SUITE_P(Variants, ContactLaw,
                         ::testing::Combine(::testing::Values(0, 1, 2, 3, 4),
                                            ::testing::Values(1.2, 0.2, 0.0), ::testing::Bool()));

TEST(Simulation, FailedContactSolveRestoresTheStepStart) {
    SceneParameters p;
    Simulation sim(p, -2.5e-5);
    const StepInputs in{{20, 0}, {0, 0}, -2.5e-5, 0};
    sim.do_step(1e-4, in);
    const State before = sim.state();
    const double work = sim.observables().friction_work;
    ContactSolverOptions& options = sim.body().contact_options();
    options.max_iterations = 0;  // neither Newton nor its fallback can succeed
    options.max_sweeps = 0;
    try {
        sim.do_step(1e-4, in);
        FAIL() << "the step should fail";
    } catch (const NumericalFailure& e) {
        // Refined down to min_internal_step (1e-9) before giving up, and says so.
        const std::string what = e.what();
        EXPECT_NE(what.find("contact solve failed at t = "), std::string::npos) << what;
        EXPECT_NE(what.find("min_internal_step = 1e-09"), std::string::npos) << what;
        EXPECT_NE(what.find(", 1.95312e-09 s"), std::string::npos) << what;  // 4e-6 / 2^11
    }
    EXPECT_EQ(sim.time(), before.time);
    EXPECT_EQ((sim.state().u - before.u).cwiseAbs().maxCoeff(), 0.0);
    EXPECT_EQ((sim.state().v - before.v).cwiseAbs().maxCoeff(), 0.0);
    EXPECT_EQ(sim.observables().friction_work, work);
    options.max_iterations = 100;
    options.max_sweeps = 2000;
    EXPECT_NO_THROW(sim.do_step(1e-4, in));  // usable again
}

TEST(Simulation, GaussSeidelTakesOverWhenNewtonFails) {
    SceneParameters p;  // damped sliding: stable, so that tolerance-level differences stay small
    p.friction_coefficient = 0.3;
    p.damping_stiffness = 4e-6;
    Simulation newton(p, -2.5e-5), fallback(p, -2.5e-5);
    const StepInputs in{{20, 0}, {0, 0}, -2.5e-5, 0};
    fallback.body().contact_options().max_iterations = 0;  // Newton gives up at once
    for (int k = 0; k < 5; ++k) {
        newton.do_step(1e-4, in);
        fallback.do_step(1e-4, in);
    }
    EXPECT_GT(fallback.statistics().gauss_seidel_sweeps, 0);
    EXPECT_EQ(fallback.statistics().refinements, 0);
    // Both solve every substep's contact problem to the tolerance: the same motion.
    const double scale = newton.state().u.cwiseAbs().maxCoeff();
    EXPECT_LT((newton.state().u - fallback.state().u).cwiseAbs().maxCoeff(), 1e-6 * scale);
}

TEST(Simulation, InitialEnergyIsTheUniaxialStrainEnergy) {
    SceneParameters p;
    Simulation sim(p, -2.5e-5);
    EXPECT_NEAR(sim.observables().energy, 0.1875, 1e-12);
}

TEST(Simulation, SubstepCountIsCeilOfStepOverInternalStep) {
    SceneParameters p;
    Simulation sim(p, -2.5e-5);
    EXPECT_EQ(sim.substeps_for(1e-4), 25);
    EXPECT_EQ(sim.substeps_for(1e-4 * (1 + 5e-12)), 25);  // masters that add up time
    EXPECT_EQ(sim.substeps_for(1e-4 * (1 + 1e-8)), 26);
    EXPECT_EQ(sim.substeps_for(1.01e-4), 26);
    EXPECT_EQ(sim.substeps_for(1e-7), 1);
}

// A restarted simulation takes its kept factor instead of refactoring, and gives the bits of a
// new one; a restart onto another discretization is refused.
TEST(Simulation, RestartKeepsTheFactorAndGivesTheSameBits) {
    SceneParameters p;
    p.friction_coefficient = 0.5;
    Simulation sim(p, -2.5e-5);
    StepInputs in;
    in.foundation_velocity[0] = 20;
    in.top_displacement = -2.5e-5;
    for (int k = 0; k < 3; ++k) sim.do_step(1e-4, in);
    EXPECT_EQ(sim.body().factorizations(), 1);

    SceneParameters q = p;
    q.friction_coefficient = 0.3;
    q.static_friction_ratio = 2;
    in.foundation_velocity[0] = 10;
    sim.restart(q, -3e-5);
    Simulation fresh(q, -3e-5);
    for (int k = 0; k < 3; ++k) {
        sim.do_step(1e-4, in);
        fresh.do_step(1e-4, in);
    }
    EXPECT_EQ(sim.body().factorizations(), 1);  // the kept one
    EXPECT_EQ(sim.state().u, fresh.state().u);
    EXPECT_EQ(sim.state().v, fresh.state().v);
    EXPECT_EQ(sim.state().lambda, fresh.state().lambda);
    EXPECT_EQ(sim.observables().energy, fresh.observables().energy);

    SceneParameters other = q;
    other.nx = 10;
    EXPECT_THROW(sim.body().restart(other), std::logic_error);
}

// Eigen's dense products block by the CPU's cache sizes, and the blocks decide the rounding:
// the stepper fixes them, so that every machine computes the same bits. (Where the CPU has
// other caches than these, e.g. an AMD EPYC's 48 KiB L1, this fails without the fix.)
TEST(Stepper, FixesTheDenseBlockingWhateverTheCpu) {
    SceneParameters p;
    p.nx = p.ny = 4;
    Stepper stepper(p);
    EXPECT_EQ(Eigen::l1CacheSize(), 32 << 10);
    EXPECT_EQ(Eigen::l2CacheSize(), 1 << 20);
    EXPECT_EQ(Eigen::l3CacheSize(), 32 << 20);
}
