#include "contact/elementary_example.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace contactbody {

ElementaryExample::ElementaryExample(double a, double b, double c, double friction, double u_tau_old)
    : a_(a), b_(b), c_(c), friction_(friction), u_tau_old_(u_tau_old) {
    if (!(a * c - b * b > 0) || !(b > 0) || !(friction >= 0))
        throw std::invalid_argument("elementary example: needs a c > b^2, b > 0 and F >= 0");
    Eigen::Matrix2d K;
    K << a, -b, -b, c;
    inverse_ = K.inverse();
}

ElementaryExample ElementaryExample::from_material(double lame, double mu, double dt, double m1, double m2,
                                                   double friction, double u_tau_old) {
    const double stiff = (lame + 3 * mu) / 2, k = 4 / (dt * dt);
    return {k * m1 + stiff, (lame + mu) / 2, k * m2 + stiff, friction, u_tau_old};
}

ContactProblem ElementaryExample::problem(const Eigen::Vector2d& f) const {
    ContactProblem p;
    p.W = inverse_;
    p.a = inverse_ * f;
    p.gap_limit = Eigen::VectorXd::Zero(1);
    p.slip_origin = Eigen::VectorXd::Constant(1, u_tau_old_);
    p.friction = Eigen::VectorXd::Constant(1, friction_);
    p.rate = rate_;
    return p;
}

bool ElementaryExample::in_sigma(int i, const Eigen::Vector2d& f, double m) const {
    const double fn = f[0], ft = f[1], F = friction_, b = b_, c = c_, ut = u_tau_old_;
    const double s = c * fn + b * ft;                // sign of -lambda_nu in S_3, S_4
    const double upper = (c + b * F) * ut + F * fn;  // stick-slip up boundary
    const double lower = (c - b * F) * ut - F * fn;  // stick-slip down boundary
    switch (i) {
        case 1:
            return s <= -m;
        case 2:
            return fn >= -b * ut + m && lower + m <= ft && ft <= upper - m;
        case 3:
            return s >= m && ft >= upper + m;
        case 4:
            if (F * b < c) return fn >= -b * ut + m && s >= m && ft <= lower - m;
            if (F * b > c) return fn >= -b * ut + m && s <= -m && ft >= lower + m;
            return false;  // F = c/b: sigma_5 instead
        default:
            throw std::invalid_argument("elementary example: region is 1..4");
    }
}

bool ElementaryExample::in_sigma5(const Eigen::Vector2d& f, double m) const {
    return std::abs(c_ * f[0] + b_ * f[1]) <= std::max(m, 0.0) && f[0] >= -b_ * u_tau_old_ + m;
}

ElementaryState ElementaryExample::closed_form(int i, const Eigen::Vector2d& f) const {
    const double fn = f[0], ft = f[1], F = friction_, a = a_, b = b_, c = c_, ut = u_tau_old_;
    const double s = c * fn + b * ft;
    switch (i) {
        case 1:
            return {s / (a * c - b * b), (a * ft + b * fn) / (a * c - b * b), 0, 0};
        case 2:
            return {0, ut, -(fn + b * ut), c * ut - ft};
        case 3:
            return {0, (ft - F * fn) / (c + b * F), -s / (c + b * F), -F * s / (c + b * F)};
        case 4:
            if (F * b == c) throw std::invalid_argument("elementary example: S_4 needs F != c/b");
            return {0, (ft + F * fn) / (c - b * F), -s / (c - b * F), F * s / (c - b * F)};
        default:
            throw std::invalid_argument("elementary example: region is 1..4");
    }
}

namespace {
double scale_of(const Eigen::Vector2d& f) { return 1 + f.lpNorm<Eigen::Infinity>(); }

// Appends x unless an equal solution is already listed (on a shared boundary S_i = S_j).
void add_distinct(std::vector<ElementarySolution>& list, int region, const ElementaryState& x, double tol) {
    for (const ElementarySolution& s : list)
        if ((s.x - x).lpNorm<Eigen::Infinity>() <= tol) return;
    list.push_back({region, x});
}
}  // namespace

std::vector<ElementarySolution> ElementaryExample::closed_form_solutions(const Eigen::Vector2d& f,
                                                                         double margin) const {
    std::vector<ElementarySolution> out;
    const double tol = 1e-9 * scale_of(f);
    for (int i = 1; i <= 4; ++i)
        if (in_sigma(i, f, margin)) add_distinct(out, i, closed_form(i, f), tol);
    return out;
}

double ElementaryExample::violation(const Eigen::Vector2d& f, const ElementaryState& x) const {
    const double un = x[0], ut = x[1], ln = x[2], lt = x[3], F = coefficient(ut - u_tau_old_);
    double v = std::max(std::abs(a_ * un - b_ * ut - f[0] - ln), std::abs(-b_ * un + c_ * ut - f[1] - lt));
    v = std::max({v, std::max(un, 0.0), std::max(ln, 0.0), std::abs(un * ln)});
    v = std::max(v, std::max(std::abs(lt) + F * ln, 0.0));  // |lambda_tau| <= -F lambda_nu
    const double slip = ut - u_tau_old_;
    // lambda_tau = F lambda_nu sign(slip) when slipping: with the cone bound this is
    // the complementarity (lambda_tau - F lambda_nu sign) * slip = 0 on each side.
    if (slip > 0) v = std::max(v, std::abs((lt - F * ln) * slip));
    if (slip < 0) v = std::max(v, std::abs((lt + F * ln) * slip));
    return v;
}

