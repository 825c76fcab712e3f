#include "contact/contact_solver.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>

#include "contact/friction_law.hpp"
#include "linalg/dense_lu.hpp"
#include "util/build_features.hpp"
#include "util/text.hpp"

namespace contactbody {

std::uint64_t ContactProblem::next_revision() {
    static std::atomic<std::uint64_t> counter{0};
    return ++counter;
}

void ContactProblem::set_operator(const Eigen::MatrixXd& delassus, double friction_coefficient) {
    const Eigen::Index n = delassus.rows() / (1 + tangents);
    const bool friction = friction_coefficient > 0;
    W = friction ? delassus : Eigen::MatrixXd(delassus.topLeftCorner(n, n));
    a.resize(friction ? (1 + tangents) * n : n);
    this->friction.setConstant(friction ? n : 0, friction_coefficient);
    revision = next_revision();
}

void ContactProblem::set_conditions(Eigen::Index n, double friction_coefficient) {
    const bool with_friction = friction_coefficient > 0;
    W.resize(0, 0);
    a.setZero(with_friction ? (1 + tangents) * n : n);
    friction.setConstant(with_friction ? n : 0, friction_coefficient);
    revision = next_revision();
}

double ContactProblem::RateLaw::coefficient(double base, double slip, double* derivative) const {
    const double v = std::abs(slip) / slip_time, sign = slip >= 0 ? 1.0 : -1.0;
    double F = base + viscous * v, dF = viscous;
    if (stribeck_velocity > 0 && excess != 0) {
        const double e = excess * std::exp(-v / stribeck_velocity);
        F += e;
        dF -= e / stribeck_velocity;
    }
    if (derivative) *derivative = dF * sign / slip_time;
    return F;
}

double ContactProblem::coefficient(Eigen::Index i, double slip, double* derivative) const {
    return rate.coefficient(friction[i], slip, derivative);
}

// Alart-Curnier residual phi(lambda), zero exactly at a solution; piecewise linear in lambda,
// so a semi-smooth Newton step lands on the solution once the node states are right.
// The augmentation parameters r = 1 / diag(W) make phi a force in every row.
double ContactSolver::residual(const ContactProblem& p, const Eigen::VectorXd& lambda, Eigen::VectorXd& phi) {
    const Eigen::Index n = p.gap_limit.size();
    // W lambda: a substep's first residual is at the last solve's multipliers (the warm
    // start), whose product the last residual formed; it is kept, not formed again.
    const bool known = p.revision != 0 && p.revision == product_revision_ &&
                       lambda.size() == product_lambda_.size() && lambda == product_lambda_;
    if (!known) {
        ++residual_evaluations_;
        if (compact_products_ && compact_revision_ != p.revision) {  // W changed: its substep size did
            sliding_.reset();
            compact_revision_ = p.revision;
        }
        product_.resize(lambda.size());
        if (!compact_products_ || !sliding_.apply(p.W, p.friction, lambda, product_))
            product_.noalias() = p.W * lambda;
        product_lambda_ = lambda;
        product_revision_ = p.revision;
    }
    u_hat_ = product_ + p.a;
    return apply_law(p, lambda, r_.tail(r_.size() - n), phi);  // r_T: W's tangential diagonal
}

double ContactSolver::apply_law(const ContactProblem& p, const Eigen::VectorXd& lambda,
                                const Eigen::Ref<const Eigen::VectorXd>& rT, Eigen::VectorXd& phi) {
    const Eigen::Index n = p.gap_limit.size();
    const int tangents = p.has_friction() ? p.tangents : 0;
    const bool rate = tangents > 0 && p.rate_dependent();
    status_.resize(n);
    pattern_.resize(n);
    law_F_.resize(n);
    law_trial_.resize(n);
    law_ratio_.resize(n);
    law_direction_.resize(tangents * n);
    if (rate) {
        law_dF_.setZero(n);
        law_slip_direction_.setZero(tangents * n);
    }
    return apply_node_law(
        p, lambda, [&](int c, Eigen::Index i) { return u_hat_[c * n + i]; },
        [&](int c, Eigen::Index i) { return c == 0 ? r_[i] : rT[i]; },
        [&](Eigen::Index i, const double* slip) {
            if (!rate) return p.friction[i];
            const double size = tangential_size(slip, tangents);
            double dF = 0;
            const double F = p.coefficient(i, size, &dF);
            // At s = 0 the interval takes the right derivative (direction +x), the disc none:
            // docs/decisions.md, "One friction law for any number of tangents".
            const bool derivative = size > 0 || tangents == 1;
            law_dF_[i] = derivative ? dF : 0.0;
            for (int t = 0; t < tangents; ++t)
                law_slip_direction_[t * n + i] = size > 0 ? slip[t] / size : derivative ? 1.0 : 0.0;
            return F;
        },
        [&](Eigen::Index i, const NodeLaw& law) {
            status_[i] = law.status;
            pattern_[i] = law.pattern;
            law_F_[i] = law.coefficient;
            law_trial_[i] = law.trial;
            law_ratio_[i] = law.ratio;
            for (int t = 0; t < tangents; ++t) law_direction_[t * n + i] = law.direction[t];
        },
        phi);
}

// The reduced Newton matrix of pattern_ (its unknowns in reduced_), LU-factored.
void ContactSolver::factor(const ContactProblem& p, const ContactSolverOptions& options) {
    const Eigen::Index n = p.gap_limit.size(), m = p.W.rows();
    const bool friction = p.has_friction();
    reduced_.clear();
    reduced_.reserve(static_cast<size_t>(m));  // once: no allocation when the set grows
    for (Eigen::Index i = 0; i < n; ++i)
        if (pattern_[i] != 0) reduced_.push_back(static_cast<int>(i));
    if (friction)
        for (Eigen::Index i = 0; i < n; ++i)
            if (pattern_[i] == 1) reduced_.push_back(static_cast<int>(n + i));
    const Eigen::Index k = static_cast<Eigen::Index>(reduced_.size());
    newton_lu_.reserve(m);
    auto A = newton_lu_.matrix(k);
    for (Eigen::Index b = 0; b < k; ++b) {
        const int col = reduced_[b];
        const bool slipping = friction && col < n && pattern_[col] != 1;
        const double sf = slipping ? slip_sign(p, col) : 0;
        for (Eigen::Index a = 0; a < k; ++a)
            A(a, b) = p.W(reduced_[a], col) - (slipping ? sf * p.W(reduced_[a], n + col) : 0.0);
    }
    if (!newton_lu_.factor(k)) {
        lu_revision_ = 0;
        throw ContactSolveError("contact solver: singular Newton matrix");
    }
    ++base_;                 // an update of the last factorization no longer applies
    lu_pattern_ = pattern_;  // what the LU is of
    lu_friction_ = p.friction;
    lu_revision_ = p.revision;
    if (options.update_factorization && update_.columns_of() != m) {
        // Sized once, for the largest update: updating allocates nothing.
        update_.reserve(m, max_update_unknowns);
        gathered_.resize(m, 2 * max_update_unknowns);
        in_changed_.assign(static_cast<size_t>(m), false);
        update_x_.resize(m);
        update_pattern_.resize(n);
    }
}

// Semi-smooth Newton direction delta (J delta = -phi, J the generalized Jacobian of phi for
// the node states found by residual()), computed on the reduced system: open nodes' unknowns
// and slipping nodes' tangential ones follow explicitly from the others,
//   open:      delta_N = phi_N, delta_T = -phi_T     (lambda goes to 0)
//   slipping:  delta_T = -phi_T + sf (phi_N - delta_N),  sf = +-F_i
// and the remaining rows (N of active nodes, T of sticking ones), divided by r, read
//   W(N_i, :) delta = phi_N / r_N,   W(T_i, :) delta = -phi_T / r_T.
// The reduced matrix depends only on W, the pattern and F, so its LU is reused while they hold,
// and (options.update_factorization) updated while few nodes have changed state since.
void ContactSolver::newton_direction(const ContactProblem& p, const ContactSolverOptions& options,
                                     Direction how, const Eigen::VectorXd& lambda) {
    const bool reuse = how != Direction::factor;
    const Eigen::Index n = p.gap_limit.size(), m = p.W.rows();
    const bool friction = p.has_friction();
    explicit_.setZero(m);  // the delta_R-independent part of delta
    for (Eigen::Index i = 0; i < n; ++i) {
        if (pattern_[i] == 0) {
            explicit_[i] = phi_[i];
            if (friction) explicit_[n + i] = -phi_[n + i];
        } else if (friction && pattern_[i] != 1) {
            // = -lambda_T - sf lambda_N (phi_T = lambda_T - sf trial, phi_N = -lambda_N - trial):
            // exactly zero after a projected step (options.project_slip).
            explicit_[n + i] = projects_slip_ ? -lambda[n + i] - slip_sign(p, i) * lambda[i]
                                              : -phi_[n + i] + slip_sign(p, i) * phi_[i];
        }
    }
    if (!reuse) factor(p, options);
    reduced_rhs_.resize(m);
    const Eigen::Index k = static_cast<Eigen::Index>(reduced_.size());
    // W explicit_ by its nonzero columns (open nodes' and slipping nodes' tangential ones:
    // in sliding about half of W's), in the reduced system's rows only: the normal rows,
    // and the tangential ones when a node sticks (reduced_ lists the normal rows first).
    const bool sticking = friction && (pattern_.array() == 1).any();
    const Eigen::Index rows = sticking ? m : n;
    explicit_product_.setZero(m);
    for (Eigen::Index j = 0; j < m; ++j)
        if (explicit_[j] != 0) explicit_product_.head(rows).noalias() += explicit_[j] * p.W.col(j).head(rows);
    if (how == Direction::update) {
        updated_solve(p);
    } else {
        for (Eigen::Index a = 0; a < k; ++a) {
            const int row = reduced_[a];
            reduced_rhs_[a] = newton_target(p, row) - explicit_product_[row];
        }
        step_ = explicit_;
        if (k > 0) {
            newton_lu_.solve_in_place(reduced_rhs_.head(k));
            for (Eigen::Index a = 0; a < k; ++a) step_[reduced_[a]] = reduced_rhs_[a];
        }
    }
    if (friction)
        for (Eigen::Index i = 0; i < n; ++i)
            if (pattern_[i] == 2 || pattern_[i] == -2) step_[n + i] -= slip_sign(p, i) * step_[i];
}

namespace {
// Whether unknown j (N rows first, then T) is in the reduced Newton system of pattern P.
template <class Pattern>
bool in_system(const Pattern& P, Eigen::Index n, Eigen::Index j) {
    return j < n ? P[j] != 0 : P[j - n] == 1;
}
}  // namespace

// The Newton matrix of pattern P as an m x m matrix: the reduced system's entries on its
// unknowns, W's diagonal on the others (their steps are explicit; W's scale, so that the
// update below does not mix entries of W with ones).
double ContactSolver::newton_entry(const ContactProblem& p, const Pattern& P, Eigen::Index a,
                                   Eigen::Index b) const {
    const Eigen::Index n = p.gap_limit.size();
    if (!in_system(P, n, b)) return a == b ? diagonal_[b] : 0.0;
    if (!in_system(P, n, a)) return 0.0;
    if (b < n && (P[b] == 2 || P[b] == -2)) {
        const double sf = P[b] > 0 ? p.friction[b] : -p.friction[b];
        return p.W(a, b) - sf * p.W(a, n + b);
    }
    return p.W(a, b);
}

// x <- J0^-1 x for the factored pattern's m x m Newton matrix J0 (columns of x).
void ContactSolver::base_solve(const ContactProblem& p, Eigen::Ref<Eigen::MatrixXd> x) {
    const Eigen::Index m = p.W.rows(), k = static_cast<Eigen::Index>(reduced_.size());
    const Eigen::Index n = p.gap_limit.size();
    for (Eigen::Index j = 0; j < m; ++j)
        if (!in_system(lu_pattern_, n, j)) x.row(j) /= diagonal_[j];
    if (k == 0) return;
    auto g = gathered_.topLeftCorner(k, x.cols());
    for (Eigen::Index a = 0; a < k; ++a) g.row(a) = x.row(reduced_[static_cast<size_t>(a)]);
    if (x.cols() == 1)  // the vector kernels: the blocked ones cost 3x on one column
        newton_lu_.solve_in_place(gathered_.col(0).head(k));
    else
        newton_lu_.solve_in_place(g);
    for (Eigen::Index a = 0; a < k; ++a) x.row(reduced_[static_cast<size_t>(a)]) = g.row(a);
}

// The Newton matrix J of this pattern as the factored one's J0 plus a low-rank change, for
// Woodbury's formula J^-1 = J0^-1 - Z Cap^-1 V^T J0^-1, Z = J0^-1 U, Cap = I + V^T Z. Only
// the rows and columns of the c unknowns C of the nodes whose state changed differ:
// J - J0 = E_C D(C, :) + D(~C, C) E_C^T = U V^T, U = [E_C, D(~C, C)], V^T = [D(C, :); E_C^T].
// False where a refactorization is cheaper (c > k / 20: docs/decisions.md, "Updated Newton
// factorizations") or the capacitance matrix is singular.
bool ContactSolver::prepare_update(const ContactProblem& p) {
    const Eigen::Index n = p.gap_limit.size(), m = p.W.rows();
    const bool friction = p.has_friction();
    if (update_.columns_of() != m) return false;  // factored without the update's buffers
    if (update_base_ == base_ && update_pattern_.size() == pattern_.size() && update_pattern_ == pattern_)
        return true;
    // The changed unknowns are overwritten even where the update is then declined: a decline
    // is followed by a refactorization, which moves base_, so the cached return above never
    // sees them.
    std::vector<int>& changed = update_.changed();
    changed.clear();
    for (Eigen::Index i = 0; i < n; ++i) {
        if (pattern_[i] == lu_pattern_[i]) continue;
        changed.push_back(static_cast<int>(i));
        if (friction) changed.push_back(static_cast<int>(n + i));
    }
    const Eigen::Index c = update_.size();
    const Eigen::Index k = static_cast<Eigen::Index>(reduced_.size());
    if (c > max_update_unknowns || update_share * c > k) return false;
    for (int j : changed) in_changed_[static_cast<size_t>(j)] = true;
    auto rows = update_.rows();
    auto columns = update_.columns();
    columns.setZero();
    for (Eigen::Index i = 0; i < c; ++i) {
        const Eigen::Index j = changed[static_cast<size_t>(i)];
        for (Eigen::Index b = 0; b < m; ++b)
            rows(i, b) = newton_entry(p, pattern_, j, b) - newton_entry(p, lu_pattern_, j, b);
        for (Eigen::Index a = 0; a < m; ++a)
            if (!in_changed_[static_cast<size_t>(a)])
                columns(a, i) = newton_entry(p, pattern_, a, j) - newton_entry(p, lu_pattern_, a, j);
    }
    for (int j : changed) in_changed_[static_cast<size_t>(j)] = false;
    if (!update_.prepare([&](auto&& x) { base_solve(p, x); })) return false;
    update_base_ = base_;
    update_pattern_ = pattern_;
    return true;
}

// The Newton step on this pattern's system by the prepared update (prepare_update).
void ContactSolver::updated_solve(const ContactProblem& p) {
    const Eigen::Index n = p.gap_limit.size(), m = p.W.rows();
    update_x_.setZero();
    for (Eigen::Index j = 0; j < m; ++j)
        if (in_system(pattern_, n, j)) update_x_[j] = newton_target(p, j) - explicit_product_[j];
    update_.solve(update_x_, [&](auto&& x) { base_solve(p, x); });
    step_ = explicit_;
    for (Eigen::Index j = 0; j < m; ++j)
        if (in_system(pattern_, n, j)) step_[j] = update_x_[j];
}

std::vector<signed char> ContactSolver::factored_pattern(std::uint64_t revision) const {
    if (update_.columns_of() == 0 || lu_revision_ == 0 || lu_revision_ != revision) return {};
    return {lu_pattern_.data(), lu_pattern_.data() + lu_pattern_.size()};
}

// After a full step of the pattern's Newton system, each slipping node's tangential
// multiplier is -sf lambda_N up to round-off: set it so (projects_slip_).
void ContactSolver::project_slip(const ContactProblem& p, Eigen::VectorXd& lambda) const {
    const Eigen::Index n = p.gap_limit.size();
    for (Eigen::Index i = 0; i < n; ++i)
        if (pattern_[i] == 2 || pattern_[i] == -2) lambda[n + i] = -slip_sign(p, i) * lambda[i];
}

// J delta = -phi with every row of J, for a 2D slip-rate law (a slipping node's friction
// depends on its own tangential motion, which the reduced system eliminates). Rows as in
// residual():
//   open:   phi_N = -lambda_N, phi_T = lambda_T
//   active: phi_N = r_N (gap - u_N)
//   stick:  phi_T = r_T (u_T - origin)
//   slip:   phi_T = lambda_T - s F(v) trial, trial = -lambda_N - r_N (gap - u_N), s = sign(z)
// The full Jacobian's direction (full_jacobian.cpp) with one tangent, but with the open nodes'
// rows kept: eliminating them was 3-5 % faster and changed the outputs' last bits, which moved
// the belt's stick-slip cycles (docs/decisions.md, "The 2D contact solve's reduced Newton").
void ContactSolver::rate_newton_direction(const ContactProblem& p) {
    const Eigen::Index n = p.gap_limit.size(), m = p.W.rows();
    newton_lu_.reserve(m);
    auto J = newton_lu_.matrix(m);
    J.setZero();
    for (Eigen::Index i = 0; i < n; ++i) {
        const Eigen::Index t = n + i;
        if (pattern_[i] == 0) {
            J(i, i) = -1;
            J(t, t) = 1;
            continue;
        }
        J.row(i) = -r_[i] * p.W.row(i);
        if (pattern_[i] == 1) {
            J.row(t) = r_[t] * p.W.row(t);
            continue;
        }
        const double s = pattern_[i] > 0 ? 1.0 : -1.0;
        // d trial = -d lambda_N + r_N W(N_i, :) d lambda; dF = F' W(T_i, :) d lambda
        const double dF = law_dF_[i] * law_slip_direction_[i];  // dF/ds (signed)
        J.row(t) = -s * (law_F_[i] * r_[i] * p.W.row(i) + law_trial_[i] * dF * p.W.row(t));
        J(t, i) += s * law_F_[i];
        J(t, t) += 1;
    }
    if (!newton_lu_.factor(m)) throw ContactSolveError("contact solver: singular Newton matrix");
    step_ = -phi_;
    newton_lu_.solve_in_place(step_);
}

ContactSolveInfo ContactSolver::solve(const ContactProblem& p, const ContactSolverOptions& options,
                                      Eigen::VectorXd& lambda) {
    const Eigen::Index m = p.W.rows();
    if (lambda.size() != m) lambda.setZero(m);
    if (p.revision == 0 || p.revision != diagonal_revision_) {  // W's diagonal: strided reads
        diagonal_ = p.W.diagonal();
        r_ = diagonal_.cwiseInverse();
        diagonal_revision_ = p.revision;
    }
    if constexpr (solid_bodies_built) {
        if (p.has_friction() && (p.tangents == 2 || !options.reduced_newton)) {
            start_ = lambda;
            try {
                return solve_full_jacobian(p, options, lambda);
            } catch (const ContactSolveError& e) {
                // As in 2D: node by node from the same start, F at each node's own slip where
                // the contact nodes keep their tangential inertia (ContactProblem::RateLaw).
                lambda = start_;
                ContactSolveInfo info;
                info.iterations = options.max_iterations;
                const bool exact_rate = p.rate_dependent() && p.rate.tangential_inertia;
                if (p.tangents == 2 ? gauss_seidel_disc(p, options, lambda, info, p.rate.tangential_inertia)
                                    : gauss_seidel(p, options, lambda, info, exact_rate))
                    return info;
                Text msg;
                msg << e.what() << "; node by node from the same start: relative residual " << info.residual
                    << " after " << info.sweeps << " sweeps";
                throw ContactSolveError(msg.str());
            }
        }
    } else if (p.tangents != 1) {
        throw std::logic_error(
            "ContactSolver: this build has no isotropic friction (CONTACTBODY_SOLID_BODIES=0)");
    }
    projects_slip_ = options.project_slip && p.has_friction() && !p.rate_dependent();
    compact_products_ = projects_slip_ && p.revision != 0;
    start_ = lambda;
    const bool rate = p.has_friction() && p.rate_dependent() && p.rate.tangential_inertia;
    ContactSolveInfo info;
    try {
        return newton(p, options, lambda, rate);
    } catch (const ContactSolveError& e) {
        // Newton can cycle where the step is badly conditioned (large F, large steps);
        // Gauss-Seidel is slower but does not cycle on these problems.
        lambda = start_;
        info.iterations = options.max_iterations;
        if (gauss_seidel(p, options, lambda, info, rate)) return info;
        if (!rate) {
            Text msg;
            msg << e.what() << "; Gauss-Seidel from the same start: relative residual " << info.residual
                << " after " << info.sweeps << " sweeps";
            throw ContactSolveError(msg.str());
        }
    }
    // A rate law's last resort: where a substep has several solutions near each other (no
    // tangential mass, velocity weakening) Newton's cycling can still land on one, given
    // all its iterations.
    lambda = start_;
    try {
        ContactSolveInfo last = newton(p, options, lambda, false);
        last.sweeps = info.sweeps;
        return last;
    } catch (const ContactSolveError& e) {
        Text msg;
        msg << e.what() << " (after Newton stagnated and Gauss-Seidel from the same start "
            << "reached a relative residual " << info.residual << " in " << info.sweeps << " sweeps)";
        throw ContactSolveError(msg.str());
    }
}

namespace {

// The exact solution of one node's problem with the other nodes' multipliers fixed:
// u = q + A l (A the node's 2x2 block of W, or 1x1 without friction), open, stick or slip.
struct Local {
    double lN = 0, lT = 0;
};

Local solve_node(double qN, double qT, double aNN, double aNT, double aTT, double gap, double origin,
                 double F, bool friction) {
    Local l;
    if (qN <= gap) return l;  // open
    if (!friction) {
        l.lN = (gap - qN) / aNN;
        return l;
    }
    // stick: u_N = gap, u_T = origin
    const double det = aNN * aTT - aNT * aNT;
    const double bN = gap - qN, bT = origin - qT;
    const Local stick{(aTT * bN - aNT * bT) / det, (aNN * bT - aNT * bN) / det};
    if (stick.lN <= 0 && std::abs(stick.lT) <= -F * stick.lN) return stick;
    // slip with sign s: l_T = s F l_N, u_N = gap
    for (const double s : {1.0, -1.0}) {
        const double slope = aNN + s * F * aNT;
        if (!(slope > 0)) continue;
        const double lN = bN / slope, lT = s * F * lN;
        const double slip = qT + aNT * lN + aTT * lT - origin;
        if (lN <= 0 && slip * s >= 0) return {lN, lT};
    }
    // No consistent local state (the node's own problem is ill-posed): the cone projection
    // of the sticking solution.
    l.lN = std::min(0.0, stick.lN);
    l.lT = std::clamp(stick.lT, F * l.lN, -F * l.lN);
    return l;
}

// The same with a slip-rate law, F taken at the slip being solved for (not lagged: with a
// Stribeck drop the lagged iteration F_k+1 = F(slip(F_k)) diverges once
// |W_TT dF/dslip p| > 1, which at large pressures and substeps is the common case). Sticking
// needs F(0); slipping with sign s is one equation in the slip sigma (s sigma > 0):
//   r(sigma) = qT - origin + (aNT + s F(sigma) aTT) lN(sigma) - sigma,
//   lN(sigma) = (gap - qN) / (aNN + s F(sigma) aNT),
// continuous, with s r(0) > 0 where the node cannot stick, and s r -> -inf as |sigma| grows
// (F bounded, or growing with the viscous term): a root is bracketed and bisected.
Local solve_rate_node(const ContactProblem& p, Eigen::Index i, double qN, double qT, double aNN, double aNT,
                      double aTT, double current_slip) {
    const double gap = p.gap_limit[i], origin = p.slip_origin[i];
    if (qN <= gap) return {};
    const double bN = gap - qN, bT = origin - qT;
    const double det = aNN * aTT - aNT * aNT;
    const Local stick{(aTT * bN - aNT * bT) / det, (aNN * bT - aNT * bN) / det};
    const double F0 = p.coefficient(i, 0.0);
    if (stick.lN <= 0 && std::abs(stick.lT) <= -F0 * stick.lN) return stick;
    // s r at sigma = s t, and lN there; false where the node's problem is ill-posed.
    auto signed_residual = [&](double s, double t, double& value, double& lN) {
        const double F = p.coefficient(i, s * t);
        const double slope = aNN + s * F * aNT;
        if (!(slope > 0)) return false;
        lN = bN / slope;
        value = s * (qT - origin + (aNT + s * F * aTT) * lN) - t;
        return std::isfinite(value);
    };
    // The direction the node slips in now first (continuity), else the one the sticking
    // solution's excess points to: lT = s F lN with lN < 0.
    const double first = current_slip != 0 ? (current_slip > 0 ? 1.0 : -1.0) : (stick.lT > 0 ? -1.0 : 1.0);
    for (const double s : {first, -first}) {
        double r0, lN;
        if (!signed_residual(s, 0.0, r0, lN) || !(r0 > 0)) continue;
        // A bracket near the node's current slip, so that the sweeps follow one root where
        // there are several: intervals [c 2^k, c 2^(k+1)] outward from c, alternately above
        // and below it, then [0, the lowest].
        const double c = std::max({s * current_slip, 1e-300, 1e-12 * (std::abs(qT) + std::abs(origin))});
        double lo = 0, hi = 0, r_lo = 0, r_hi = 0;
        bool bracketed = false;
        double up = c, r_up, down = c, r_down;
        if (!signed_residual(s, c, r_up, lN)) continue;
        r_down = r_up;
        bool up_ok = true, down_ok = true;
        for (int k = 0; k < 2100 && !bracketed && (up_ok || down_ok); ++k) {
            if (up_ok) {
                double r;
                if (!signed_residual(s, 2 * up, r, lN)) {
                    up_ok = false;
                } else if (r_up > 0 && !(r > 0)) {
                    lo = up, hi = 2 * up, r_lo = r_up, r_hi = r, bracketed = true;
                } else {
                    up *= 2, r_up = r;
                }
            }
            if (!bracketed && down_ok) {
                double r;
                const double next = 0.5 * down;
                if (next < 1e-300 * c || !signed_residual(s, next, r, lN)) {
                    down_ok = false;  // [0, down]: r0 > 0, so a root below iff r_down <= 0
                    if (!(r_down > 0)) lo = 0, hi = down, r_lo = r0, r_hi = r_down, bracketed = true;
                } else if (r > 0 && !(r_down > 0)) {
                    lo = next, hi = down, r_lo = r, r_hi = r_down, bracketed = true;
                } else {
                    down = next, r_down = r;
                }
            }
        }
        if (!bracketed) continue;
        for (int k = 0; k < 200 && hi - lo > 1e-15 * hi; ++k) {
            const double mid = 0.5 * (lo + hi);
            double r_mid;
            if (!signed_residual(s, mid, r_mid, lN)) break;
            if ((r_mid > 0) == (r_lo > 0))
                lo = mid, r_lo = r_mid;
            else
                hi = mid, r_hi = r_mid;
        }
        const double root = std::abs(r_lo) < std::abs(r_hi) ? lo : hi;
        double r_root;
        if (!signed_residual(s, root, r_root, lN)) continue;
        return {lN, s * p.coefficient(i, s * root) * lN};
    }
    // No consistent local state: the cone projection of the sticking solution.
    Local l;
    l.lN = std::min(0.0, stick.lN);
    l.lT = std::clamp(stick.lT, F0 * l.lN, -F0 * l.lN);
    return l;
}

}  // namespace

bool ContactSolver::gauss_seidel(const ContactProblem& p, const ContactSolverOptions& options,
                                 Eigen::VectorXd& lambda, ContactSolveInfo& info, bool exact_rate) {
    const Eigen::Index n = p.gap_limit.size();
    const bool friction = p.has_friction();
    const auto sweep = [&] {
        for (Eigen::Index i = 0; i < n; ++i) {
            const Eigen::Index t = n + i;
            const double lN = lambda[i], lT = friction ? lambda[t] : 0.0;
            const double aNT = friction ? p.W(i, t) : 0.0, aTT = friction ? p.W(t, t) : 1.0;
            const double qN = u_hat_[i] - p.W(i, i) * lN - aNT * lT;
            const double qT = friction ? u_hat_[t] - aNT * lN - aTT * lT : 0.0;
            const Local l =
                friction && p.rate_dependent() && exact_rate
                    ? solve_rate_node(p, i, qN, qT, p.W(i, i), aNT, aTT, u_hat_[t] - p.slip_origin[i])
                    : solve_node(qN, qT, p.W(i, i), aNT, aTT, p.gap_limit[i],
                                 friction ? p.slip_origin[i] : 0.0,
                                 !friction            ? 0.0
                                 : p.rate_dependent() ? p.coefficient(i, u_hat_[t] - p.slip_origin[i])
                                                      : p.friction[i],
                                 friction);
            if (l.lN != lN) {
                u_hat_.noalias() += (l.lN - lN) * p.W.col(i);
                lambda[i] = l.lN;
            }
            if (friction && l.lT != lT) {
                u_hat_.noalias() += (l.lT - lT) * p.W.col(t);
                lambda[t] = l.lT;
            }
        }
    };
    // (the residual also sets u_hat_ = a + W lambda)
    return sweep_until(options, info, sweep, [&] { return residual(p, lambda, phi_); });
}

ContactSolveInfo ContactSolver::newton(const ContactProblem& p, const ContactSolverOptions& options,
                                       Eigen::VectorXd& lambda, bool stop_on_stagnation) {
    ContactSolveInfo info;
    info.residual = residual(p, lambda, phi_);
    double merit = phi_.squaredNorm();
    const bool rate = p.has_friction() && p.rate_dependent();
    if (saved_base_.size() > 0) {  // factor_at: the saved run's factorization, then its updates
        bool fits = options.update_factorization && !rate && saved_base_.size() == pattern_.size();
        for (Eigen::Index i = 0; fits && i < saved_base_.size(); ++i)
            fits = saved_base_[i] == 0 || saved_base_[i] == 1 ||
                   (p.has_friction() && (saved_base_[i] == 2 || saved_base_[i] == -2));
        if (fits) {
            pattern_.swap(saved_base_);
            try {
                factor(p, options);
                ++factorizations_;
            } catch (const ContactSolveError&) {
                lu_revision_ = 0;  // singular: the iterations factor their own
            }
            pattern_.swap(saved_base_);
        }
        saved_base_.resize(0);
    }
    // With a slip-rate law Newton can cycle among node states where the substep has several
    // solutions or none near the start; the exact node-by-node fallback then solves it. So,
    // asked to, it stops once `stagnation` iterations have not halved the best residual (a
    // converging Newton halves it every iteration or two) instead of running to
    // max_iterations.
    constexpr int stagnation = 12;
    double best = info.residual;
    int best_iteration = 0;
    while (!(info.residual <= options.tolerance)) {
        if (stop_on_stagnation && info.iterations - best_iteration >= stagnation) {
            Text msg;
            msg << "contact solver stagnated: " << stagnation << " Newton iterations did not "
                << "halve the relative residual " << best << " (tolerance " << options.tolerance << ")";
            throw ContactSolveError(msg.str());
        }
        if (info.iterations >= options.max_iterations) {
            Text msg;
            msg << "contact solver did not converge in " << options.max_iterations
                << " iterations (relative residual " << info.residual << ", tolerance " << options.tolerance
                << ")";
            throw ContactSolveError(msg.str());
        }
        ++info.iterations;
        ++newton_iterations_;
        // The reduced Newton matrix is fixed by W and the node states: when the states of
        // the last solve recur, its LU is reused (O(m^2) per iteration instead of O(m^3)).
        // With few changed nodes (options.update_factorization) it is updated instead.
        const bool factored = !rate && p.revision != 0 && p.revision == lu_revision_ &&
                              pattern_.size() == lu_pattern_.size() &&
                              p.friction.size() == lu_friction_.size() && p.friction == lu_friction_;
        const bool same = factored && pattern_ == lu_pattern_;
        const bool update = factored && !same && options.update_factorization && prepare_update(p);
        const bool reuse = same || update;
        if (rate) {
            lu_revision_ = 0;  // the buffer now holds another matrix
            rate_newton_direction(p);
        } else {
            newton_direction(p, options,
                             same     ? Direction::reuse
                             : update ? Direction::update
                                      : Direction::factor,
                             lambda);
        }
        if (update) ++updates_;
        if (!reuse) ++factorizations_;
        if (!step_.allFinite()) {
            lu_revision_ = 0;
            throw ContactSolveError("contact solver: singular Newton matrix");
        }
        // Backtracking on |phi|^2; if no step decreases it, take the full one anyway
        // (phi is piecewise linear: the full step is exact once the states settle).
        double alpha = 1, res = 0;
        bool decreased = false;
        for (int k = 0; k < 8 && !decreased; ++k) {
            if (k > 0) alpha *= 0.5;
            trial_ = lambda + alpha * step_;
            if (projects_slip_ && alpha == 1) project_slip(p, trial_);
            res = residual(p, trial_, trial_phi_);
            decreased = trial_phi_.squaredNorm() <= (1 - 1e-4 * alpha) * merit || res <= options.tolerance;
        }
        // An updated direction that needed a shorter step may have lost accuracy to a badly
        // conditioned update: the next iteration refactors.
        if (update && alpha < 1) lu_revision_ = 0;
        if (decreased) {  // the residual at the accepted point is the trial's
            lambda.swap(trial_);
            phi_.swap(trial_phi_);
            info.residual = res;
        } else {
            lambda += step_;
            if (projects_slip_) project_slip(p, lambda);
            info.residual = residual(p, lambda, phi_);
        }
        merit = phi_.squaredNorm();
        if (info.residual < 0.5 * best) {
            best = info.residual;
            best_iteration = info.iterations;
        }
    }
    return info;
}

}  // namespace contactbody
