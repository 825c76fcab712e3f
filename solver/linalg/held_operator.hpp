// K on the free dofs of one substep size with a set of contact unknowns held (their rows and
// columns the identity's), factored in K's own ordering: the sparse contact solve's operator
// (contact/sparse_contact.hpp says how it is used).
#pragma once

#include <Eigen/Dense>
#include <memory>
#include <vector>

#include "assembly/assembly.hpp"
#include "linalg/trailing_cholesky.hpp"

namespace contactbody {

class TrailingCholesky;
class PatternLu;
struct SupernodalKernels;

// K on the free dofs for one substep size, with a set of contact unknowns held.
class HeldOperator {
public:
    // contact_dofs: the free positions of the contact unknowns in multiplier order (y dofs,
    // then each tangent's; Discretization::contact_unknowns), unknowns_per_node of them a node
    // (2: y and x; 3: y, x and z).
    // options: how a supernodal factor is made (TrailingCholesky).
    HeldOperator(const SparseMatrix& K, std::vector<int> contact_dofs, int unknowns_per_node,
                 FactorOptions options = {});
    ~HeldOperator();
    HeldOperator(const HeldOperator&) = delete;
    HeldOperator& operator=(const HeldOperator&) = delete;

    Eigen::Index size() const { return K_.rows(); }
    Eigen::Index unknowns() const { return static_cast<Eigen::Index>(dofs_.size()); }
    int dof(Eigen::Index j) const { return dofs_[static_cast<size_t>(j)]; }
    // K's diagonal at contact unknown j: 1 / K_jj <= W_jj, the augmentation parameter's scale.
    double stiffness(Eigen::Index j) const { return stiffness_[j]; }
    // (K x) at contact unknown j's dof.
    double row_product(Eigen::Index j, const Eigen::VectorXd& x) const { return rows_.row(j).dot(x); }
    // Holds the unknowns j with held[j] != 0 (refactoring where the set changed), and loads
    // each slipping node i along its tangential unknowns j = c n + i (c = 1 .. tangents) by
    // slip[(c - 1) n + i] times the slip coefficient times its held y dof's reaction (the
    // pressure's sign: r_j = sf_j r_y, as SparseContactSolver's slip law; in 2D slip is +-1, in
    // 3D the node's unit slip direction t, so that r_T = F p t): that row of K_H becomes
    // K_j - sf_j K_y, its right-hand side b_j - sf_j b_y (factored by PatternLu). Without slips
    // (empty or zero) K_H is symmetric: K's Cholesky.
    void hold(const std::vector<char>& held, const std::vector<double>& slip = {});
    const std::vector<char>& held() const { return held_; }
    // The held slips, tangents x n (zero where a node's rows are K's).
    const std::vector<double>& slip() const { return slip_; }
    bool holds_slips() const { return lu_held_; }  // some node's rows are slipping rows
    bool holds(const std::vector<char>& held, const std::vector<double>& slip) const {
        return held == held_ && slip == slip_;
    }
    // F of the held slips (the kinetic coefficient: the stepper's), 0 where slips are not held
    // (a factor whose LU found no pivot: then never again). A new one refactors.
    double slip_coefficient() const { return slips_allowed_ ? slip_coefficient_ : 0.0; }
    void set_slip_coefficient(double friction);
    // b <- b - K_H(:, held) values(held) on the rows not held, and values on the held rows: the
    // right-hand side whose held solve has x = values on the held dofs (a slipping row's
    // right-hand side is b_x - sf b_y).
    void impose(Eigen::VectorXd& b, const Eigen::VectorXd& values) const;
    // x = K_H^-1 b (K_H: K with the held rows and columns the identity's, and the slipping rows).
    void solve(const Eigen::VectorXd& b, Eigen::VectorXd& x);
    long refactorizations() const { return refactorizations_; }
    // What they factored, in whole factorizations (each its refactored share).
    double refactored_work() const { return refactored_work_; }
    double factor_nonzeros() const;
    // What a refactorization costs in held solves: its flops (the analysis's) over a solve's,
    // 4 per nonzero of L (forward and backward).
    double refactorization_in_solves() const;
    TrailingCholesky& factor() { return *factor_; }
    // The dense kernels of its supernodal factor (the set its options choose), or null where
    // the factor is another (a build without solid bodies has none): what the contact solve's
    // dense algebra on the same body may run.
    const SupernodalKernels* dense_kernels() const;

private:
    SparseMatrix K_;                   // both triangles: the held columns' entries
    SparseMatrix lower_, held_lower_;  // lower triangle, and as factored (same pattern)
    RowMajorSparseMatrix rows_;        // K's rows at the contact unknowns
    std::vector<int> dofs_;
    Eigen::VectorXd stiffness_;
    // Per contact unknown: the positions in lower_'s values of its row and column, and of its
    // diagonal entry.
    std::vector<std::vector<int>> positions_;
    std::vector<int> diagonal_;
    std::unique_ptr<TrailingCholesky> factor_;
    std::vector<char> held_, held_dof_;  // per contact unknown, per free dof
    long refactorizations_ = 0;
    double refactored_work_ = 0;
    // The slipping rows' factor: K's values (both triangles) as held, and per contact unknown
    // the positions of its row's entries (aligned with its column's: x's and y's of a node
    // match) and of its diagonal; each free dof's contact unknown (or -1).
    std::unique_ptr<PatternLu> lu_;
    bool lu_held_ = false, slips_allowed_ = false;
    double slip_coefficient_ = 0;
    int tangents_ = 1;
    bool baseline_kernels_ = false;
    std::vector<double> slip_;
    std::vector<double> lu_values_;
    std::vector<std::vector<int>> row_positions_;
    std::vector<int> full_diagonal_, unknown_of_;
    void factor_held();
    void factor_into_held();  // the factorization itself
    void slip_values();
};

}  // namespace contactbody
