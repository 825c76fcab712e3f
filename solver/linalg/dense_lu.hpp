// Dense LU factors for the condensed contact solve's Newton systems, whose size changes with the
// active set: LeadingLu factors the leading k x k of a buffer sized once (no allocation as k
// changes), and RowColumnUpdate solves a matrix that differs from a factored one in a few rows
// and columns (Woodbury's formula), for a Newton matrix whose few changed nodes do not pay a
// refactorization.
#pragma once

#include <Eigen/Dense>
#include <vector>

namespace contactbody {

// An LU with partial pivoting of the leading k x k of an m x m buffer: Eigen's blocked kernel
// (the reference LAPACK's dgetrf on reference BLAS was a quarter of a pressed substep at nx = 160:
// docs/decisions.md, "Newton on the reduced system").
class LeadingLu {
public:
    using Block = Eigen::Block<Eigen::MatrixXd>;
    // Sizes the buffer for factors up to m x m (once: a smaller m keeps it).
    void reserve(Eigen::Index m) {
        if (buffer_.rows() < m) buffer_.resize(m, m);
        if (pivots_.size() < static_cast<size_t>(m)) pivots_.resize(static_cast<size_t>(m));
    }
    Eigen::Index capacity() const { return buffer_.rows(); }
    // The k x k matrix to fill before factor(k).
    Block matrix(Eigen::Index k) { return buffer_.topLeftCorner(k, k); }
    // Factors matrix(k) in place; false at a zero pivot (the factor is then unusable).
    bool factor(Eigen::Index k);
    Eigen::Index size() const { return k_; }
    // x <- A^-1 x for the k rows of x (a vector, or a block of columns).
    template <class X>
    void solve_in_place(X&& x) const {
        for (Eigen::Index a = 0; a < k_; ++a) x.row(a).swap(x.row(pivots_[static_cast<size_t>(a)]));
        const auto lu = factor_view();
        lu.template triangularView<Eigen::UnitLower>().solveInPlace(x);
        lu.template triangularView<Eigen::Upper>().solveInPlace(x);
    }

private:
    Eigen::Map<const Eigen::MatrixXd, 0, Eigen::OuterStride<>> factor_view() const {
        return {buffer_.data(), k_, k_, Eigen::OuterStride<>(buffer_.rows())};
    }
    Eigen::MatrixXd buffer_;
    std::vector<int> pivots_;
    Eigen::Index k_ = 0;
};

// J that differs from J0 only in the rows and columns of c unknowns C (a Newton matrix whose
// nodes in C changed state), solved from J0's solve by Woodbury's formula: with D = J - J0,
//   J - J0 = E_C D(C, :) + D(~C, C) E_C^T = U V^T,  U = [E_C, D(~C, C)],  V^T = [D(C, :); E_C^T],
//   J^-1 = J0^-1 - Z K^-1 V^T J0^-1,  Z = J0^-1 U,  K = I + V^T Z (the capacitance matrix, 2c square).
// Set changed(), fill rows(c) = D(C, :) and columns(c) = D(~C, C) (zero in C's rows), then
// prepare(solve0); solve(x, solve0) after that. solve0(X) sets X <- J0^-1 X for an m-row block.
// Allocates nothing once reserved.
class RowColumnUpdate {
public:
    void reserve(Eigen::Index m, Eigen::Index max_changed);
    Eigen::Index max_changed() const { return rows_.rows(); }
    Eigen::Index columns_of() const { return rows_.cols(); }  // m
    std::vector<int>& changed() { return changed_; }          // C
    const std::vector<int>& changed() const { return changed_; }
    Eigen::Index size() const { return static_cast<Eigen::Index>(changed_.size()); }  // c
    auto rows() { return rows_.topRows(size()); }
    // D(~C, C), into U's second half (U's first half, E_C, is set by prepare).
    auto columns() { return z_.middleCols(size(), size()); }
    // Z and K's LU; false where K is singular. Call after rows() and columns() are filled.
    template <class Solve0>
    bool prepare(Solve0&& solve0) {
        const Eigen::Index c = size(), r = 2 * c;
        auto z = z_.leftCols(r);
        z.leftCols(c).setZero();
        for (Eigen::Index i = 0; i < c; ++i) z(changed_[static_cast<size_t>(i)], i) = 1;  // E_C
        solve0(z);
        auto k = capacitance_.matrix(r);
        k.topRows(c).noalias() = rows_.topRows(c) * z;
        for (Eigen::Index i = 0; i < c; ++i) k.row(c + i) = z.row(changed_[static_cast<size_t>(i)]);
        k.diagonal().array() += 1;
        return capacitance_.factor(r);
    }
    // x <- J^-1 x for an m-vector x, by the last prepare that succeeded.
    template <class Solve0>
    void solve(Eigen::VectorXd& x, Solve0&& solve0) {
        const Eigen::Index c = size(), r = 2 * c;
        solve0(x);
        auto t = t_.head(r);
        t.head(c).noalias() = rows_.topRows(c) * x;
        for (Eigen::Index i = 0; i < c; ++i) t[c + i] = x[changed_[static_cast<size_t>(i)]];
        capacitance_.solve_in_place(t);
        x.noalias() -= z_.leftCols(r) * t;
    }

private:
    std::vector<int> changed_;
    Eigen::MatrixXd rows_, z_;  // max_changed x m (D(C, :)); m x 2 max_changed (U, then Z)
    LeadingLu capacitance_;
    Eigen::VectorXd t_;
};

}  // namespace contactbody