int ElementaryExample::region_of(const ElementaryState& x, double tol) const {
    if (std::abs(x[2]) <= tol) return 1;
    const double slip = x[1] - u_tau_old_;
    if (std::abs(slip) <= tol) return 2;
    return slip > 0 ? 3 : 4;
}

std::vector<ElementarySolution> ElementaryExample::rate_solutions(const Eigen::Vector2d& f) const {
    std::vector<ElementarySolution> out;
    const double tol = 1e-9 * scale_of(f);
    // Rounding margins: on a set's edge a slip root sits at an end of its interval (w = 0, or
    // N = 0), where the bracketing cannot see it, and the open or sticking state it equals is
    // admitted instead.
    const double margin = 1e-12 * scale_of(f);
    if (in_sigma(1, f, -margin)) add_distinct(out, 1, closed_form(1, f), tol);
    const double fn = f[0], ft = f[1], ut = u_tau_old_, b = b_, c = c_;
    const double N0 = b * ut + fn;  // the pressure at the sticking position
    if (N0 >= -margin && std::abs(c * ut - ft) <= coefficient(0) * std::max(N0, 0.0) + margin)
        add_distinct(out, 2, ElementaryState(0, ut, -std::max(N0, 0.0), c * ut - ft), tol);
    for (const double s : {1.0, -1.0}) {
        // Slip w with s w > 0 and N(w) >= 0. Beyond w = f_tau / c - u_tau_old, G_+ > 0 (F N >= 0);
        // G_- needs N > 0, so w > -N0 / b.
        double near = 0, far = 0;
        if (s > 0) {
            near = std::max(0.0, -N0 / b);
            far = std::max(near, ft / c - ut) * (1 + 1e-9) + 1e-12;
        } else {
            if (N0 <= 0) continue;
            near = 0;
            far = -N0 / b;
        }
        auto G = [&](double w) {
            const double N = b * (ut + w) + fn;
            return c * (ut + w) - ft + s * coefficient(w) * N;
        };
        // Points from the near end: geometric from 1e-14 of the span (the Stribeck drop acts on
        // |w| ~ slip_time x stribeck_velocity, which may be tiny), then uniform.
        const double span = far - near;
        if (!(std::abs(span) > 0)) continue;
        std::vector<double> t;
        for (int k = 0; k <= 3000; ++k) t.push_back(std::pow(10.0, -14 + 14.0 * k / 3000));
        for (int k = 1; k <= 3000; ++k) t.push_back(static_cast<double>(k) / 3000);
        std::sort(t.begin(), t.end());
        double w0 = near + t[0] * span, g0 = G(w0);
        for (size_t k = 1; k < t.size(); ++k) {
            const double w1 = near + t[k] * span, g1 = G(w1);
            if ((g0 < 0) != (g1 < 0)) {
                double lo = w0, hi = w1, glo = g0;
                for (int it = 0; it < 200 && lo != hi; ++it) {
                    const double mid = 0.5 * (lo + hi), gm = G(mid);
                    if ((gm < 0) == (glo < 0))
                        lo = mid, glo = gm;
                    else
                        hi = mid;
                    if (std::nextafter(lo, hi) == hi) break;
                }
                const double w = 0.5 * (lo + hi), N = b * (ut + w) + fn;
                add_distinct(out, s > 0 ? 3 : 4, ElementaryState(0, ut + w, -N, -s * coefficient(w) * N),
                             tol);
            }
            w0 = w1;
            g0 = g1;
        }
    }
    return out;
}

std::vector<ElementarySolution> ElementaryExample::solver_solutions(const Eigen::Vector2d& f,
                                                                    ContactSolver& solver,
                                                                    int* failed) const {
    const ContactProblem p = problem(f);
    const double s = scale_of(f), tol = 1e-8 * s;
    static const double normal[] = {0, -0.1, -1, -10};
    static const double tangential[] = {-10, -1, -0.1, 0, 0.1, 1, 10};
    std::vector<ElementarySolution> out;
    int failures = 0;
    Eigen::VectorXd lambda(2);
    for (double ln : normal)
        for (double lt : tangential) {
            lambda << ln * s, lt * s;
            try {
                solver.solve(p, ContactSolverOptions{1e-13, 100, 0}, lambda);  // Newton alone
            } catch (const ContactSolveError&) {
                ++failures;
                continue;
            }
            const Eigen::Vector2d u = p.a + p.W * lambda;
            const ElementaryState x(u[0], u[1], lambda[0], lambda[1]);
            add_distinct(out, region_of(x, tol), x, tol);
        }
    if (failed) *failed = failures;
    return out;
}

}  // namespace contactbody
