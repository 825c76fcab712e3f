// The contact solve on the body's sparse system, for contact boundaries too long for the
// condensed one (docs/decisions.md, "The contact solve at any size"): the Delassus operator
// W = B K^-1 B^T is dense in the 2 n_c contact unknowns, so forming it costs n_c^3 and
// (2 n_c)^2 memory. Here it is never formed.
//
// Semi-smooth Newton on the same Alart-Curnier residual as ContactSolver (friction_law.hpp, node_law),
// iterated as a primal-dual active set: each iterate (w, lambda) satisfies K w = rhs + B^T lambda
// exactly, and a node pattern's step solves that pattern's linear problem on the sparse system:
//   active node:   its y dof held at the gap (u_N = gap limit),
//   sticking node: its x dof (and a 3D body's z dof) held at the slip origin too,
//   slipping node: its x dof loaded by lambda_T = sf pressure, sf = +-F (the reaction of its
//                  held y dof: a non-symmetric coupling); a 3D body's x and z dofs by
//                  the disc's slip law linearized at the iterate, l_T = F p t + rho (I - t t^T)
//                  (delta l_T - r_T delta u_T), t the iterate's slip direction and
//                  rho = F p / |z| (a spring across t: Newton in t, not a fixed point),
//   open node:     unloaded.
// The held factor is the Cholesky factor of K with a set of contact dofs held (their rows and
// columns the identity's), in K's own fill-reducing ordering and symbolic analysis; it holds
// the slipping nodes too, their tangential rows K_j - sf_j K_y (r_j = sf_j r_y: the slip law,
// sf = +-F in 2D, F t_j along a 3D node's slip direction t at the time it was factored, where
// rho is small and more slip than GCR's kept directions span), which makes it an LU on the
// same order and pattern (PatternLu, or the supernodal factor's LU). A pattern
// is solved on the factor of a nearby held set: what differs (dofs held now but free in the
// factor, dofs free now but held in it, and the slipping nodes' loads that the factor does not
// hold) are the unknowns of a
// small linear system solved by GCR, one held solve an iteration, whose directions are kept
// while the factor holds (a substep like the last needs none; where a node changes state, the
// directions' entries at what is no longer an unknown are eliminated between them). The factor is rebuilt (a
// numeric refactorization) only where many dofs differ.
#pragma once

#include <Eigen/Dense>
#include <memory>
#include <vector>

#include "assembly/assembly.hpp"
#include "contact/contact_solver.hpp"
#include "linalg/held_operator.hpp"

namespace contactbody {

struct SupernodalKernels;

class SparseContactSolver {
public:
    // Solves K w = rhs + B^T lambda with the contact conditions of `problem` (its gap limits,
    // slip origins and friction coefficients; its W and a are not used), from the multipliers
    // of the last substep in lambda and its stick memory `sticking` (the first pattern, but
    // where a node chattered over the last solves: so the result depends on the State, K's
    // held set and what the solver kept since forget(); with fresh_factor, K is first held at
    // that pattern and all that is dropped). Throws ContactSolveError where Newton or GCR
    // fail.
    // B: N_i = -e_y(i), T_i = +e_x(i) (the full stepper's).
    ContactSolveInfo solve(HeldOperator& K, const ContactProblem& problem,
                           const ContactSolverOptions& options, const Eigen::VectorXd& rhs,
                           const Eigen::VectorXd& sticking, Eigen::VectorXd& lambda, Eigen::VectorXd& w,
                           bool fresh_factor);
    // Drops what the solver keeps from solve to solve (GCR's directions, the last patterns:
    // they make a solve faster, and change its last bits).
    void forget() {
        history_ = 0;
        kept_ = parked_ = 0;
        kept_operator_ = last_operator_ = detour_operator_ = nullptr;
        detour_solves_ = 0;
    }
    const Eigen::Matrix<NodeStatus, Eigen::Dynamic, 1>& status() const { return status_; }
    bool touching() const { return (pattern_.array() != 0).any(); }
    long solves() const { return solves_; }  // held solves over the solver's life
    long krylov_iterations() const { return krylov_iterations_; }
    long gcr_rounds() const { return rounds_; }        // GCR's rounds after the first (solve_coupled)
    long warm_starts() const { return warm_starts_; }  // Newton iterations without a held solve of their own

