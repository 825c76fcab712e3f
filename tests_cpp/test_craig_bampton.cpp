// The mass-carrying Craig-Bampton body (the comparison path) against the full body: with every
// fixed-interface mode it is the full body in other coordinates, in the variants whose contact
// dofs are massless (in 0 and 3 the full body itself amplifies round-off to order one,
// test_reduced_stepper.cpp); with few modes its own energy balance closes.
#include <gtest/gtest.h>

#include "craig_bampton.hpp"

using namespace contactbody;

namespace {

SceneParameters scene(MassVariant variant) {
    SceneParameters p;
    p.nx = p.ny = 6;
    p.mass_matrix = variant;
    p.friction_coefficient = 0.3;
    p.damping_mass = 20;
    p.damping_stiffness = 4e-6;
    p.initial_velocity[0] = 0.5;
    return p;
}

SubstepLoad load_at(int k, double dt) {  // the clamp pressing on, the foundation at 20 m/s
    const double rate = -2e-3, top0 = -2.5e-5;
    return {top0 + rate * k * dt, top0 + rate * (k + 1) * dt, rate, 20.0, 0.0};
}

double energy(Body& body, const State& s) {
    const auto [kinetic, strain] = body.kinetic_and_strain_energy(s);
    return kinetic + strain;
}

}  // namespace

TEST(CraigBampton, AllModesGiveTheFullBody) {
    const double dt = 2e-6;
    for (MassVariant v : {MassVariant::redistributed_normal, MassVariant::redistributed_both,
                          MassVariant::redistributed_implicit_contact}) {
        SCOPED_TRACE(static_cast<int>(v));
        const SceneParameters p = scene(v);
        Stepper full(p);
        const Discretization& d = full.discretization();
        const int interior = static_cast<int>(d.free_dofs.size()) - 2 * full.num_contact_nodes();
        CraigBamptonStepper cb(p, interior);
        State s = full.initial_state(load_at(0, dt).top_start);
        State r = cb.from_full(s);
        double scale = 0, worst = 0;
        Works full_works, cb_works;
        int touching = 0;
        for (int k = 0; k < 500; ++k) {
            const SubstepReport a = full.substep(s, dt, load_at(k, dt));
            const SubstepReport b = cb.substep(r, dt, load_at(k, dt));
            full_works += a.work;
            cb_works += b.work;
            scale = std::max(scale, std::abs(a.normal_force));
            worst = std::max({worst, std::abs(a.normal_force - b.normal_force),
                              std::abs(a.friction_force[0] - b.friction_force[0]),
                              std::abs(a.top_reaction[0] - b.top_reaction[0]),
                              std::abs(a.top_reaction[1] - b.top_reaction[1])});
            touching += a.active_nodes > 0;
        }
        EXPECT_GT(touching, 100);
        EXPECT_LT(worst / scale, 1e-10);
        State back;
        cb.to_full(r, back);
        EXPECT_LT((back.u - s.u).cwiseAbs().maxCoeff() / s.u.cwiseAbs().maxCoeff(), 1e-10);
        const double E = energy(full, s);
        EXPECT_LT(std::abs(energy(cb, r) - E) / E, 1e-10);
        double worst_work = 0;
        Works::for_each(full_works, cb_works,
                        [&](double x, double y) { worst_work = std::max(worst_work, std::abs(x - y)); });
        EXPECT_LT(worst_work / E, 1e-10);
    }
}

TEST(CraigBampton, EnergyBalanceClosesWithFewModes) {
    const double dt = 2e-6;
    for (int v = 0; v < num_mass_variants; ++v) {
        SCOPED_TRACE(v);
        const SceneParameters p = scene(static_cast<MassVariant>(v));
        Stepper full(p);
        CraigBamptonStepper cb(p, 8);
        State start = full.initial_state(load_at(0, dt).top_start);
        for (int dof : full.discretization().clamped_dofs)
            if (dof % 2 == 1) start.v[dof] = load_at(0, dt).top_rate;
        State r = cb.from_full(start);
        const double E0 = energy(cb, r);
        Works works;
        double scale = E0;
        for (int k = 0; k < 500; ++k) {
            works += cb.substep(r, dt, load_at(k, dt)).work;
            scale = std::max({scale, std::abs(works.clamp), std::abs(works.friction)});
        }
        const double balance =
            energy(cb, r) - E0 - (works.clamp + works.normal_contact + works.friction - works.damping);
        EXPECT_LT(std::abs(balance) / scale, 1e-9);
        EXPECT_GT(works.damping, 0);
    }
}
