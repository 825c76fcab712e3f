// A supernodal Cholesky factor L L^T = P K P^T of a symmetric positive definite K in a given
// fill-reducing order: columns with the same structure below them are grouped into supernodes
// (fundamental ones, then relaxed amalgamation: a child merged into its parent where the zeros
// it adds stay few), each stored as a dense panel and factored right-looking by dense kernels
// (Eigen's blocked LLT, triangular solve and rank update); its solves run by panels. On several
// threads, independent subtrees run side by side and the large panels near the root are cut
// into blocks of fixed sizes: the same arithmetic for any number of threads, so the same bits.
// Written here because CHOLMOD's supernodal module is GPL (docs/decisions.md, "The factor of a
// 3D body"). It also makes the LU without pivoting of a matrix with the same pattern but values
// that are not symmetric, on the same supernodes (factor_lu: a held operator's slipping rows).
// A factorization of the same kind as the last redoes only the supernodes whose values changed
// and their ancestors, with the same bits as a whole one (docs/decisions.md, "The supernodal
// factor redoes only what changed").
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
    // threads: of the numeric factor (util/worker_team.hpp), its bits the same for any number.
    SupernodalCholesky(const SparseMatrix& lower, const std::vector<int>& position,
                       bool baseline_kernels = false, int threads = 1);
    const char* kernel_set() const { return kernels_->name; }
    // The numeric factor of a matrix with lower's pattern. False where K is not positive
    // definite (failed_column() tells where, in factor order).
    bool factor(const SparseMatrix& lower);
    Eigen::Index failed_column() const { return failed_; }
    // The LU factor without pivoting, P A P^T = L U, of a matrix A with lower's symmetric
    // pattern (both triangles in `pattern`, CSC; its values in `values`) but values that need not
    // be: the same supernodes, U's rows beside L's columns (twice the flops and memory), on one
    // thread. False where a pivot is not above 1e-12 times what is left of its column's largest
    // entry (failed_column()). The held operator's slipping rows (linalg/held_operator.hpp).
    bool factor_lu(const SparseMatrix& pattern, const double* values);
    bool lu() const { return lu_; }
    // The last factorization's flops over a whole one's (1 where it redid all).
    double refactored_share() const { return refactored_flops_ / flops_; }
    // x = K^-1 b. Allocates nothing once the factor exists.
    void solve(const Eigen::VectorXd& b, Eigen::VectorXd& x) const;

    Eigen::Index size() const { return n_; }
    Eigen::Index supernodes() const { return static_cast<Eigen::Index>(first_.size()) - 1; }
    double factor_nonzeros() const;                 // of the panels (the amalgamation's zeros included)
    double factor_flops() const { return flops_; }  // of the factorization, with those zeros
    int threads() const { return threads_; }
    // The subtrees' groups that run side by side (each group past the first updates the
    // supernodes above them in a buffer of its own: memory that one more group costs), and the
    // share of the flops left to those supernodes (run one by one, each cut into blocks).
    static constexpr size_t groups = 2;
    double top_share() const { return top_flops_ / flops_; }
    // The buffers' entries (groups 1.. 's updates of the top), the memory that threads cost.
    double buffer_values() const {
        double sum = 0;
        for (size_t g = 1; g < top_values_.size(); ++g) sum += static_cast<double>(top_values_[g]);
        return sum;
    }
    // Blocks of a panel: columns factored at a time, the columns of an update computed at a
    // time, and rows of a triangular solve.
    static constexpr std::ptrdiff_t column_block = 256, update_block = 256, row_block = 512;

private:
    Eigen::Index n_ = 0, failed_ = -1;
    std::vector<int> position_;
    // Supernode s: columns first_[s] .. first_[s + 1] - 1; rows (its columns, then the rows
    // below) row_index_[row_start_[s] .. row_start_[s + 1]); its panel (rows x columns,
    // column-major) at values_[value_start_[s]].
    std::vector<int> first_, super_of_, row_start_, row_index_;
    std::vector<std::ptrdiff_t> value_start_;
    std::vector<double> values_;
    // The LU's U by rows beside L's columns: supernode s's U(its columns, the rows below)
    // transposed, at upper_[value_start_[s]] as values_'s panel (its diagonal block: U^T, lower);
    // values_'s diagonal blocks then hold L's unit lower triangle. Kept after a Cholesky, so that
    // a held operator that goes back and forth between the two allocates nothing.
    std::vector<double> upper_, square_;
    std::vector<double*> lu_targets_;  // each supernode's L panel, then its U panel
    bool lu_ = false;
    double flops_ = 0, top_flops_ = 0, refactored_flops_ = 0;
    // Each supernode's parent (-1 at a root) and flops (its factor and update). What the last
    // factorization factored (none after a failure), and its input values: a factorization of
    // the same kind redoes the supernodes those values' changes reach (redo_), and each other
    // supernode's update of them, from the first of its rows below that lies in one (reach_).
    std::vector<int> parent_;
    std::vector<double> own_flops_;
    enum class Factored { none, cholesky, lu } factored_ = Factored::none;
    std::vector<double> factored_values_;
    std::vector<char> redo_;
    std::vector<std::ptrdiff_t> reach_;
    bool plan(Factored kind, const SparseMatrix& pattern, const double* values);
    void clear_redone(std::vector<double>& panels) const;
    const SupernodalKernels* kernels_;
    int threads_ = 1;
    // The groups' supernodes (ascending), and those above them (top_, ascending); each top
    // supernode's place in the buffers that take groups 1.. 's updates of it (top_offset_).
    std::vector<std::vector<int>> group_supernodes_;
    std::vector<int> top_;
    std::vector<std::vector<std::ptrdiff_t>> top_offset_;  // per group (group 0 has none)
    std::vector<std::ptrdiff_t> top_values_;
    std::vector<std::vector<double>> top_updates_;  // per group: its buffer
    std::vector<std::vector<double*>> targets_;     // per group: where each supernode's panel is
    // Per worker: a panel's update of its ancestors (a block of columns), a supernode's
    // row -> its place.
    std::vector<std::vector<double>> update_;
    std::vector<std::vector<int>> local_;
    mutable Eigen::VectorXd permuted_, gathered_;
    // One supernode's factor and its updates of the panels at `targets`; team: where its blocks
    // run (null: on worker alone). -1, or the failed column.
    std::ptrdiff_t factor_supernode(size_t s, double* const* targets, int worker,
                                    const class WorkerTeam* team);
    // Its update of the ancestors' panels from row `from` (of those below its columns) on.
    void update_ancestors(size_t s, std::ptrdiff_t from, double* const* targets, int worker,
                          const class WorkerTeam* team);
    void update_ancestors_lu(size_t s, std::ptrdiff_t from, double* const* lower, double* const* upper);
    void divide_among_groups(const std::vector<std::vector<int>>& children,
                             const std::vector<double>& own_flops);
    // strict: C's diagonal left out (the LU's update of U, whose diagonal L's update has made).
    // from: the first column scattered (C's still starts at q0).
    void scatter(size_t s, std::ptrdiff_t q0, std::ptrdiff_t q1, const double* C, std::ptrdiff_t ldc,
                 double* const* targets, int* local, bool strict = false, std::ptrdiff_t from = 0) const;
    std::ptrdiff_t factor_supernode_lu(size_t s, double* const* lower, double* const* upper);
};

}  // namespace contactbody