    static constexpr int max_directions = 96;  // GCR's kept directions, and its iterations
    // GCR's kept directions on a supernodal factor of options.wide_span_nonzeros or more:
    // there a solve costs more than orthonormalizing this many images again at each Newton
    // iteration (orthonormalize_all), and they span most of a 3D contact zone's slips
    // (docs/decisions.md, "GCR's kept directions span the slips").
    static constexpr int wide_span_directions = 768;
    static constexpr int max_detour = 16;
    // The solutions combined after GCR are solved again where the sizes combined exceed the
    // combination's by this (digits lost to cancellation that a solve would keep).
    static constexpr double max_cancellation = 100;
    // A 3D slip is held in the factor (F p along a fixed t) only where its linearized disc law
    // is near that: its rho = F p / |z| at most this (the spring across t that the factor leaves
    // out, rho r_T / (1 - rho), at most 0.11 r_T). Sliding substeps have rho of 1e-4 to 0.05, a
    // static start's load increments 0.3 to 1 (docs/decisions.md, "A 3D body's factor holds its
    // slipping nodes").
    static constexpr double max_held_ratio = 0.1;

private:
    // held_ from pattern_: active nodes' y dofs, and sticking nodes' tangential dofs with
    // friction; and slip_ (where K may hold slips): slipping nodes' signs (2D) or slip
    // directions (3D), tangents x n (HeldOperator::hold); a 3D node's where its rho is at most
    // max_held_ratio (ratio_, zero before the first residual), or, where ratios_known is false
    // (a solve's first iteration on a factor it keeps), where K holds it.
    void held_set(const ContactProblem& p, const HeldOperator& K, bool ratios_known);
    void solve_pattern(HeldOperator& K, const ContactProblem& p, const Eigen::VectorXd& rhs, double scale,
                       double tolerance);
    // The coupled unknowns' system on K's current factor, into w_new_; false where it took
    // more than max_iterations held solves on a detour (a factor of another held set); on
    // the pattern's own factor that throws ContactSolveError.
    bool solve_coupled(HeldOperator& K, const ContactProblem& p, const Eigen::VectorXd& rhs, double scale,
                       double tolerance, int max_iterations, bool detour);
    double residual(const HeldOperator& K, const ContactProblem& p, const Eigen::VectorXd& w,
                    const Eigen::VectorXd& lambda, Eigen::VectorXd& phi);
    void reactions(const HeldOperator& K, const ContactProblem& p, const Eigen::VectorXd& rhs);
    // The system's unknowns (Coupling) and what a held solve with them gives.
    enum Kind : int { load, value };
    struct Coupling {
        int unknown;  // contact unknown j (N: node i, T: n + i)
        Kind kind;    // a load (the factor's dof free) or a held value (held in the factor)
        double sf;    // +-F where the equation is a slip law's, else 0
        bool held;    // the pattern holds the dof (else it is loaded)
        int partner;  // a 3D slipping node's other tangential unknown's coupling, else -1
    };
    // The right-hand side and held values of unknowns xi on top of base (the affine part's),
    // solved into x.
    void held_solve(HeldOperator& K, const Eigen::VectorXd& rhs, bool affine,
                    const Eigen::Ref<const Eigen::VectorXd>& xi, Eigen::VectorXd& x);
    // What the system's equations read of a solution x, per coupled unknown k (3 q entries):
    // the reaction at its dof, its dof's value, and its node's normal reaction (homogeneous:
    // without rhs).
    void responses(const HeldOperator& K, const ContactProblem& p, const Eigen::VectorXd& rhs,
                   const Eigen::VectorXd& x, bool homogeneous, Eigen::Ref<Eigen::VectorXd> out) const;
    // The system's equations from those responses (homogeneous: without rhs and held values).
    void equations(const HeldOperator& K, const ContactProblem& p,
                   const Eigen::Ref<const Eigen::VectorXd>& response, bool homogeneous,
                   Eigen::Ref<Eigen::VectorXd> e) const;
    bool orthonormalize(int slot, Eigen::Index q, double dependent);
    void remake_images(const HeldOperator& K, const ContactProblem& p, int first);
    void make_images(const HeldOperator& K, const ContactProblem& p);
    bool orthonormalize_all(const SupernodalKernels& kernels, Eigen::Index q);
    void add_directions(Eigen::Index q, bool solutions);
    void coupled_responses(int slot, Eigen::Index n, Eigen::Ref<Eigen::VectorXd> out) const;
    void eliminate_uncoupled();
    void unpark();
    void move_direction(int from, int to);

