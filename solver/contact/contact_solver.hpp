// Frictional contact problem condensed to the contact unknowns of one substep.
//
// With n nodes, multipliers lambda = (lambda_N[0..n), lambda_T[0..n)) and the affine map
//   u_hat = a + W lambda   (u_hat = (u_N, u_T) at the nodes, W the Delassus operator B K^-1 B^T),
// find lambda such that at every node i
//   lambda_N <= 0,  u_N - gap_limit <= 0,  lambda_N (u_N - gap_limit) = 0,
//   lambda_T in F_i lambda_N Sgn(u_T - slip_origin)        (Coulomb on the slip).
// Without friction (F == 0) the tangential part is absent: lambda and u_hat have n entries.
// With a slip-rate law (RateLaw) F_i depends on the node's slip rate v = (u_T - slip_origin) /
// slip_time, implicitly: F_i(v) = friction_i + excess exp(-|v| / stribeck_velocity)
// + viscous |v|.
#pragma once

#include <Eigen/Dense>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "contact/sliding_product.hpp"
#include "linalg/dense_lu.hpp"

namespace contactbody {

enum class NodeStatus : unsigned char { open, stick, slip };

struct ContactProblem {
    // Tangential components per node: 1 (a 2D body, slip along x) or 2 (a 3D body, x and z:
    // isotropic friction |lambda_T| <= F lambda_N). With friction the unknowns are
    // (N[0..n), T_x[0..n), T_z[0..n)); slip_origin holds the x origins, then the z ones.
    int tangents = 1;
    Eigen::MatrixXd W;            // (1 + tangents) n square (or n x n without friction)
    Eigen::VectorXd a;            // u_hat at lambda = 0
    Eigen::VectorXd gap_limit;    // n: u_N must not exceed it
    Eigen::VectorXd slip_origin;  // tangents n: slip is u_T - slip_origin (unused without friction)
    Eigen::VectorXd friction;     // n: F_i, the node's friction coefficient (with friction)
    // The slip-rate dependence of F_i (off while stribeck_velocity and viscous are 0).
    struct RateLaw {
        double excess = 0;             // F_s - F_d, the Stribeck drop
        double stribeck_velocity = 0;  // m/s; 0: no Stribeck term
        double viscous = 0;            // s/m
        double slip_time = 1;          // s: v = slip / slip_time
        // Whether the contact nodes keep their tangential inertia. Then the substep is unique
        // once it is short enough, and the solver, when Newton stagnates, solves each node's
        // problem exactly with F(v) (Gauss-Seidel). Without it (redistributed_both) the
        // substep has several solutions at every size, and the solver keeps to Newton and
        // Gauss-Seidel with F lagged, whose solutions lead its trajectories on (measured:
        // examples/stribeck_bifurcation; the exact solves chose ones that ended in substeps
        // nothing could solve).
        bool tangential_inertia = true;
        bool active() const { return viscous > 0 || (stribeck_velocity > 0 && excess > 0); }
        // base + excess exp(-|v| / stribeck_velocity) + viscous |v| at this slip, and its
        // derivative with respect to the slip.
        double coefficient(double base, double slip, double* derivative = nullptr) const;
    } rate;
    bool rate_dependent() const { return rate.active(); }
    // F_i at slip (u_T - slip_origin), and dF_i/dslip.
    double coefficient(Eigen::Index i, double slip, double* derivative = nullptr) const;
    // Identifies W: the solver reuses its Newton factorization across solves while the revision
    // (nonzero) and the node states are unchanged. Set a new one whenever W changes; 0 = never
    // reuse. next_revision() gives process-wide unique values.
    std::uint64_t revision = 0;
    static std::uint64_t next_revision();
    // W from a body's Delassus operator on the normal and tangential unknowns ((1 + tangents)
    // n square): all of it with friction, its normal block without (friction_coefficient 0);
    // a and friction sized to match, and a new revision.
    void set_operator(const Eigen::MatrixXd& delassus, double friction_coefficient);
    // The conditions of n nodes without W (the sparse contact solve's): a (zero) and friction
    // sized as set_operator sizes them, W empty.
    void set_conditions(Eigen::Index n, double friction_coefficient);
    // a holds the N and T unknowns with friction, the N ones without.
    bool has_friction() const { return a.size() > gap_limit.size(); }
};

struct ContactSolverOptions {
    double tolerance = 1e-10;  // on the Alart-Curnier residual, relative to max |lambda|
    int max_iterations = 100;
    int max_sweeps = 1000;  // of the Gauss-Seidel fallback (which also stops on stagnation)
    // When a few nodes change state, solve the new Newton matrix by a low-rank update of the
    // last factorization (Woodbury) instead of refactoring it: fewer operations, other last
    // bits. The reduced body takes it; the full body keeps its bits (its substep's cost is
    // elsewhere).
    bool update_factorization = false;
    // After a full Newton step, set each slipping node's tangential multiplier to its Coulomb
    // bound -sf lambda_N, which the step reaches in exact arithmetic: while no node changes
    // state the next step's explicit part is then exactly zero, and its product with W is
    // skipped, and products with W read half of it (W_N - W_T sf on the normal unknowns).
    // Other last bits; the reduced body takes it.
    bool project_slip = false;
    // With one tangent, Newton on the reduced system (open nodes and slipping nodes' tangential
    // unknowns eliminated, its LU reused and updated while the node states hold); false: on
    // the full generalized Jacobian, as with two tangents (slower in 2D: docs/decisions.md,
    // "The 2D contact solve's reduced Newton"; benchmarks/reduced_newton.py).
    bool reduced_newton = true;
    // The sparse solve's inexact Newton: GCR's goal for a pattern that the last iteration
    // changed is this share of the last residual, at most inexact_cap, halved with each such
    // pattern (relative, as the tolerance); 0: every pattern to the tolerance. A static
    // start's load path takes 0.1 (docs/decisions.md, "The static start's load path solves its
    // early patterns loosely").
    double inexact_forcing = 0;
    double inexact_cap = 1e-2;
    // The sparse solve keeps up to SparseContactSolver::wide_span_directions GCR directions
    // (else max_directions) on a supernodal factor of this many nonzeros or more, where a solve
    // costs more than the dense algebra on them. A static start's load path takes none: its
    // growing contact set refactors before a wide span pays (docs/decisions.md, "GCR's kept
    // directions span the slips").
    double wide_span_nonzeros = 4e6;
    // The sparse solve refactors to a pattern that differs from its factor's held set in more
    // dofs than this, unless the factor holds nothing and a refactorization costs more than
    // max_directions held solves: then the pattern is tried on the factor first, until such
    // detours have cost a refactorization (SparseContactSolver::solve_pattern). A static start's
    // load path takes 1024 (docs/decisions.md, "The static start with friction, traced").
    int max_differing = 64;
};

struct ContactSolveInfo {
    int iterations = 0;
    double residual = 0;  // relative, as compared with the tolerance
    int sweeps = 0;       // Gauss-Seidel sweeps, when Newton failed and the fallback ran
};

class ContactSolveError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

class ContactSolver {
public:
    // Per node 0 open, 1 stick, +-2 slip direction: what the Newton matrix depends on besides W.
    using Pattern = Eigen::Matrix<signed char, Eigen::Dynamic, 1>;
    // Solves in place from the warm start in lambda: semi-smooth Newton, and if it does not
    // converge, nonsmooth Gauss-Seidel from the same start. With a slip-rate law Newton first
    // stops early when it stagnates, and if Gauss-Seidel fails too it runs again from the
    // start with all its iterations. Throws ContactSolveError when all fail (lambda is then
    // unspecified).
    ContactSolveInfo solve(const ContactProblem& problem, const ContactSolverOptions& options,
                           Eigen::VectorXd& lambda);
    // u_hat = a + W lambda at the last solution: the solver's last product with W.
    const Eigen::VectorXd& displacements() const { return u_hat_; }
    // Node states of the last solution (open / sticking / slipping).
    const Eigen::Matrix<NodeStatus, Eigen::Dynamic, 1>& status() const { return status_; }
    // Newton matrices factored so far (the rest of the iterations reused one), residuals
    // evaluated with a product by W (a warm start at the last solution reuses its product)
    // and Newton iterations, over the solver's life.
    long factorizations() const { return factorizations_; }
    long factorization_updates() const { return updates_; }  // Newton matrices solved by an update
    long residual_evaluations() const { return residual_evaluations_; }
    long newton_iterations() const { return newton_iterations_; }
    // The node pattern of the factorization that the next solve of W (revision) would update
    // (options.update_factorization), or empty: an updated step's last bits depend on it, so a
    // saved state keeps it. factor_at(pattern) makes the next solve factor at it first, as
    // the saved run had.
    std::vector<signed char> factored_pattern(std::uint64_t revision) const;
    void factor_at(const std::vector<signed char>& pattern) {
        saved_base_ = Eigen::Map<const Pattern>(pattern.data(), static_cast<Eigen::Index>(pattern.size()));
    }

private:
    ContactSolveInfo newton(const ContactProblem& p, const ContactSolverOptions& options,
                            Eigen::VectorXd& lambda, bool stop_on_stagnation);
    // Semi-smooth Newton on the full generalized Jacobian (full_jacobian.cpp), for two
    // tangents, or one without options.reduced_newton; where it fails, node by node.
    ContactSolveInfo solve_full_jacobian(const ContactProblem& p, const ContactSolverOptions& options,
                                         Eigen::VectorXd& lambda);
    double full_residual(const ContactProblem& p, const Eigen::VectorXd& lambda, Eigen::VectorXd& phi);
    void full_newton_direction(const ContactProblem& p, const Eigen::VectorXd& lambda);
    Eigen::VectorXd tangential_augmentation_;
    // The Jacobian's rows of the active nodes' unknowns (row-major: built row by row), and a
    // slipping node's W_T^T (s / |s|) under a slip-rate law.
    Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> jacobian_rows_;
    Eigen::RowVectorXd slip_row_;
    // The node law at u_hat_ (friction_law.hpp: apply_node_law), r_T(i) node i's tangential
    // augmentation; keeps per node what the Jacobians need (law_...).
    double apply_law(const ContactProblem& p, const Eigen::VectorXd& lambda,
                     const Eigen::Ref<const Eigen::VectorXd>& rT, Eigen::VectorXd& phi);
    // Per node at the last residual (tangent t's entries at t n + i): F, the normal trial,
    // z / |z| and F trial / |z| where slipping, and with a slip-rate law dF/d|s| and s / |s|.
    Eigen::VectorXd law_F_, law_trial_, law_direction_, law_ratio_, law_dF_, law_slip_direction_;
    // Node-by-node exact solves with the other nodes fixed; true when the residual reaches
    // the tolerance within options.max_sweeps.
    bool gauss_seidel(const ContactProblem& p, const ContactSolverOptions& options, Eigen::VectorXd& lambda,
                      ContactSolveInfo& info, bool exact_rate);
    bool gauss_seidel_disc(const ContactProblem& p, const ContactSolverOptions& options,
                           Eigen::VectorXd& lambda, ContactSolveInfo& info, bool exact_rate);
    // The residual, then sweep() and the residual again until it reaches the tolerance; false
    // at max_sweeps, or when 50 sweeps have not halved the best residual.
    template <class Sweep, class Residual>
    static bool sweep_until(const ContactSolverOptions& options, ContactSolveInfo& info, Sweep&& sweep,
                            Residual&& residual) {
        info.residual = residual();
        double best = info.residual;
        int best_sweep = 0;
        while (!(info.residual <= options.tolerance)) {
            if (info.sweeps >= options.max_sweeps || info.sweeps - best_sweep > 50) return false;
            ++info.sweeps;
            sweep();
            info.residual = residual();
            if (info.residual < 0.5 * best) {
                best = info.residual;
                best_sweep = info.sweeps;
            }
        }
        return true;
    }
    double residual(const ContactProblem& p, const Eigen::VectorXd& lambda, Eigen::VectorXd& phi);
    enum class Direction { reuse, update, factor };  // the last factorization, updated, or anew
    void factor(const ContactProblem& p, const ContactSolverOptions& options);  // of pattern_
    void newton_direction(const ContactProblem& p, const ContactSolverOptions& options, Direction how,
                          const Eigen::VectorXd& lambda);
    // The right-hand side of the reduced Newton system's row j.
    double newton_target(const ContactProblem& p, Eigen::Index j) const {
        const double w = diagonal_[j];
        return j < p.gap_limit.size() ? phi_[j] * w : -phi_[j] * w;
    }
    double newton_entry(const ContactProblem& p, const Pattern& P, Eigen::Index a, Eigen::Index b) const;
    void base_solve(const ContactProblem& p, Eigen::Ref<Eigen::MatrixXd> x);
    bool prepare_update(const ContactProblem& p);
    void updated_solve(const ContactProblem& p);
    // Every row of the generalized Jacobian, for a 2D slip-rate law.
    void rate_newton_direction(const ContactProblem& p);
    void project_slip(const ContactProblem& p, Eigen::VectorXd& lambda) const;
    // +-F_i for a slipping node, the sign of its slip.
    double slip_sign(const ContactProblem& p, Eigen::Index i) const {
        return pattern_[i] > 0 ? p.friction[i] : -p.friction[i];
    }

