// Sparse Cholesky factor P K P^T = L L^T (CHOLMOD) with a chosen set of unknowns ordered last.
//
// With the contact dofs last, a substep needs one forward solve, a small dense correction of
// the trailing entries, and one backward solve: the contact multipliers only enter the
// right-hand side at trailing positions, so L^-1 of them stays in the trailing block L22.
// Forward and backward solves are exposed separately for that, and allocate nothing after
// the first call (CHOLMOD's solve2 with kept workspaces).
#pragma once

#include <Eigen/Dense>
#include <memory>
#include <vector>

#include "assembly/assembly.hpp"

namespace contactbody {

class SupernodalCholesky;

// How a supernodal factor is made (linalg/supernodal_cholesky.hpp): its dense kernels, the
// architecture's baseline ones (baseline_kernels) or the fastest this CPU has
// (linalg/supernodal_kernels.hpp), and the threads of its numeric factorization (the same bits
// for any number).
struct FactorOptions {
    bool baseline_kernels = false;
    int threads = 1;
    bool supernodal = false;  // tests: a refactorable factor is the supernodal one whatever its flops
};

class TrailingCholesky {
public:
    // Factors the symmetric positive definite K (only its lower triangle is read) with the
    // unknowns in `trailing` ordered last (fill-reducing order elsewhere, and among them).
    // Throws std::runtime_error naming the cause if K is not positive definite.
    // refactorable (no trailing unknowns): refactor() may be called; the factor is then kept
    // as CHOLMOD factors a prepermuted matrix, in natural order. Where factoring costs
    // supernodal_flops or more (tetrahedral bodies, whose separators are surfaces; 2D bodies
    // from about 200k unknowns), a refactorable factor is instead our supernodal Cholesky in
    // the same order (linalg/supernodal_cholesky.hpp; CHOLMOD's supernodal module is GPL): its
    // dense panels in BLAS-3 kernels (docs/decisions.md, "A supernodal Cholesky of our own").
    // kernel: of a refactorable factor, by the rule above (automatic) or forced (tests,
    // benchmarks; supernodal_lu, Eigen's SparseLU of the same order, is the factor it replaced,
    // kept for comparison and allocating in its solve() and refactor()).
    enum class Kernel { automatic, simplicial, supernodal, supernodal_lu };
    TrailingCholesky(const SparseMatrix& K, const std::vector<int>& trailing, bool refactorable = false,
                     Kernel kernel = Kernel::automatic, FactorOptions options = {});
    ~TrailingCholesky();
    TrailingCholesky(const TrailingCholesky&) = delete;
    TrailingCholesky& operator=(const TrailingCholesky&) = delete;

    Eigen::Index size() const { return n_; }
    Eigen::Index trailing_size() const { return m_; }
    // Position in factor order (n - m .. n-1 for trailing unknowns) of unknown `index`.
    int position(int index) const { return inverse_perm_[static_cast<size_t>(index)]; }
    // The trailing diagonal block of L (dense, lower triangular, m x m).
    const Eigen::MatrixXd& trailing_block() const { return trailing_block_; }
    // Nonzeros of L (memory of the factor, and what a solve costs).
    double factor_nonzeros() const;
    // The analysis's flops of one factorization, and whether the factor is the supernodal LU.
    double factor_flops() const { return factor_flops_; }
    bool supernodal() const { return lu_ != nullptr || supernodal_ != nullptr; }
    Kernel kernel() const {
        return supernodal_ ? Kernel::supernodal : lu_ ? Kernel::supernodal_lu : Kernel::simplicial;
    }
    // The rule: supernodal from supernodal_flops, and from dense_supernodal_flops where the
    // panels are dense (dense_flops_per_nonzero flops per factor nonzero or more: tetrahedral
    // bodies; docs/decisions.md, "The rule on whole substeps").
#ifdef CONTACTBODY_SUPERNODAL_FLOPS  // a measurement's build (benchmarks/factor_crossover.py)
    static constexpr double supernodal_flops = CONTACTBODY_SUPERNODAL_FLOPS;
    static constexpr double dense_supernodal_flops = CONTACTBODY_SUPERNODAL_FLOPS;
#else
    static constexpr double supernodal_flops = 1e9, dense_supernodal_flops = 1e8;
#endif
    static constexpr double dense_flops_per_nonzero = 200;
    static bool supernodal_pays(double flops, double nonzeros) {
        return flops >= supernodal_flops ||
               (flops >= dense_supernodal_flops && flops >= dense_flops_per_nonzero * nonzeros);
    }
    // The kernel set a supernodal factor would run (linalg/supernodal_kernels.hpp), or null in
    // a build without one (the 2D FMU's binaries).
    static const char* supernodal_kernel_set(bool baseline_kernels);
    // Factors K2 in place of K, keeping the ordering and symbolic analysis: K2's nonzeros must
    // lie in K's pattern (the sparse contact solve's held dofs: rows and columns zeroed, 1 on
    // the diagonal). Only for a refactorable factor.
    void refactor(const SparseMatrix& K2);
    // A supernodal factor's LU without pivoting of A in place of K (A's pattern K's, both
    // triangles in `pattern`; its values, which need not be symmetric, in `values`): then
    // solve() solves A. False where a pivot fails (the factor is then made again by refactor())
    // or where the factor is not our supernodal one.
    bool refactor_lu(const SparseMatrix& pattern, const double* values);
    // The last factorization's flops over a whole one's: below 1 where the supernodal factor
    // redid only what changed (1 for the other kernels, which factor whole).
    double refactored_share() const;

    // y = L^-1 P b; the returned view is valid until the next forward() and may be
    // modified in place before backward(). Not for the supernodal LU (throws).
    Eigen::Map<Eigen::VectorXd> forward(const Eigen::VectorXd& b);
    // x = P^T L^-T y, with y the (possibly modified) result of the last forward().
    void backward(Eigen::VectorXd& x);
    // x = K^-1 b: one forward and one backward solve (the floor of a substep).
    void solve(const Eigen::VectorXd& b, Eigen::VectorXd& x);

private:
    struct Cholmod;
    struct Lu;
    std::unique_ptr<Cholmod> c_;
    std::unique_ptr<Lu> lu_;
    std::unique_ptr<SupernodalCholesky> supernodal_;
    void factor_supernodal(const SparseMatrix& lower, const char* what);  // throws if not SPD
    double factor_flops_ = 0;
    Eigen::Index n_ = 0, m_ = 0;
    std::vector<int> perm_, inverse_perm_;  // factor position -> unknown, and back
    // Without trailing unknowns: triu(P K P^T), factored in natural order, and for each of its
    // values the position of K's lower-triangle value it is (refactor()).
    SparseMatrix permuted_upper_;
    std::vector<int> value_map_;
    Eigen::MatrixXd trailing_block_;
};

}  // namespace contactbody
