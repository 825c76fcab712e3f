// A supernodal Cholesky factor L L^T = P K P^T of a symmetric positive definite K in a given
// fill-reducing order: columns with the same structure below them are grouped into supernodes
// (fundamental ones, then relaxed amalgamation: a child merged into its parent where the zeros
// it adds stay few), each stored as a dense panel and factored right-looking by dense kernels
// (Eigen's blocked LLT, triangular solve and rank update); its solves run by panels.
// Written here because CHOLMOD's supernodal module is GPL (docs/decisions.md, "The factor of a
// 3D body"). Not yet the body's factor: no held dofs, trailing block or partial refactorization.
#pragma once

#include <Eigen/Dense>
#include <vector>

#include "assembly/assembly.hpp"
#include "linalg/supernodal_kernels.hpp"

namespace contactbody {

class SupernodalCholesky {
public:
    // lower: K's lower triangle (CSC, compressed); position[i]: unknown i's place in the
    // factor order. The symbolic analysis: supernodes and their row structures. The numeric
    // factor runs the fastest kernels this CPU has (linalg/supernodal_kernels.hpp), or the
    // architecture's baseline ones (baseline_kernels: the same bits on every machine).
    SupernodalCholesky(const SparseMatrix& lower, const std::vector<int>& position,
                       bool baseline_kernels = false);
    const char* kernel_set() const { return kernels_->name; }
    // The numeric factor of a matrix with lower's pattern. False where K is not positive
    // definite (failed_column() tells where, in factor order).
    bool factor(const SparseMatrix& lower);
    Eigen::Index failed_column() const { return failed_; }
    // x = K^-1 b. Allocates nothing once the factor exists.
    void solve(const Eigen::VectorXd& b, Eigen::VectorXd& x) const;

    Eigen::Index size() const { return n_; }
    Eigen::Index supernodes() const { return static_cast<Eigen::Index>(first_.size()) - 1; }
    double factor_nonzeros() const;                 // of the panels (the amalgamation's zeros included)
    double factor_flops() const { return flops_; }  // of the factorization, with those zeros

private:
    Eigen::Index n_ = 0, failed_ = -1;
    std::vector<int> position_;
    // Supernode s: columns first_[s] .. first_[s + 1] - 1; rows (its columns, then the rows
    // below) row_index_[row_start_[s] .. row_start_[s + 1]); its panel (rows x columns,
    // column-major) at values_[value_start_[s]].
    std::vector<int> first_, super_of_, row_start_, row_index_;
    std::vector<std::ptrdiff_t> value_start_;
    std::vector<double> values_;
    double flops_ = 0;
    const SupernodalKernels* kernels_;
    std::vector<int> local_;      // a supernode's row -> its place (factor())
    std::vector<double> update_;  // a panel's update of its ancestors
    mutable Eigen::VectorXd permuted_, gathered_;
};

}  // namespace contactbody