    // W's diagonal and its inverse r_ (the augmentation parameters), for W of diagonal_revision_.
    Eigen::VectorXd diagonal_;
    std::uint64_t diagonal_revision_ = 0;
    // Workspace kept between calls so that steady stepping does not reallocate.
    Eigen::VectorXd u_hat_, r_, phi_, trial_phi_, step_, trial_, explicit_, explicit_product_, start_;
    // The last product W lambda, the lambda and the W (revision) it was formed for.
    Eigen::VectorXd product_, product_lambda_;
    std::uint64_t product_revision_ = 0;
    // Whether this solve projects slipping nodes (options.project_slip, with friction and no
    // slip-rate law), and makes its products with half of W where the nodes slide, for the W
    // of compact_revision_.
    bool projects_slip_ = false, compact_products_ = false;
    SlidingProduct sliding_;
    std::uint64_t compact_revision_ = 0;
    std::vector<int> reduced_;  // unknowns of the reduced Newton system
    LeadingLu newton_lu_;       // of the reduced system, or of the full Jacobian's active rows
    Eigen::VectorXd reduced_rhs_;
    Eigen::Matrix<NodeStatus, Eigen::Dynamic, 1> status_;
    Pattern pattern_, lu_pattern_;  // of the last residual, and of the LU
    Eigen::VectorXd lu_friction_;   // and the coefficients of the slipping nodes
    std::uint64_t lu_revision_ = 0;
    // The update (prepare_update) of the factorization base_ to update_pattern_.
    static constexpr Eigen::Index max_update_unknowns = 32;
    static constexpr Eigen::Index update_share = 20;  // update while 20 c <= k (prepare_update)
    Pattern saved_base_;                              // factor_at's
    std::vector<bool> in_changed_;
    RowColumnUpdate update_;
    Eigen::MatrixXd gathered_;  // base_solve's rows of the reduced system
    Eigen::VectorXd update_x_;
    Pattern update_pattern_;
    long base_ = 0, update_base_ = -1;
    long factorizations_ = 0, residual_evaluations_ = 0, newton_iterations_ = 0, updates_ = 0;
};

}  // namespace contactbody
