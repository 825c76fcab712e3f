// The paper's section 6 elementary example: one P1 triangle with one contact node, one midpoint
// step. With nu = (1, 0), tau = (0, 1), problem (23) reads
//   a u_nu - b u_tau = f_nu + lambda_nu,   -b u_nu + c u_tau = f_tau + lambda_tau,
//   -lambda_nu in N_{R-}(u_nu),   lambda_tau in F lambda_nu Sgn(u_tau - u_tau_old),
// a = 4/dt^2 m1 + (l + 3 mu)/2,  b = (l + mu)/2,  c = 4/dt^2 m2 + (l + 3 mu)/2.
// It is posed here as the ContactProblem the stepper hands to ContactSolver each substep
// (W = K^-1 with B = I), next to the paper's closed forms S1-S4 and their sets sigma_1-sigma_4.
#pragma once

#include <Eigen/Dense>
#include <vector>

#include "contact/contact_solver.hpp"
#include "contact/friction_law.hpp"

namespace contactbody {

// A solution x = (u_nu, u_tau, lambda_nu, lambda_tau) of (23).
using ElementaryState = Eigen::Vector4d;

struct ElementarySolution {
    int region;  // i of the closed form S_i (1 open, 2 stick, 3 slip up, 4 slip down)
    ElementaryState x;
};

class ElementaryExample {
public:
    ElementaryExample(double a, double b, double c, double friction, double u_tau_old);
    // From the Lame coefficients, the step and the redistributed masses m1 (normal), m2.
    static ElementaryExample from_material(double lame, double mu, double dt, double m1, double m2,
                                           double friction, double u_tau_old);

    double a() const { return a_; }
    double b() const { return b_; }
    double c() const { return c_; }
    double friction() const { return friction_; }
    double u_tau_old() const { return u_tau_old_; }

    // The condensed problem of ContactSolver for the load f = (f_nu, f_tau).
    ContactProblem problem(const Eigen::Vector2d& f) const;

    // Friction depending on the slip rate, F(v) with F_d = friction(), v = slip /
    // law.slip_time (dt / 2 for the midpoint step). Enters problem(), violation() and
    // rate_solutions().
    void set_rate_law(const ContactProblem::RateLaw& law) { rate_ = law; }
    const ContactProblem::RateLaw& rate_law() const { return rate_; }
    // F at this slip u_tau - u_tau_old (F(0) = F_s bounds a sticking node).
    double coefficient(double slip) const { return rate_.coefficient(friction_, slip); }
    // Every solution of (23) with the rate law, found directly: S1 (open), the sticking
    // state if F(0) admits it, and each root of the slip equation along the contact
    //   G_s(w) = c (u_tau_old + w) - f_tau + s F(|w| / slip_time) N(w) = 0,
    //   N(w) = b (u_tau_old + w) + f_nu >= 0, s w > 0,
    // bracketed on a grid fine near w = 0 (where the Stribeck drop acts) and bisected.
    std::vector<ElementarySolution> rate_solutions(const Eigen::Vector2d& f) const;

    // The paper's sets: f in sigma_i (closed, i = 1..4; sigma_4 follows the case F < c/b or
    // F > c/b) and the half-line sigma_5 (F = c/b). `margin` > 0 shrinks each set, < 0 grows it;
    // for the line sigma_5 it is also the tolerance on c f_nu + b f_tau = 0.
    bool in_sigma(int i, const Eigen::Vector2d& f, double margin = 0) const;
    bool in_sigma5(const Eigen::Vector2d& f, double margin = 0) const;
    // The closed form S_i(f) (i = 1..4; S_4 needs F != c/b).
    ElementaryState closed_form(int i, const Eigen::Vector2d& f) const;
    // All S_i(f) with f in sigma_i, equal ones merged: the solution set of (23) when F != c/b.
    // A negative margin also admits sets that f misses by rounding only (on a boundary).
    std::vector<ElementarySolution> closed_form_solutions(const Eigen::Vector2d& f, double margin = 0) const;

    // How far x is from solving (23): the largest equation residual or inclusion violation.
    double violation(const Eigen::Vector2d& f, const ElementaryState& x) const;
    // The case (i)-(iv) of the paper that x falls in, judged with tolerance `tol`.
    int region_of(const ElementaryState& x, double tol) const;

    // The distinct solutions ContactSolver reaches from a fixed family of starting multipliers
    // (Newton finds one solution per start; several starts expose several solutions).
    // `failed` counts the starts from which it did not converge.
    std::vector<ElementarySolution> solver_solutions(const Eigen::Vector2d& f, ContactSolver& solver,
                                                     int* failed = nullptr) const;

private:
    double a_, b_, c_, friction_, u_tau_old_;
    ContactProblem::RateLaw rate_;
    Eigen::Matrix2d inverse_;
};

}  // namespace contactbody
