// What both reduced bodies (ReducedStepper, and CraigBamptonStepper, its benchmark rival)
// share about the clamp: the clamped x dofs' rows, whose residual is the clamp's x reaction,
// and the passage between a full state and a reduced one's lift and clamp entries. A reduced
// state is (coordinates, lift, clamp) in u and in v: u = (y, lift_at, top), v likewise.
#pragma once

#include <Eigen/Dense>

#include "assembly/discretization.hpp"
#include "body/stepper.hpp"

namespace contactbody {

// The clamped dofs' rows of one tangential component (x = 0, or a 3D body's z = 2), summed
// (their reaction), of M and A: on the free dofs, and against the clamp's y motion (e^T M_cx,
// e^T A_cx).
struct ClampXRows {
    Eigen::VectorXd mass_free, stiffness_free;
    double mass_top = 0, stiffness_top = 0;
};
ClampXRows clamp_x_rows(const Discretization& d, int component = 0);

// Those rows against a reduced body's coordinates, its lift S and the clamp.
struct ClampRows {
    Eigen::VectorXd mass, stiffness;
    double mass_lift = 0, stiffness_lift = 0, mass_top = 0, stiffness_top = 0;

    // The rows' residual over a midpoint substep (they do not move: no work), M_cf a +
    // A_cf u^{k+1/2} + A_cc u_c^{k+1/2} + C_cf vbar: the coordinates y, ydot at its start,
    // their midpoint increment w (du = 2 w), and the lift's and clamp's (w_t their common
    // increment); c1 = 4/dt^2, c2 = 2/dt, C = alpha M + beta A where `damped`.
    struct Substep {
        double c1 = 0, c2 = 0, w_t = 0, lift_at = 0, lift_rate = 0, top = 0, top_rate = 0;
        double alpha = 0, beta = 0;
        bool damped = false;
    };
    double residual(const Substep& k, const Eigen::Ref<const Eigen::VectorXd>& y,
                    const Eigen::Ref<const Eigen::VectorXd>& ydot, const Eigen::VectorXd& w,
                    const Eigen::VectorXd& du) const;
};

// A reduced state's lift and clamp entries (n: its coordinates' count) from the full state's
// top y dof, and the full state's free-dof motion less the lift's, u_f - S lift_at and
// v_f - S lift_rate, which the body projects on its coordinates.
void split_off_lift(const Discretization& d, int top_dof, const Eigen::VectorXd& lift, const State& full,
                    Eigen::Index n, State& s, Eigen::VectorXd& u, Eigen::VectorXd& v);
// The full state of a reduced one whose free dofs move by u and v: the clamped dofs at the
// clamp (y at s's top, x held), s's multipliers, node states and time.
void expand_to_full(const Discretization& d, const Eigen::VectorXd& u, const Eigen::VectorXd& v,
                    const State& s, Eigen::Index n, State& full);

}  // namespace contactbody
