// The time loop allocates nothing once warm. This binary interposes malloc, calloc and realloc
// (glibc's __libc_* do the work), so allocations by Eigen, CHOLMOD, BLAS and operator new are
// all counted while the counter is armed. Not built with sanitizers, which interpose malloc too.
#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <cstdlib>
#include <functional>

#include "reduced/reduced_stepper.hpp"
#include "simulation/simulation.hpp"

namespace {
std::atomic<bool> armed{false};
std::atomic<long> allocations{0};
}  // namespace

extern "C" {
void* __libc_malloc(std::size_t);
void* __libc_calloc(std::size_t, std::size_t);
void* __libc_realloc(void*, std::size_t);
void* malloc(std::size_t size) {
    if (armed.load(std::memory_order_relaxed)) ++allocations;
    return __libc_malloc(size);
}
void* calloc(std::size_t count, std::size_t size) {
    if (armed.load(std::memory_order_relaxed)) ++allocations;
    return __libc_calloc(count, size);
}
void* realloc(void* p, std::size_t size) {
    if (armed.load(std::memory_order_relaxed)) ++allocations;
    return __libc_realloc(p, size);
}
}

namespace contactbody {
namespace {

// 100 warm steps: none allocates but one that made a warning (its message; once per kind and
// run). Returns the contact solves they made, so that a test can see the solver ran.
long expect_no_allocation(Simulation& sim, const StepInputs& in,
                          const std::function<void()>& after_step = {}) {
    long contact_solves = 0;
    for (int k = 0; k < 100; ++k) {
        armed = true;
        sim.do_step(1e-4, in);
        armed = false;
        if (after_step) after_step();
        contact_solves += sim.statistics().contact_solves;
        const long made = allocations.exchange(0);
        if (sim.take_warnings().empty()) {
            EXPECT_EQ(made, 0) << "step " << k;
        }
    }
    return contact_solves;
}

class NoAllocation : public ::testing::TestWithParam<std::tuple<int, double, bool>> {
protected:
    // The parameters' scene: variant, F, and whether damped.
    SceneParameters scene() const {
        SceneParameters p;
        p.nx = p.ny = 8;
        p.internal_step = 1e-5;
        p.mass_matrix = static_cast<MassVariant>(std::get<0>(GetParam()));
        p.friction_coefficient = std::get<1>(GetParam());
        if (std::get<2>(GetParam())) {  // Rayleigh damping adds two sparse products, no storage
            p.damping_mass = 50;
            p.damping_stiffness = 4e-6;
        }
        return p;
    }
};

TEST_P(NoAllocation, InTheStepLoopOnceWarm) {
    Simulation sim(scene(), -2.5e-5);
    StepInputs in;
    in.foundation_velocity[0] = 20;
    in.top_displacement = -2.5e-5;
    armed = true;
    sim.do_step(1e-4, in);  // cold: factorization and workspaces
    armed = false;
    EXPECT_GT(allocations.exchange(0), 0);               // the counter does see the library's allocations
    for (int k = 0; k < 50; ++k) sim.do_step(1e-4, in);  // sizes every workspace
    EXPECT_GT(expect_no_allocation(sim, in), 0);         // the loop did exercise the contact solver
}

INSTANTIATE_TEST_SUITE_P(Variants, NoAllocation,
                         ::testing::Combine(::testing::Values(0, 1, 2, 3, 4), ::testing::Values(1.2, 0.0),
                                            ::testing::Bool()));

// The same on the sparse contact solve (sparse_contact.hpp): its held factor's
// refactorizations, its coupled system and its kept directions reuse their storage.
TEST_P(NoAllocation, OnTheSparseContactSolveOnceWarm) {
    auto stepper = std::make_unique<Stepper>(scene());
    stepper->set_contact_path(Stepper::ContactPath::sparse);
    const Stepper& body = *stepper;
    Simulation sim(std::move(stepper), -2.5e-5);
    StepInputs in;
    in.foundation_velocity[0] = 20;
    in.top_displacement = -2.5e-5;
    for (int k = 0; k < 50; ++k) sim.do_step(1e-4, in);
    ASSERT_TRUE(body.sparse_contact());
    int slipping_rows = 0;  // steps that ended on a factor with slipping rows (its LU)
    EXPECT_GT(expect_no_allocation(sim, in,
                                   [&] {
                                       const std::vector<signed char> pattern =
                                           body.contact_factorization().pattern;
                                       slipping_rows +=
                                           std::any_of(pattern.begin(), pattern.end(),
                                                       [](signed char x) { return x == 3 || x == -3; });
                                   }),
              0);
    if (std::get<1>(GetParam()) > 0) EXPECT_GT(slipping_rows, 0);
}

// The slip-rate law: the full Newton Jacobian lives in the same buffer.
TEST(NoAllocationWithTheSlipRateLaw, InTheStepLoopOnceWarm) {
    for (const int variant : {1, 3}) {
        SceneParameters p;
        p.nx = p.ny = 8;
        p.internal_step = 1e-5;
        p.mass_matrix = static_cast<MassVariant>(variant);
        p.friction_coefficient = 0.3;
        p.static_friction_ratio = 1.5;
        p.stribeck_velocity = 1;
        p.viscous_friction = 0.01;
        p.damping_stiffness = 4e-6;
        Simulation sim(p, -2.5e-5);
        StepInputs in;
        in.foundation_velocity[0] = 5;
        in.top_displacement = -2.5e-5;
        for (int k = 0; k < 50; ++k) sim.do_step(1e-4, in);
        EXPECT_GT(expect_no_allocation(sim, in), 0) << "variant " << variant;
    }
}

// The reduced body's substep, once its operators and the contact solver are warm: variant 1
// with the massless edge, 3 with the tangential-mass edge (their defaults), and 1 with it.
TEST(NoAllocationInTheReducedBody, InTheSubstepLoopOnceWarm) {
    for (const int variant : {1, 3, 11}) {
        SceneParameters p;
        if (variant == 11) p.reduced_edge = ReducedEdge::tangential_mass;
        p.nx = p.ny = 8;
        p.mass_matrix = static_cast<MassVariant>(variant % 10);
        p.friction_coefficient = 0.3;
        p.damping_stiffness = 4e-6;
        ReducedStepper reduced(p, 10);
        ReducedState s = reduced.from_full(Stepper(p).initial_state(-2.5e-5));
        const SubstepLoad load{-2.5e-5, -2.5e-5, 0, 20};
        for (int k = 0; k < 50; ++k) reduced.substep(s, 4e-6, load);
        int solved = 0;
        armed = true;
        for (int k = 0; k < 200; ++k) solved += reduced.substep(s, 4e-6, load).contact_solved;
        armed = false;
        EXPECT_EQ(allocations.exchange(0), 0) << "variant " << variant;
        EXPECT_GT(solved, 0) << "variant " << variant;
    }
}

}  // namespace
}  // namespace contactbody
