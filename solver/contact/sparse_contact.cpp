#include "contact/sparse_contact.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "contact/friction_law.hpp"
#include "linalg/pattern_lu.hpp"
#include "linalg/supernodal_kernels.hpp"
#include "linalg/trailing_cholesky.hpp"
#include "util/build_features.hpp"
#include "util/text.hpp"

namespace contactbody {

namespace {
// A 3D body's isotropic friction (the disc), which a 2D-only build leaves out (build_features.hpp).
bool isotropic(const ContactProblem& p) { return solid_bodies_built && p.has_friction() && p.tangents == 2; }

// One r_T for every tangential direction, the mean of K's: invariant under a turn about y.
double tangential_stiffness(const HeldOperator& K, Eigen::Index n, Eigen::Index i, int tangents) {
    double sum = 0;
    for (int t = 1; t <= tangents; ++t) sum += K.stiffness(t * n + i);
    return sum / tangents;
}

// Whether node i holds a slip in `slip` (tangents x n): any of its tangents' entries.
bool holds_slip(const std::vector<double>& slip, size_t i, size_t n) {
    for (size_t s = i; s < slip.size(); s += n)
        if (slip[s] != 0) return true;
    return false;
}

double slip_sign(const ContactProblem& p, Eigen::Index i, signed char pattern) {
    return pattern > 0 ? p.friction[i] : -p.friction[i];
}
}  // namespace

double SparseContactSolver::residual(const HeldOperator& K, const ContactProblem& p, const Eigen::VectorXd& w,
                                     const Eigen::VectorXd& lambda, Eigen::VectorXd& phi) {
    const Eigen::Index n = p.gap_limit.size();
    const int tangents = p.has_friction() ? p.tangents : 0;
    trial_pattern_.resize(n);
    trial_status_.resize(n);
    trial_direction_.resize(tangents * n);
    trial_ratio_.resize(n);
    return apply_node_law(
        p, lambda, [&](int c, Eigen::Index i) { return c == 0 ? -w[K.dof(i)] : w[K.dof(c * n + i)]; },
        [&](int c, Eigen::Index i) {
            return c == 0 ? K.stiffness(i) : tangential_stiffness(K, n, i, tangents);
        },
        [&](Eigen::Index i, const double*) { return p.friction[i]; },
        [&](Eigen::Index i, const NodeLaw& law) {
            trial_status_[i] = law.status;
            trial_pattern_[i] = law.pattern;
            for (int t = 0; t < tangents; ++t) trial_direction_[t * n + i] = law.direction[t];
            trial_ratio_[i] = law.ratio;
        },
        phi);
}

// The multipliers of w: the contact dofs' reactions K w - rhs (B^T lambda), zero at open nodes.
void SparseContactSolver::reactions(const HeldOperator& K, const ContactProblem& p,
                                    const Eigen::VectorXd& rhs) {
    const Eigen::Index n = p.gap_limit.size();
    const bool friction = p.has_friction();
    for (Eigen::Index i = 0; i < n; ++i) {
        const bool active = pattern_[i] != 0;
        lambda_new_[i] = active ? -(K.row_product(i, w_new_) - rhs[K.dof(i)]) : 0.0;
        for (Eigen::Index c = 1; friction && c <= p.tangents; ++c)
            lambda_new_[c * n + i] = active ? K.row_product(c * n + i, w_new_) - rhs[K.dof(c * n + i)] : 0.0;
    }
}

void SparseContactSolver::held_set(const ContactProblem& p, const HeldOperator& K, bool ratios_known) {
    const bool slips = K.slip_coefficient() > 0;
    const Eigen::Index n = pattern_.size();
    const Eigen::Index tangents = static_cast<Eigen::Index>(held_.size()) / n - 1;
    const bool friction = p.has_friction();
    slip_.assign(static_cast<size_t>(tangents * n), 0.0);
    for (Eigen::Index i = 0; i < n; ++i) {
        held_[static_cast<size_t>(i)] = pattern_[i] != 0;
        for (Eigen::Index c = 1; c <= tangents; ++c)
            held_[static_cast<size_t>(c * n + i)] = friction && pattern_[i] == 1;
        if (!slips || !friction || (pattern_[i] != 2 && pattern_[i] != -2)) continue;
        if (isotropic(p)) {  // along the pattern's slip direction (the last residual's)
            // A solve's first pattern has no iterate's rho yet: its slips are held where the
            // factor holds them (docs/decisions.md, "A 3D body's factor holds its slipping nodes").
            if (ratios_known ? !(ratio_[i] <= max_held_ratio)
                             : !holds_slip(K.slip(), static_cast<size_t>(i), static_cast<size_t>(n)))
                continue;
            for (Eigen::Index c = 0; c < tangents; ++c)
                slip_[static_cast<size_t>(c * n + i)] = direction_[c * n + i];
        } else
            slip_[static_cast<size_t>(i)] = pattern_[i] > 0 ? 1 : -1;
    }
    // Where half of GCR's kept directions can span every slip's unknowns, they solve them
    // without held solves once made: a 3D factor holds slips only beyond that.
    if (isotropic(p)) {
        Eigen::Index held = 0;
        for (Eigen::Index i = 0; i < n; ++i)
            held += holds_slip(slip_, static_cast<size_t>(i), static_cast<size_t>(n));
        if (tangents * held <= std::max(max_directions, kept_capacity_ / 2)) std::fill(slip_.begin(), slip_.end(), 0.0);
    }
}

namespace {
// The friction coefficient that K's factor gives contact unknown j's row (sf of a slipping
// tangential row), else 0.
double factor_slip(const HeldOperator& K, Eigen::Index j, Eigen::Index n) {
    if (j < n || j - n >= static_cast<Eigen::Index>(K.slip().size())) return 0.0;
    return K.slip()[static_cast<size_t>(j - n)] * K.slip_coefficient();
}

// Whether node i's held slip in `a` and in `b` (tangents x n) differ in kind: one holds a slip
// and the other none, or their directions are more than 60 degrees apart (in 2D: opposite
// signs). A 3D slip's direction moves with every Newton iteration; where it moved less, the
// factor's slip is kept and GCR takes the difference.
bool slip_differs(const std::vector<double>& a, const std::vector<double>& b, size_t i, size_t n) {
    double ab = 0, aa = 0, bb = 0;
    for (size_t s = i; s < a.size(); s += n) ab += a[s] * b[s], aa += a[s] * a[s], bb += b[s] * b[s];
    if ((aa == 0) != (bb == 0)) return true;
    return aa != 0 && !(ab >= 0.5 * std::sqrt(aa * bb));
}
}  // namespace

void SparseContactSolver::held_solve(HeldOperator& K, const Eigen::VectorXd& rhs, bool affine,
                                     const Eigen::Ref<const Eigen::VectorXd>& xi, Eigen::VectorXd& x) {
    const Eigen::Index m = K.unknowns();
    if (affine)
        b_ = rhs;
    else
        b_.setZero();
    for (Eigen::Index j = 0; j < m; ++j) values_[j] = affine ? targets_[j] : 0.0;
    for (size_t k = 0; k < coupling_.size(); ++k) {
        const Coupling& c = coupling_[k];
        const double v = xi[static_cast<Eigen::Index>(k)];
        if (c.kind == load)
            b_[K.dof(c.unknown)] += v;
        else
            values_[c.unknown] = v / K.stiffness(c.unknown);
    }
    K.impose(b_, values_);
    K.solve(b_, x);
    ++solves_;
}

void SparseContactSolver::responses(const HeldOperator& K, const ContactProblem& p,
                                    const Eigen::VectorXd& rhs, const Eigen::VectorXd& x, bool homogeneous,
                                    Eigen::Ref<Eigen::VectorXd> out) const {
    const Eigen::Index n = p.gap_limit.size(), q = static_cast<Eigen::Index>(coupling_.size());
    const auto reaction = [&](Eigen::Index j) {
        return K.row_product(j, x) - (homogeneous ? 0.0 : rhs[K.dof(j)]);
    };
    for (Eigen::Index k = 0; k < q; ++k) {
        const Eigen::Index j = coupling_[static_cast<size_t>(k)].unknown;
        out[k] = reaction(j);
        out[q + k] = x[K.dof(j)];
        out[2 * q + k] = j >= n ? reaction(j % n) : 0.0;
    }
}

void SparseContactSolver::equations(const HeldOperator& K, const ContactProblem& p,
                                    const Eigen::Ref<const Eigen::VectorXd>& response, bool homogeneous,
                                    Eigen::Ref<Eigen::VectorXd> e) const {
    const Eigen::Index n = p.gap_limit.size(), q = static_cast<Eigen::Index>(coupling_.size());
    const auto reaction = [&](Eigen::Index k) { return response[k]; };
    const auto value = [&](Eigen::Index k) { return response[q + k]; };
    const auto pressure = [&](Eigen::Index k) { return response[2 * q + k]; };
    for (Eigen::Index k = 0; k < q; ++k) {
        const Coupling& c = coupling_[static_cast<size_t>(k)];
        const Eigen::Index j = c.unknown, i = j % n;
        if (solid_bodies_built && c.partner >= 0) {
            // A 3D slipping node: phi_T = l_T - F p t(z) linearized at the iterate (Newton, not
            // a fixed point in t): l_T - F p t - rho (I - t t^T) (q - q0), q = l_T - r_T u_T,
            // rho = F p / |z| (node_law's ratio), q0 the iterate's (the shift).
            const int component = static_cast<int>(j / n) - 1;
            const Eigen::Index x_k = component == 0 ? k : c.partner, z_k = component == 0 ? c.partner : k;
            const double rT = tangential_stiffness(K, n, i, p.tangents);
            const double t[2] = {direction_[i], direction_[n + i]};
            const double l[2] = {reaction(x_k), reaction(z_k)};
            const double qT[2] = {l[0] - rT * value(x_k), l[1] - rT * value(z_k)};
            const double along = t[0] * qT[0] + t[1] * qT[1];
            e[k] = l[component] - p.friction[i] * t[component] * pressure(k) -
                   ratio_[i] * (qT[component] - t[component] * along) +
                   (homogeneous ? 0.0 : newton_shift_[component * n + i]);
            continue;
        }
        e[k] = c.held ? K.stiffness(j) * (value(k) - (homogeneous ? 0.0 : targets_[j]))
                      : reaction(k) - (c.sf != 0 ? c.sf * pressure(k) : 0.0);
    }
}

// The step of pattern_ from the multipliers in lambda_trial_ (the iterate): w_new_, lambda_new_.
void SparseContactSolver::solve_pattern(HeldOperator& K, const ContactProblem& p, const Eigen::VectorXd& rhs,
                                        double scale, double tolerance) {
    const Eigen::Index n = p.gap_limit.size(), m = K.unknowns();
    const bool friction = p.has_friction();
    int differing = 0;
    held_set(p, K, newton_iteration_ > 1);
    for (Eigen::Index i = 0; i < n; ++i) {
        targets_[i] = -p.gap_limit[i];  // u_N = -w_y = gap limit
        for (Eigen::Index c = 1; c < m / n; ++c)
            targets_[c * n + i] = friction ? p.slip_origin[(c - 1) * n + i] : 0.0;
    }
    for (Eigen::Index j = 0; j < m; ++j)
        differing += held_[static_cast<size_t>(j)] != K.held()[static_cast<size_t>(j)];
    // A 3D pattern whose held dofs alone differ from the factor's in more than max_differing
    // (a contact set still growing: a static start's load increments) asks for no held slips:
    // it is refactored as the Cholesky, at half the LU's cost, and its slips are GCR's, until
    // the set settles.
    if (isotropic(p) && differing > max_differing_) std::fill(slip_.begin(), slip_.end(), 0.0);
    for (Eigen::Index i = 0; i < n && !slip_.empty(); ++i)
        differing += slip_differs(slip_, K.slip(), static_cast<size_t>(i), static_cast<size_t>(n));
    // A pattern that differs from the factor's held set in more than max_differing dofs is
    // refactored at once, and one that differs in fewer tried on the factor with max_detour
    // solves. On a factor that holds nothing, where a refactorization costs more held solves
    // than GCR may take, detours of up to max_directions solves are rented until their solves
    // come to what a refactorization costs (docs/decisions.md, "When to refactor"). The
    // detours' count restarts with each factor and where a state is saved or restored
    // (forget), so that a restored state replays.
    const double refactorization = K.refactorization_in_solves();
    const bool costly = refactorization > max_directions &&
                        std::none_of(K.held().begin(), K.held().end(), [](char h) { return h != 0; });
    if (detour_operator_ != &K || detour_refactorizations_ != K.refactorizations()) {
        detour_solves_ = 0;  // a factor's detours start at none
        detour_operator_ = &K;
        detour_refactorizations_ = K.refactorizations();
    }
    // A factor that can hold the pattern's slips (one tangent) is refactored where more dofs
    // differ than its refactorization costs in solves (docs/decisions.md, "A 2D body's factor
    // holds its slipping nodes").
    const int most = K.slip_coefficient() > 0
                         ? std::min<int>(max_differing_, static_cast<int>(2 * refactorization))
                         : max_differing_;
    const bool renting = differing > most && costly && detour_solves_ < refactorization;
    // A factor whose held slips are the pattern's but for their directions' drift (a 3D
    // slip's moves with each Newton iteration and substep) is kept, and GCR takes the
    // difference, until GCR's solves beyond one a Newton iteration have cost a
    // refactorization: then it is refactored at the pattern's directions (the same rent).
    const bool drifting = isotropic(p) && differing <= most && K.holds_slips() && !K.holds(held_, slip_);
    if ((differing > most && !renting) || (drifting && detour_solves_ >= refactorization))
        K.hold(held_, slip_);
    const bool detour = !K.holds(held_, slip_);
    const long before = solves_;
    if (!solve_coupled(K, p, rhs, scale, tolerance, detour && !costly ? max_detour : max_directions,
                       detour)) {
        K.hold(held_, slip_);
        solve_coupled(K, p, rhs, scale, tolerance, max_directions, false);
    } else if (renting) {
        detour_solves_ += solves_ - before;
    } else if (drifting && detour) {
        detour_solves_ += std::max<long>(0, solves_ - before - 1);
    }
    reactions(K, p, rhs);
}

// Modified Gram-Schmidt of the image in `slot` (its direction's own, made from its responses)
// against the kept ones before it, and normalized: its combination of the directions as made
// (combinations_'s column) follows, so that only q-sized images are orthogonalized. False
// where what is left of the image is not above `dependent` times what it was (or is zero).
bool SparseContactSolver::orthonormalize(int slot, Eigen::Index q, double dependent) {
    auto c = images_.col(slot).head(q);
    auto t = combinations_.col(slot).head(slot + 1);
    t.setZero();
    t[slot] = 1;
    const double before = c.norm();
    for (int j = 0; j < slot; ++j) {
        const double beta = images_.col(j).head(q).dot(c);
        c -= beta * images_.col(j).head(q);
        t.head(j + 1) -= beta * combinations_.col(j).head(j + 1);
    }
    const double norm = c.norm();
    if (!(norm > dependent * before)) return false;
    c /= norm;
    t /= norm;
    return true;
}

// The kept directions from `first` on as the first ones, their images made again from their
// responses (the pattern or the coefficients changed) and orthonormalized, those that depend
// on the others dropped.
void SparseContactSolver::remake_images(const HeldOperator& K, const ContactProblem& p, int first) {
    const Eigen::Index q = static_cast<Eigen::Index>(coupling_.size());
    int kept = 0;
    for (int j = first; j < kept_; ++j, ++kept)
        if (j != kept) move_direction(j, kept);
    kept_ = kept;
    make_images(K, p);
    if (const SupernodalKernels* kernels = K.dense_kernels(); kernels && orthonormalize_all(*kernels, q)) return;
    make_images(K, p);  // one by one (what orthonormalize_all may have begun on is made again)
    kept = 0;
    for (int j = 0; j < kept_; ++j) {
        if (kept != j) {
            move_direction(j, kept);
            images_.col(kept).head(q) = images_.col(j).head(q);
        }
        if (orthonormalize(kept, q, 1e-10)) ++kept;
    }
    kept_ = kept;
}

void SparseContactSolver::make_images(const HeldOperator& K, const ContactProblem& p) {
    const Eigen::Index n = p.gap_limit.size(), q = static_cast<Eigen::Index>(coupling_.size());
    for (int j = 0; j < kept_; ++j) {
        coupled_responses(j, n, response_.head(3 * q));
        equations(K, p, response_.head(3 * q), true, images_.col(j).head(q));
    }
}

// The kept images orthonormalized all at once, by the Cholesky QR twice (images = Q R, the
// Gram matrix's Cholesky factor R^T, so that Q = images R^-1 and the combinations are R^-1) in
// the factor's dense kernels: the same orthonormal images as Gram-Schmidt's, at the speed of
// matrix products (docs/decisions.md, "GCR's kept directions span the slips"). False, the
// images left to Gram-Schmidt, where some image is near the others' span (its part outside
// it below 1e-6 of it: there the Gram matrix loses the digits that Gram-Schmidt keeps).
bool SparseContactSolver::orthonormalize_all(const SupernodalKernels& kernels, Eigen::Index q) {
    const Eigen::Index k = kept_, ld = images_.rows();
    if (k == 0) return true;
    if (k > q) return false;
    // Compact k x q and k x k blocks in workspace sized once (solve).
    Eigen::Map<Eigen::MatrixXd> transposed(transposed_.data(), k, q);
    Eigen::Map<Eigen::MatrixXd> factors[2] = {{gram_first_.data(), k, k}, {gram_second_.data(), k, k}};
    for (int pass = 0; pass < 2; ++pass) {
        Eigen::Map<Eigen::MatrixXd>& l = factors[pass];
        transposed = images_.topLeftCorner(q, k).transpose();
        kernels.lower_product(transposed.data(), k, k, q, l.data(), k);
        if (pass == 0)
            for (Eigen::Index j = 0; j < k; ++j) image_norm_[j] = std::sqrt(l(j, j));
        if (kernels.cholesky(l.data(), k, k) >= 0) return false;
        for (Eigen::Index j = 0; j < k && pass == 0; ++j)
            if (!(l(j, j) > 1e-6 * image_norm_[j])) return false;
        kernels.solve_right(l.data(), k, k, images_.data(), q, ld);
    }
    auto t = combinations_.topLeftCorner(k, k);
    t.setIdentity();
    for (const auto& l : factors) kernels.solve_right(l.data(), k, k, t.data(), k, combinations_.rows());
    return true;
}

// xi += the kept directions combined by coefficients_ (over the directions as made), and with
// `solutions` w_new_ += their solutions combined alike (combined_: the sizes added, for the
// digits lost); without, w_new_ is left to be solved again (combined_ infinite).
void SparseContactSolver::add_directions(Eigen::Index q, bool solutions) {
    // The solutions in one matrix-vector product: w_new_ read and written once, not once a
    // direction (docs/decisions.md, "The kept solutions combined in one product").
    if (solutions) w_new_.noalias() += solutions_.leftCols(kept_) * coefficients_.head(kept_);
    for (int j = 0; j < kept_; ++j) {
        const double a = coefficients_[j];
        if (a == 0) continue;
        for (Eigen::Index k = 0; k < q; ++k)
            xi_[k] += a * directions_(coupling_[static_cast<size_t>(k)].unknown, j);
        combined_ += solutions ? std::abs(a) * solution_size_[j] : std::numeric_limits<double>::infinity();
        coefficients_[j] = 0;
    }
}

// What the equations read of a kept direction's solution (responses() of the coupled unknowns)
// from its responses at every contact unknown.
void SparseContactSolver::coupled_responses(int slot, Eigen::Index n, Eigen::Ref<Eigen::VectorXd> out) const {
    const Eigen::Index q = static_cast<Eigen::Index>(coupling_.size()), m = directions_.rows();
    const auto all = responses_.col(slot);
    for (Eigen::Index k = 0; k < q; ++k) {
        const Eigen::Index j = coupling_[static_cast<size_t>(k)].unknown;
        out[k] = all[j];
        out[q + k] = all[m + j];
        out[2 * q + k] = j >= n ? all[j % n] : 0.0;
    }
}

// Direction `from` (as made: loads and values, responses, solution, size) into slot `to`.
void SparseContactSolver::move_direction(int from, int to) {
    directions_.col(to) = directions_.col(from);
    responses_.col(to) = responses_.col(from);
    solutions_.col(to) = solutions_.col(from);
    solution_size_[to] = solution_size_[from];
}

// A kept direction (loads and values on the factor's dofs) stays valid on the same factor
// when the pattern changes, where it has no entry at an unknown that is no longer coupled:
// such entries are eliminated between the directions (one direction fewer each), so that a
// substep whose pattern differs from the last by a node keeps the others' directions. The
// direction eliminated with is parked (the slots from max_directions down), not dropped: a
// node at the contact zone's end that opens and closes at alternate substeps (the midpoint
// scheme's chatter there) couples its unknowns again a substep later, and its parked
// directions, valid again, come back without a held solve (unpark).
void SparseContactSolver::eliminate_uncoupled() {
    const Eigen::Index m = directions_.rows();
    for (Eigen::Index u = 0; u < m; ++u) {
        if (coupling_of_[static_cast<size_t>(u)] >= 0) continue;
        int pivot = -1;
        double largest = 0;
        for (int j = 0; j < kept_; ++j) {
            const double a = std::abs(directions_(u, j));
            if (a > largest) largest = a, pivot = j;
        }
        if (pivot < 0) continue;
        for (int j = 0; j < kept_; ++j) {
            if (j == pivot || directions_(u, j) == 0) continue;
            const double f = directions_(u, j) / directions_(u, pivot);
            directions_.col(j) -= f * directions_.col(pivot);
            responses_.col(j) -= f * responses_.col(pivot);
            solutions_.col(j) -= f * solutions_.col(pivot);
            solution_size_[j] += std::abs(f) * solution_size_[pivot];
            directions_(u, j) = 0;
        }
        const int slot = kept_capacity_ - parked_ - 1;
        if (slot >= kept_) {  // else no room: dropped
            move_direction(pivot, slot);
            ++parked_;
        }
        if (pivot != --kept_) move_direction(kept_, pivot);
    }
}

// The parked directions without an entry at an uncoupled unknown, back among the kept ones.
void SparseContactSolver::unpark() {
    const Eigen::Index m = directions_.rows();
    for (int slot = kept_capacity_ - parked_; slot < kept_capacity_;) {
        bool valid = true;
        for (Eigen::Index u = 0; u < m && valid; ++u)
            valid = directions_(u, slot) == 0 || coupling_of_[static_cast<size_t>(u)] >= 0;
        if (!valid) {
            ++slot;
            continue;
        }
        move_direction(slot, kept_++);
        const int first = kept_capacity_ - parked_--;  // the parked slots stay together
        if (slot != first)
            move_direction(first, slot);
        else
            ++slot;
    }
}

bool SparseContactSolver::solve_coupled(HeldOperator& K, const ContactProblem& p, const Eigen::VectorXd& rhs,
                                        double scale, double tolerance, int max_iterations, bool detour) {
    const Eigen::Index n = p.gap_limit.size(), m = K.unknowns();
    const bool friction = p.has_friction();
    // A Newton iteration after the first on the factor of the last (the same right-hand side
    // and targets) starts from the last one's solution: the unknowns coupled there stay
    // coupled, held to their values or unloaded where the pattern no longer couples them, and
    // GCR moves them there, most often in the kept directions, instead of a held solve of
    // the new guesses (one held solve fewer for each Newton iteration after the first).
    const bool warm =
        newton_iteration_ > 1 && last_operator_ == &K && last_refactorizations_ == K.refactorizations();
    // The unknowns: what the pattern asks that the factor's held set does not give.
    coupling_.clear();
    for (Eigen::Index j = 0; j < m; ++j) {
        const Eigen::Index i = j % n;
        const bool wants = held_[static_cast<size_t>(j)] != 0, has = K.held()[static_cast<size_t>(j)] != 0;
        const bool slips = j >= n && friction && (pattern_[i] == 2 || pattern_[i] == -2);
        // A slipping node's friction, F p along its slip direction: +-F in 2D, F t in 3D (t
        // the last residual's, held through the pattern's solve).
        const double sf = !slips         ? 0.0
                          : isotropic(p) ? p.friction[i] * direction_[(j / n - 1) * n + i]
                                         : slip_sign(p, i, pattern_[i]);
        // A slipping row that the factor has is in K's solve already, unless its coefficient
        // differs (the static one, another node state, or a 3D slip direction that moved:
        // then both of the node's tangential unknowns, whose law is one).
        bool other = !slips || !isotropic(p) ? sf != factor_slip(K, j, n) : false;
        for (Eigen::Index c = 0; slips && isotropic(p) && c < p.tangents; ++c)
            other = other || p.friction[i] * direction_[c * n + i] != factor_slip(K, (1 + c) * n + i, n);
        if (wants && !has)
            coupling_.push_back({static_cast<int>(j), load, 0.0, true, -1});
        else if (!wants && has)
            coupling_.push_back({static_cast<int>(j), value, sf, false, -1});
        else if (!wants && other)
            coupling_.push_back({static_cast<int>(j), load, sf, false, -1});
        else if (warm &&
                 !std::isnan(last_xi_[j]))  // coupled at the last iteration: held to its value, or unloaded
            coupling_.push_back({static_cast<int>(j), has ? value : load, has ? 0.0 : sf, has, -1});
    }
    for (Eigen::Index j = 0; j < m; ++j) coupling_of_[static_cast<size_t>(j)] = -1;
    for (size_t k = 0; k < coupling_.size(); ++k)
        coupling_of_[static_cast<size_t>(coupling_[k].unknown)] = static_cast<int>(k);
    if (isotropic(p)) {  // a slipping node's x and z equations take both
        for (Coupling& c : coupling_) {
            const Eigen::Index i = c.unknown % n;
            if (c.unknown >= n && (pattern_[i] == 2 || pattern_[i] == -2))
                c.partner = coupling_of_[static_cast<size_t>(c.unknown < 2 * n ? 2 * n + i : n + i)];
        }
    }
    // Their first values from the iterate's multipliers (a held value from rest); warm, the
    // last iteration's (its solution is theirs: no held solve).
    const Eigen::Index q = static_cast<Eigen::Index>(coupling_.size());
    double force_scale = scale;
    for (Eigen::Index k = 0; k < q; ++k) {
        const Coupling& c = coupling_[static_cast<size_t>(k)];
        const Eigen::Index i = c.unknown % n;
        double guess = 0;  // the reaction wanted, less what the factor's slipping row gives
        if (warm)
            guess = std::isnan(last_xi_[c.unknown])
                        ? (c.kind == value ? targets_[c.unknown] * K.stiffness(c.unknown) : 0.0)
                        : last_xi_[c.unknown];
        else if (c.kind == load && c.held)
            guess = c.unknown < n ? -lambda_trial_[i] : lambda_trial_[c.unknown];
        else if (c.kind == load)
            guess = c.sf * -lambda_trial_[i];
        if (c.kind == load && !warm) guess -= factor_slip(K, c.unknown, n) * -lambda_trial_[i];
        xi_[k] = guess;
        if (c.kind == load) force_scale = std::max(force_scale, std::abs(guess));
    }
    if (warm) {
        ++warm_starts_;
        w_new_ = last_w_;
        combined_ = last_combined_;
    } else {
        held_solve(K, rhs, true, xi_, w_new_);
        combined_ = 0;
    }
    if (q > 0) {
        auto r = krylov_residual_.head(q);
        auto response = response_.head(3 * q);
        const auto solution_residual = [&] {  // what the equations lack at w_new_
            responses(K, p, rhs, w_new_, false, response);
            equations(K, p, response, false, r);
            r = -r;
        };
        solution_residual();
        force_scale = std::max(force_scale, r.lpNorm<Eigen::Infinity>());
        const double goal = 0.5 * tolerance * force_scale;
        // The kept directions hold while the factor does (what a held solve gives them). Each
        // keeps its held solve's responses at every contact unknown, so that where the
        // pattern changed (its unknowns: eliminate_uncoupled) or the coefficients did
        // (the friction, a 3D slip direction and its rho: every Newton iteration of a 3D slip)
        // its image is made again without a solve, and the images orthonormalized again.
        // The directions stay as made; combinations_ says which of them each orthonormal
        // image's direction is.
        // The same pattern couples the same unknowns, but where a warm start kept some: both.
        bool same_coupling = kept_pattern_.size() == pattern_.size() && kept_pattern_ == pattern_ &&
                             kept_unknowns_.size() == coupling_.size();
        for (size_t k = 0; k < coupling_.size() && same_coupling; ++k)
            same_coupling = kept_unknowns_[k] == coupling_[k].unknown;
        if (kept_operator_ != &K || kept_refactorizations_ != K.refactorizations()) {
            kept_ = parked_ = 0;
            kept_operator_ = &K;
            kept_refactorizations_ = K.refactorizations();
        } else if (!same_coupling || kept_friction_.size() != p.friction.size() ||
                   kept_friction_ != p.friction || kept_direction_.size() != direction_.size() ||
                   kept_direction_ != direction_ || kept_ratio_.size() != ratio_.size() ||
                   kept_ratio_ != ratio_) {
            // The unknowns follow the pattern and, where the factor holds slipping rows, the
            // friction too (a node slipping with the static coefficient is coupled, with the
            // kinetic one not): entries at unknowns no longer coupled go first.
            if (!same_coupling) unpark();
            eliminate_uncoupled();
            remake_images(K, p, 0);
        }
        kept_pattern_ = pattern_;
        kept_unknowns_.resize(coupling_.size());
        for (size_t k = 0; k < coupling_.size(); ++k) kept_unknowns_[k] = coupling_[k].unknown;
        kept_friction_ = p.friction;
        kept_direction_ = direction_;
        kept_ratio_ = ratio_;
        // GCR: the kept directions' images c_j are orthonormal, so the residual's part in
        // their span goes at no solve; each new direction costs one held solve. Directions
        // are kept as loads and values (per contact unknown) with their solutions; the
        // solution's residual is checked at the end of a round: the directions are combined
        // from the directions as made, whose round-off GCR's own residual does not see where
        // they are near dependent (F = 1.2). Where it is above the goal, GCR goes on from it
        // (a round); the third round's solution is taken.
        int iterations = 0;
        for (int round = 0;; ++round) {
            bool changed = false;
            coefficients_.head(kept_).setZero();
            for (int j = 0; j < kept_; ++j) {
                const double alpha = images_.col(j).head(q).dot(r);
                r -= alpha * images_.col(j).head(q);
                coefficients_.head(j + 1) += alpha * combinations_.col(j).head(j + 1);
                changed = true;
            }
            while (r.lpNorm<Eigen::Infinity>() > goal) {
                if (iterations >= max_iterations) {
                    if (detour) {
                        add_directions(q, false);
                        return false;
                    }
                    Text msg;
                    msg << "sparse contact solve: GCR on " << q << " coupled unknowns did not reach " << goal
                        << " N/m in " << max_iterations << " held solves (" << r.lpNorm<Eigen::Infinity>()
                        << " N/m left)";
                    throw ContactSolveError(msg.str());
                }
                if (kept_ + parked_ == kept_capacity_ && parked_ > 0) {
                    parked_ = 0;                       // the parked ones go first
                } else if (kept_ == kept_capacity_) {  // the older half goes (the rest orthonormalized again)
                    add_directions(q, true);
                    remake_images(K, p, kept_capacity_ / 2);
                }
                const int slot = kept_;
                auto v = direction_coupled_.head(q);
                auto c = images_.col(slot).head(q);
                v = r;
                held_solve(K, rhs, false, v, z_);
                solutions_.col(slot) = z_;
                solution_size_[slot] = z_.lpNorm<Eigen::Infinity>();
                directions_.col(slot).setZero();
                for (Eigen::Index k = 0; k < q; ++k)
                    directions_(coupling_[static_cast<size_t>(k)].unknown, slot) = v[k];
                for (Eigen::Index j = 0; j < m; ++j) {  // its responses at every contact unknown
                    responses_(j, slot) = K.row_product(j, z_);
                    responses_(m + j, slot) = z_[K.dof(j)];
                }
                coupled_responses(slot, n, response_.head(3 * q));
                equations(K, p, response_.head(3 * q), true, c);
                if (!orthonormalize(slot, q, 0))
                    throw ContactSolveError("sparse contact solve: GCR broke down");
                const double alpha = c.dot(r);
                r -= alpha * c;
                coefficients_[slot] = 0;
                coefficients_.head(slot + 1) += alpha * combinations_.col(slot).head(slot + 1);
                changed = true;
                ++kept_;
                ++iterations;
                ++krylov_iterations_;
            }
            // The solution: the directions' solutions combined where that costs less than a
            // held solve (2 n_f flops per kept direction against 4 per factor nonzero), and
            // solved again where it costs more or may have lost digits that a solve keeps (its
            // terms much larger than it).
            add_directions(
                q, static_cast<double>(kept_) * static_cast<double>(K.size()) <= 2 * K.factor_nonzeros());
            if (!changed) break;
            if (combined_ > max_cancellation * w_new_.lpNorm<Eigen::Infinity>()) {
                held_solve(K, rhs, true, xi_, w_new_);
                combined_ = 0;
            }
            if (round == 2) break;
            solution_residual();
            if (!(r.lpNorm<Eigen::Infinity>() > goal)) break;
            ++rounds_;
        }
    }
    // What the next Newton iteration starts from on this factor (solve: the same right-hand
    // side and targets).
    last_xi_.setConstant(std::numeric_limits<double>::quiet_NaN());
    for (Eigen::Index k = 0; k < q; ++k) last_xi_[coupling_[static_cast<size_t>(k)].unknown] = xi_[k];
    last_w_ = w_new_;
    last_combined_ = combined_;
    last_operator_ = &K;
    last_refactorizations_ = K.refactorizations();
    return true;
}

ContactSolveInfo SparseContactSolver::solve(HeldOperator& K, const ContactProblem& p,
                                            const ContactSolverOptions& options, const Eigen::VectorXd& rhs,
                                            const Eigen::VectorXd& sticking, Eigen::VectorXd& lambda,
                                            Eigen::VectorXd& w, bool fresh_factor) {
    const Eigen::Index n = p.gap_limit.size(), nf = K.size();
    const bool friction = p.has_friction();
    const Eigen::Index m = friction ? (1 + p.tangents) * n : n;
    if (friction && K.unknowns() != m)
        throw std::logic_error(
            "SparseContactSolver: the held operator's contact unknowns do not fit the friction's");
    if (lambda.size() != m) lambda.setZero(m);
    // Workspace: sized once (resizing to the same size does not allocate).
    const Eigen::Index m2 = K.unknowns();
    held_.resize(static_cast<size_t>(m2));
    coupling_.reserve(static_cast<size_t>(m2));
    kept_unknowns_.reserve(static_cast<size_t>(m2));
    values_.resize(m2);
    targets_.resize(m2);
    xi_.resize(m2);
    krylov_residual_.resize(m2);
    for (Eigen::VectorXd* v : {&w, &w_new_, &w_trial_, &b_, &z_, &last_w_}) v->resize(nf);
    last_xi_.resize(m2);
    for (Eigen::VectorXd* v : {&lambda_new_, &lambda_trial_}) v->resize(m);
    coupling_of_.resize(static_cast<size_t>(m2));
    response_.resize(3 * m2);
    direction_coupled_.resize(m2);
    max_differing_ = options.max_differing;
    // GCR's kept directions: enough to span a large body's slips, where its solves cost more
    // than the dense algebra on them (docs/decisions.md, "GCR's kept directions span the slips").
    const int capacity = K.dense_kernels() && K.factor_nonzeros() >= options.wide_span_nonzeros
                             ? wide_span_directions
                             : max_directions;
    if (solutions_.rows() != nf || capacity != kept_capacity_) {  // another body size: the kept directions are not its
        kept_capacity_ = capacity;
        solutions_.resize(nf, kept_capacity_);
        kept_ = parked_ = 0;
    }
    if (images_.rows() != m2 || images_.cols() != kept_capacity_) {
        responses_.resize(2 * m2, kept_capacity_);
        solution_size_.resize(kept_capacity_);
        image_norm_.resize(kept_capacity_);
        transposed_.resize(kept_capacity_, m2);
        gram_first_.resize(kept_capacity_, kept_capacity_);
        gram_second_.resize(kept_capacity_, kept_capacity_);
        images_.resize(m2, kept_capacity_);
        directions_.resize(m2, kept_capacity_);
        combinations_.setZero(kept_capacity_, kept_capacity_);
        coefficients_.setZero(kept_capacity_);
        kept_ = parked_ = 0;
    }
    // The first pattern from the State: the last substep's pressed nodes, sticking where its
    // stick memory says, else slipping along their friction.
    pattern_.resize(n);
    direction_.setZero(p.tangents == 2 ? 2 * n : 0);
    ratio_.setZero(p.tangents == 2 ? n : 0);  // the first step: t held (no iterate's z yet)
    newton_shift_.setZero(p.tangents == 2 ? 2 * n : 0);
    for (Eigen::Index i = 0; i < n; ++i) {
        if (!(lambda[i] < 0))
            pattern_[i] = 0;
        else if (!friction || sticking[i] != 0)
            pattern_[i] = 1;
        else
            pattern_[i] = lambda[n + i] >= 0 ? 2 : -2;
        if (isotropic(p) && pattern_[i] != 0) {  // along its last friction
            const double tx = lambda[n + i], tz = lambda[2 * n + i], size = std::sqrt(tx * tx + tz * tz);
            pattern_[i] = sticking[i] != 0 || !(size > 0) ? 1 : 2;
            if (size > 0) direction_[i] = tx / size, direction_[n + i] = tz / size;
        }
    }
    // A node whose state changed at each of the last two substeps is guessed to change back:
    // at a contact zone's end the midpoint scheme's nodes open and close at alternate
    // substeps, and each wrong guess costs a Newton iteration (a held solve). Counted on the
    // pad at 1,586 contact nodes: 1.26 -> 1.20 iterations a substep (decisions.md).
    if (!fresh_factor && history_ == 3 && last_patterns_[0].size() == n) {
        for (Eigen::Index i = 0; i < n; ++i) {
            const signed char back = last_patterns_[1][i];
            if (last_patterns_[0][i] != back && back != last_patterns_[2][i] &&
                pattern_[i] == last_patterns_[0][i] &&
                !(isotropic(p) && back == 2 && direction_[i] == 0 && direction_[n + i] == 0))
                pattern_[i] = back;
        }
    }
    if (fresh_factor) {  // every slip held (rho is zero here): not what K held before
        held_set(p, K, true);
        K.hold(held_, slip_);
        forget();
    }
    lambda_trial_ = lambda;
    ContactSolveInfo info;
    double merit = std::numeric_limits<double>::infinity();
    // GCR's goal (solve_coupled): the tolerance, a tenth of it for each Newton iteration that
    // ends on the pattern it solved without halving the residual (a stall that only a more
    // accurate solve of the pattern can end: F = 1.2).
    double linear_tolerance = options.tolerance;
    bool unsettled = false;  // the last iteration changed the pattern
    double loose_cap = options.inexact_cap;
    for (;;) {
        if (info.iterations >= options.max_iterations) {
            Text msg;
            msg << "sparse contact solve did not converge in " << options.max_iterations
                << " iterations (relative residual " << info.residual << ", tolerance " << options.tolerance
                << ")";
            throw ContactSolveError(msg.str());
        }
        newton_iteration_ = ++info.iterations;
        if (isotropic(p)) {  // the iterate's rho (I - t t^T) q0 (equations)
            for (Eigen::Index i = 0; i < n; ++i) {
                const double rT = tangential_stiffness(K, n, i, p.tangents);
                const double t[2] = {direction_[i], direction_[n + i]};
                const double q[2] = {lambda[n + i] - rT * w[K.dof(n + i)],
                                     lambda[2 * n + i] - rT * w[K.dof(2 * n + i)]};
                const double along = t[0] * q[0] + t[1] * q[1];
                for (int c = 0; c < 2; ++c) newton_shift_[c * n + i] = ratio_[i] * (q[c] - t[c] * along);
            }
        }
        // Inexact Newton (options.inexact_forcing): a pattern that the last iteration changed
        // is solved loosely (its solution only tells the next pattern), ever less so, where
        // the factor holds no slipping rows: with 2D's, the F = 1.2 rectangle's Newton went
        // to another solution (docs/decisions.md, "The static start's load path solves its
        // early patterns loosely").
        const bool loose = options.inexact_forcing > 0 && unsettled && !K.holds_slips();
        const double goal =
            loose ? std::max(linear_tolerance, std::min(loose_cap, options.inexact_forcing * info.residual))
                  : linear_tolerance;
        if (loose) loose_cap *= 0.5;
        // residual() measures the contact law at the solved iterate, taking its body equation
        // as exact: a loosely solved one is not, so it never ends the solve.
        const bool loosely_solved = goal > linear_tolerance;
        solve_pattern(K, p, rhs, lambda_trial_.lpNorm<Eigen::Infinity>(), goal);
        double res = residual(K, p, w_new_, lambda_new_, phi_new_);
        double trial_merit = phi_new_.squaredNorm();
        if (info.iterations > 1 && res > options.tolerance && !(trial_merit <= (1 - 1e-4) * merit)) {
            // Backtrack between the iterate and the step (both in balance: so is any mix).
            bool decreased = false;
            double alpha = 1;
            for (int k = 0; k < 8 && !decreased; ++k) {
                alpha *= 0.5;
                w_trial_ = w + alpha * (w_new_ - w);
                lambda_trial_ = lambda + alpha * (lambda_new_ - lambda);
                const double r = residual(K, p, w_trial_, lambda_trial_, phi_);
                if (phi_.squaredNorm() <= (1 - 1e-4 * alpha) * merit) {
                    decreased = true;
                    w_new_.swap(w_trial_);
                    lambda_new_.swap(lambda_trial_);
                    phi_new_.swap(phi_);
                    res = r;
                    trial_merit = phi_new_.squaredNorm();
                }
            }
            if (!decreased) {  // the full step anyway: its pattern again
                res = residual(K, p, w_new_, lambda_new_, phi_new_);
                trial_merit = phi_new_.squaredNorm();
            }
        }
        unsettled = !(trial_pattern_ == pattern_) && !(loosely_solved && res <= options.tolerance);
        if (trial_pattern_ == pattern_ && res > 0.5 * info.residual && info.iterations > 1)
            linear_tolerance = std::max(0.1 * linear_tolerance, 1e-6 * options.tolerance);
        w.swap(w_new_);
        lambda.swap(lambda_new_);
        lambda_trial_ = lambda;
        pattern_.swap(trial_pattern_);
        status_.swap(trial_status_);
        if (isotropic(p)) {
            direction_.swap(trial_direction_);
            ratio_.swap(trial_ratio_);
        }
        merit = trial_merit;
        info.residual = res;
        if (res <= options.tolerance && !loosely_solved) {
            last_patterns_[2].swap(last_patterns_[1]);
            last_patterns_[1].swap(last_patterns_[0]);
            last_patterns_[0] = pattern_;
            history_ = std::min(history_ + 1, 3);
            return info;
        }
    }
}

}  // namespace contactbody