    using Pattern = Eigen::Matrix<signed char, Eigen::Dynamic, 1>;
    Pattern pattern_, trial_pattern_;
    // A 3D body's slipping nodes' directions (x components, then z): the pattern's, and the
    // last residual's.
    Eigen::VectorXd direction_, trial_direction_;
    // Their F p / |z| (node_law's ratio: the slip law's derivative in t), and the iterate's
    // rho (I - t t^T) q0 (x components, then z): the Newton step's terms.
    Eigen::VectorXd ratio_, trial_ratio_, newton_shift_;
    Eigen::Matrix<NodeStatus, Eigen::Dynamic, 1> status_, trial_status_;
    std::vector<char> held_;
    std::vector<double> slip_;
    // The iterate and the pattern step's result (new_), the backtracking trial.
    Eigen::VectorXd w_new_, lambda_new_, w_trial_, lambda_trial_, phi_, phi_new_;
    Eigen::VectorXd b_, values_, targets_, z_;  // targets_: the held dofs' values
    std::vector<Coupling> coupling_;
    Eigen::VectorXd xi_, krylov_residual_;
    // GCR's kept_ directions as made (loads and values, per contact unknown), their held
    // solves' responses (the reaction, then the value, at every contact unknown), valid for
    // the factor they were made on; the orthonormal images (per coupled unknown) for the
    // pattern and coefficients, and which combination of the directions each one's is
    // (combinations_: upper triangular). coefficients_: GCR's step in the directions as made.
    Eigen::MatrixXd directions_, images_, responses_, combinations_;
    // orthonormalize_all's: the images transposed, the two Gram matrices' Cholesky factors,
    // the images' norms.
    Eigen::MatrixXd transposed_, gram_first_, gram_second_;
    Eigen::VectorXd image_norm_;
    // The directions' held solves (n_f each), so that the solution after GCR is their
    // combination, not one more held solve; their sizes (max norms, bounds after
    // elimination) and the sizes combined into w_new_ since it was last solved.
    Eigen::MatrixXd solutions_;
    Eigen::VectorXd solution_size_;
    double combined_ = 0;
    Eigen::VectorXd response_, direction_coupled_, coefficients_;
    std::vector<int> coupling_of_;  // per contact unknown: its coupling, or -1
    int kept_capacity_ = 0;
    int max_differing_ = 64;  // the solve's options.max_differing
    int kept_ = 0, parked_ = 0;     // parked_: eliminate_uncoupled's, in the last slots
    Pattern kept_pattern_;
    std::vector<int> kept_unknowns_;  // the coupled unknowns the images are of
    Eigen::VectorXd kept_friction_, kept_direction_, kept_ratio_;
    const HeldOperator* kept_operator_ = nullptr;
    long kept_refactorizations_ = -1;
    // Held solves made on the current factor for patterns it does not hold (solve_pattern),
    // and the factor they were counted on (an operator and its refactorizations' count).
    long detour_solves_ = 0;
    const HeldOperator* detour_operator_ = nullptr;
    long detour_refactorizations_ = -1;
    // The last solve_coupled's result on its factor: the coupled unknowns' values (NaN where
    // not coupled), its solution and the sizes combined into it; this solve's Newton iteration.
    Eigen::VectorXd last_xi_, last_w_;
    double last_combined_ = 0;
    const HeldOperator* last_operator_ = nullptr;
    long last_refactorizations_ = -1;
    int newton_iteration_ = 0;
    // The last three solves' final patterns (the latest first), history_ of them valid.
    Pattern last_patterns_[3];
    int history_ = 0;
    long solves_ = 0, krylov_iterations_ = 0, rounds_ = 0, warm_starts_ = 0;
};

}  // namespace contactbody
