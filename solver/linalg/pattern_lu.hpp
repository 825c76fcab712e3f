// An LU factor without pivoting of a matrix whose pattern is symmetric (its values need not
// be), in a fixed fill-reducing order: the sparse contact solve's held operator with slipping
// rows (sparse_contact.hpp), whose row of a slipping node's tangential dof is that dof's row of
// K plus the friction coefficient times its normal dof's row. Its fill is the Cholesky
// factor's of the same pattern and order, and a solve costs what a Cholesky solve costs.
// Written here because CHOLMOD's LU-free modules factor symmetric matrices only and Eigen's
// SparseLU solves slower at these sizes (docs/decisions.md, "A 2D body's factor holds its
// slipping nodes").
#pragma once

#include <Eigen/Dense>
#include <vector>

#include "assembly/assembly.hpp"

namespace contactbody {

class PatternLu {
public:
    // pattern: the matrix's (CSC, compressed, both triangles, a symmetric pattern with every
    // diagonal entry); position: each unknown's position in the factor order.
    PatternLu(const SparseMatrix& pattern, const std::vector<int>& position);
    // Factors the matrix whose values (in pattern's order) are given. False where a pivot is
    // not above 1e-12 times the largest entry of its column (no pivoting: then another
    // factor is wanted). After a factor that succeeded, only the columns whose values changed
    // and their ancestors in the elimination tree are factored again: the others' columns of
    // L and U depend on nothing that changed (the same bits as factoring all).
    bool factor(const double* values);
    Eigen::Index columns_factored() const { return columns_factored_; }  // by the last factor()
    // x = A^-1 b (b and x may not alias). Allocates nothing.
    void solve(const Eigen::VectorXd& b, Eigen::VectorXd& x);

private:
    Eigen::Index n_ = 0;
    std::vector<int> order_;                                  // factor position -> unknown
    std::vector<int> column_start_, column_rows_, value_of_;  // P A P^T's columns, from A's values
    // The strictly lower part's pattern, by columns (rows ascending): L(i, k) and U(k, i) at the
    // same place. across_: per row j, the places of its entries L(j, k), k < j ascending.
    std::vector<int> start_, rows_, column_of_, across_start_, across_;
    std::vector<char> group_;       // the size of the solve's group of columns that starts or ends here
    std::vector<int> parent_;       // the elimination tree (-1 at a root)
    std::vector<double> factored_;  // the values last factored, by P A P^T's columns
    std::vector<char> stale_;       // per column: to factor again
    bool factored_all_ = false;     // the last factor succeeded: factored_ is its values
    Eigen::Index columns_factored_ = 0;
    std::vector<double> lower_, upper_, diagonal_;
    Eigen::VectorXd work_;
};

}  // namespace contactbody
