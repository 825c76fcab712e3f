#include "linalg/supernodal_cholesky.hpp"

#include <algorithm>
#include <array>
#include <stdexcept>

#include "util/worker_team.hpp"

namespace contactbody {

namespace {

// The lower pattern of P K P^T by columns (rows > column, ascending), from K's lower triangle.
void permuted_lower(const SparseMatrix& lower, const std::vector<int>& position, std::vector<int>& start,
                    std::vector<int>& rows) {
    const Eigen::Index n = lower.cols();
    start.assign(static_cast<size_t>(n) + 1, 0);
    for (Eigen::Index j = 0; j < n; ++j)
        for (SparseMatrix::InnerIterator it(lower, j); it; ++it) {
            const int a = position[static_cast<size_t>(it.row())], b = position[static_cast<size_t>(j)];
            if (a != b) ++start[static_cast<size_t>(std::min(a, b)) + 1];
        }
    for (Eigen::Index j = 0; j < n; ++j) start[static_cast<size_t>(j) + 1] += start[static_cast<size_t>(j)];
    rows.resize(static_cast<size_t>(start.back()));
    std::vector<int> next(start.begin(), start.end() - 1);
    for (Eigen::Index j = 0; j < n; ++j)
        for (SparseMatrix::InnerIterator it(lower, j); it; ++it) {
            const int a = position[static_cast<size_t>(it.row())], b = position[static_cast<size_t>(j)];
            if (a != b)
                rows[static_cast<size_t>(next[static_cast<size_t>(std::min(a, b))]++)] = std::max(a, b);
        }
    for (Eigen::Index j = 0; j < n; ++j)
        std::sort(rows.begin() + start[static_cast<size_t>(j)],
                  rows.begin() + start[static_cast<size_t>(j) + 1]);
}

}  // namespace

SupernodalCholesky::SupernodalCholesky(const SparseMatrix& lower, const std::vector<int>& position,
                                       bool baseline_kernels, int threads)
    : n_(lower.cols()),
      position_(position),
      kernels_(&supernodal_kernels(baseline_kernels)),
      threads_(std::max(1, threads)) {
    const size_t n = static_cast<size_t>(n_);
    if (lower.rows() != n_ || position.size() != n) throw std::invalid_argument("SupernodalCholesky: sizes");
    std::vector<int> start, rows;
    permuted_lower(lower, position, start, rows);
    // Column structures below the diagonal, column by column: A's rows and the children's
    // structures (the elimination tree's parent of j is its structure's first row). A child's
    // structure is dropped once its parent has it.
    std::vector<int> parent(n, -1), count(n, 0), mark(n, -1);
    std::vector<std::vector<int>> children(n), structure(n);
    for (size_t j = 0; j < n; ++j) {
        std::vector<int>& s = structure[j];
        mark[j] = static_cast<int>(j);
        for (int k = start[j]; k < start[j + 1]; ++k) {
            const int i = rows[static_cast<size_t>(k)];
            if (mark[static_cast<size_t>(i)] != static_cast<int>(j)) {
                mark[static_cast<size_t>(i)] = static_cast<int>(j);
                s.push_back(i);
            }
        }
        for (int c : children[j]) {
            for (int i : structure[static_cast<size_t>(c)])
                if (mark[static_cast<size_t>(i)] != static_cast<int>(j)) {
                    mark[static_cast<size_t>(i)] = static_cast<int>(j);
                    s.push_back(i);
                }
            std::vector<int>().swap(structure[static_cast<size_t>(c)]);
        }
        std::sort(s.begin(), s.end());
        count[j] = static_cast<int>(s.size()) + 1;  // with the diagonal
        if (!s.empty()) {
            parent[j] = s.front();
            children[static_cast<size_t>(s.front())].push_back(static_cast<int>(j));
        }
    }
    structure.clear();
    // Fundamental supernodes: j + 1 joins j's where it is j's parent, j its only child, and
    // their structures agree below.
    std::vector<int> fundamental{0};
    for (size_t j = 1; j < n; ++j)
        if (!(parent[j - 1] == static_cast<int>(j) && children[j].size() == 1 &&
              count[j - 1] == count[j] + 1))
            fundamental.push_back(static_cast<int>(j));
    fundamental.push_back(static_cast<int>(n));
    // Relaxed amalgamation (CHOLMOD's rule): a supernode joins the next one where that one is
    // its parent and the merged panel's zeros stay within a share that falls with its size.
    const size_t f = fundamental.size() - 1;
    first_.assign(1, 0);
    {
        // Walk from the first: keep a current group [first, end) with its panel's entries.
        int group_first = 0;
        double group_entries = 0;
        for (size_t s = 0; s < f; ++s) {
            const int a = fundamental[s], b = fundamental[s + 1];
            double entries = 0;  // of s alone: the lower triangle of its panel
            for (int j = a; j < b; ++j) entries += count[static_cast<size_t>(j)];
            if (s == 0) {
                group_first = a;
                group_entries = entries;
                continue;
            }
            // Merging the group (ending at a - 1) into s: the group's last column's parent must
            // be in s; the group's panel grows to s's rows.
            const int last = a - 1;
            const bool child =
                parent[static_cast<size_t>(last)] >= a && parent[static_cast<size_t>(last)] < b;
            const double columns = b - group_first, group_columns = a - group_first;
            const double merged_rows = group_columns + count[static_cast<size_t>(a)];  // s's rows from a
            const double merged_entries = columns * (columns + 1) / 2 + columns * (merged_rows - columns);
            const double new_zeros = merged_entries - (group_entries + entries);
            const double share = new_zeros / merged_entries;
            const bool merge = child && (columns <= 4 || (columns <= 16 && share < 0.8) ||
                                         (columns <= 48 && share < 0.1) || share < 0.05);
            if (merge) {
                group_entries += entries;
                continue;
            }
            first_.push_back(a);
            group_first = a;
            group_entries = entries;
        }
    }
    first_.push_back(static_cast<int>(n));
    const size_t S = first_.size() - 1;
    super_of_.resize(n);
    for (size_t s = 0; s < S; ++s)
        for (int j = first_[s]; j < first_[s + 1]; ++j)
            super_of_[static_cast<size_t>(j)] = static_cast<int>(s);
    // Row structures by supernode: its columns, then A's rows and the child supernodes' rows
    // beyond its last column.
    std::vector<std::vector<int>> child_supernodes(S);
    own_flops_.assign(S, 0);
    parent_.assign(S, -1);
    std::vector<std::vector<int>> below(S);
    row_start_.assign(1, 0);
    value_start_.assign(1, 0);
    std::fill(mark.begin(), mark.end(), -1);
    for (size_t s = 0; s < S; ++s) {
        const int a = first_[s], b = first_[s + 1];
        std::vector<int>& r = below[s];
        const auto add = [&](int i) {
            if (i >= b && mark[static_cast<size_t>(i)] != static_cast<int>(s)) {
                mark[static_cast<size_t>(i)] = static_cast<int>(s);
                r.push_back(i);
            }
        };
        for (int j = a; j < b; ++j)
            for (int k = start[static_cast<size_t>(j)]; k < start[static_cast<size_t>(j) + 1]; ++k)
                add(rows[static_cast<size_t>(k)]);
        for (int c : child_supernodes[s]) {
            for (int i : below[static_cast<size_t>(c)]) add(i);
            std::vector<int>().swap(below[static_cast<size_t>(c)]);
        }
        std::sort(r.begin(), r.end());
        if (!r.empty()) {
            parent_[s] = super_of_[static_cast<size_t>(r.front())];
            child_supernodes[static_cast<size_t>(parent_[s])].push_back(static_cast<int>(s));
        }
        const std::ptrdiff_t columns = b - a, panel_rows = columns + static_cast<std::ptrdiff_t>(r.size());
        for (int j = a; j < b; ++j) row_index_.push_back(j);
        row_index_.insert(row_index_.end(), r.begin(), r.end());
        row_start_.push_back(static_cast<int>(row_index_.size()));
        value_start_.push_back(value_start_.back() + panel_rows * columns);
        // Flops: the diagonal block's Cholesky, the panel's triangular solve and its update.
        const double c = static_cast<double>(columns), m = static_cast<double>(r.size());
        own_flops_[s] = c * c * c / 3 + m * c * c + m * m * c;
        flops_ += own_flops_[s];
    }
    for (size_t s = 0; s < S; ++s) std::vector<int>().swap(below[s]);
    divide_among_groups(child_supernodes, own_flops_);
    redo_.assign(S, 1);
    reach_.assign(S, 0);
    permuted_.resize(n_);
}

// Subtrees for the groups: from the roots down, the heaviest subtree (by flops) is split (its
// root goes to the top, its children become subtrees) until none exceeds half a group's share;
// then each subtree, heaviest first, joins the lightest group. All of it from the analysis
// alone, never from the number of threads (docs/decisions.md, "The supernodal factor on
// several threads").
void SupernodalCholesky::divide_among_groups(const std::vector<std::vector<int>>& children,
                                             const std::vector<double>& own_flops) {
    const size_t S = own_flops.size();
    std::vector<double> subtree(own_flops);
    std::vector<int> parent(S, -1);
    for (size_t s = 0; s < S; ++s)
        for (int c : children[s]) {
            subtree[s] += subtree[static_cast<size_t>(c)];  // children come first
            parent[static_cast<size_t>(c)] = static_cast<int>(s);
        }
    std::vector<int> parts, group(S, -1);
    for (size_t s = 0; s < S; ++s)
        if (parent[s] < 0) parts.push_back(static_cast<int>(s));
    std::vector<char> top(S, 0);
    const auto heavier = [&](int a, int b) {
        return subtree[static_cast<size_t>(a)] != subtree[static_cast<size_t>(b)]
                   ? subtree[static_cast<size_t>(a)] > subtree[static_cast<size_t>(b)]
                   : a < b;
    };
    for (;;) {
        const auto h = std::min_element(parts.begin(), parts.end(), heavier);
        if (h == parts.end() || subtree[static_cast<size_t>(*h)] <= flops_ / (2.0 * groups) ||
            children[static_cast<size_t>(*h)].empty())
            break;
        const int root = *h;
        parts.erase(h);
        top[static_cast<size_t>(root)] = 1;
        parts.insert(parts.end(), children[static_cast<size_t>(root)].begin(),
                     children[static_cast<size_t>(root)].end());
    }
    std::sort(parts.begin(), parts.end(), heavier);
    std::vector<double> load(groups, 0);
    for (int part : parts) {
        const int g = static_cast<int>(std::min_element(load.begin(), load.end()) - load.begin());
        load[static_cast<size_t>(g)] += subtree[static_cast<size_t>(part)];
        group[static_cast<size_t>(part)] = g;
    }
    group_supernodes_.assign(groups, {});
    top_.clear();
    top_flops_ = 0;
    for (size_t s = S; s-- > 0;)  // parents first: a subtree's supernodes take its root's group
        if (!top[s] && group[s] < 0) group[s] = group[static_cast<size_t>(parent[s])];
    // Group g's buffer holds the panels of the top supernodes its supernodes update.
    top_offset_.assign(groups, std::vector<std::ptrdiff_t>(S, -1));
    top_values_.assign(groups, 0);
    for (size_t s = 0; s < S; ++s) {
        if (top[s]) {
            top_.push_back(static_cast<int>(s));
            top_flops_ += own_flops[s];
            continue;
        }
        const size_t g = static_cast<size_t>(group[s]);
        group_supernodes_[g].push_back(static_cast<int>(s));
        for (int k = row_start_[s] + (first_[s + 1] - first_[s]); g > 0 && k < row_start_[s + 1]; ++k) {
            const size_t t =
                static_cast<size_t>(super_of_[static_cast<size_t>(row_index_[static_cast<size_t>(k)])]);
            if (top[t] && top_offset_[g][t] < 0) {
                top_offset_[g][t] = top_values_[g];
                top_values_[g] += value_start_[t + 1] - value_start_[t];
            }
        }
    }
}

double SupernodalCholesky::factor_nonzeros() const {
    double sum = 0;
    for (size_t s = 0; s + 1 < first_.size(); ++s) {
        const double c = first_[s + 1] - first_[s], r = row_start_[s + 1] - row_start_[s];
        sum += c * (c + 1) / 2 + c * (r - c);
    }
    return sum;
}

bool SupernodalCholesky::factor(const SparseMatrix& lower) {
    const size_t S = first_.size() - 1;
    failed_ = -1;
    const bool partial = plan(Factored::cholesky, lower, lower.valuePtr());
    lu_ = false;  // upper_ stays allocated: a held operator goes back and forth
    if (partial)
        clear_redone(values_);
    else
        values_.assign(static_cast<size_t>(value_start_.back()), 0.0);
    // K's entries into the panels: entry (i, j) of P K P^T (i >= j) into j's supernode.
    for (Eigen::Index col = 0; col < n_; ++col)
        for (SparseMatrix::InnerIterator it(lower, col); it; ++it) {
            int i = position_[static_cast<size_t>(it.row())], j = position_[static_cast<size_t>(col)];
            if (i < j) std::swap(i, j);
            const size_t s = static_cast<size_t>(super_of_[static_cast<size_t>(j)]);
            if (!redo_[s]) continue;
            const int* r = row_index_.data() + row_start_[s];
            const int rows = row_start_[s + 1] - row_start_[s];
            const std::ptrdiff_t place = std::lower_bound(r, r + rows, i) - r;
            values_[static_cast<size_t>(value_start_[s] + (j - first_[s]) * rows + place)] += it.value();
        }
    std::ptrdiff_t update_size = 0, largest_below = 0;
    for (size_t s = 0; s < S; ++s) {
        const std::ptrdiff_t m = (row_start_[s + 1] - row_start_[s]) - (first_[s + 1] - first_[s]);
        update_size = std::max(update_size, m * std::min(m, update_block));
        largest_below = std::max(largest_below, m);
    }
    gathered_.resize(largest_below);
    const WorkerTeam team(threads_);
    update_.resize(static_cast<size_t>(threads_));
    local_.resize(static_cast<size_t>(threads_));
    for (int w = 0; w < threads_; ++w) {
        update_[static_cast<size_t>(w)].resize(static_cast<size_t>(update_size));
        local_[static_cast<size_t>(w)].resize(static_cast<size_t>(n_));
    }
    // Groups 1.. update the top in buffers of their own (zero less their updates), added in
    // their order after them.
    top_updates_.resize(groups);
    targets_.resize(groups);
    for (size_t g = 0; g < groups; ++g) {
        std::vector<double*>& t = targets_[g];
        t.resize(S);
        top_updates_[g].assign(static_cast<size_t>(top_values_[g]), 0.0);
        for (size_t s = 0; s < S; ++s)
            t[s] = top_offset_[g][s] >= 0 ? top_updates_[g].data() + top_offset_[g][s]
                                          : values_.data() + value_start_[s];
    }
    // A supernode redone is factored; another updates those it reaches.
    const auto run_supernode = [&](size_t s, double* const* targets, int worker, const WorkerTeam* on) {
        if (redo_[s]) return factor_supernode(s, targets, worker, on);
        update_ancestors(s, reach_[s], targets, worker, on);
        return std::ptrdiff_t{-1};
    };
    std::array<std::ptrdiff_t, groups> failed;
    failed.fill(-1);
    team.run(static_cast<int>(groups), [&](int g, int worker) {
        for (int s : group_supernodes_[static_cast<size_t>(g)]) {
            failed[static_cast<size_t>(g)] = run_supernode(
                static_cast<size_t>(s), targets_[static_cast<size_t>(g)].data(), worker, nullptr);
            if (failed[static_cast<size_t>(g)] >= 0) return;
        }
    });
    for (std::ptrdiff_t f : failed)
        if (f >= 0 && (failed_ < 0 || f < failed_)) failed_ = f;
    if (failed_ >= 0) {
        factored_ = Factored::none;
        return false;
    }
    team.run(static_cast<int>(top_.size()), [&](int k, int) {
        const size_t s = static_cast<size_t>(top_[static_cast<size_t>(k)]);
        if (!redo_[s]) return;
        double* panel = values_.data() + value_start_[s];
        const std::ptrdiff_t size = value_start_[s + 1] - value_start_[s];
        for (size_t g = 1; g < groups; ++g) {
            if (top_offset_[g][s] < 0) continue;
            const double* u = top_updates_[g].data() + top_offset_[g][s];
            for (std::ptrdiff_t i = 0; i < size; ++i) panel[i] += u[i];
        }
    });
    for (int s : top_) {
        failed_ = run_supernode(static_cast<size_t>(s), targets_[0].data(), 0, &team);
        if (failed_ >= 0) {
            factored_ = Factored::none;
            return false;
        }
    }
    return true;
}

// Whether this factorization may redo only part of the last one: the last factored `kind`
// with the same pattern. Then redo_ marks the supernodes holding a changed value (entry (i, j)
// of P K P^T belongs to min(i, j)'s) and their ancestors, reach_ each other supernode's first
// row below that lies in a redone one (rows ascend along the path to the root, so those rows
// are the last ones); else redo_ marks all. Keeps the values for the next call.
bool SupernodalCholesky::plan(Factored kind, const SparseMatrix& pattern, const double* values) {
    const size_t S = first_.size() - 1;
    const size_t count = static_cast<size_t>(pattern.nonZeros());
    const bool partial = factored_ == kind && factored_values_.size() == count;
    if (partial) {
        std::fill(redo_.begin(), redo_.end(), 0);
        for (Eigen::Index col = 0; col < n_; ++col)
            for (int k = pattern.outerIndexPtr()[col]; k < pattern.outerIndexPtr()[col + 1]; ++k)
                if (values[k] != factored_values_[static_cast<size_t>(k)]) {
                    const int i = position_[static_cast<size_t>(pattern.innerIndexPtr()[k])],
                              j = position_[static_cast<size_t>(col)];
                    redo_[static_cast<size_t>(super_of_[static_cast<size_t>(std::min(i, j))])] = 1;
                }
        for (size_t s = 0; s < S; ++s)  // parents come after their children
            if (redo_[s] && parent_[s] >= 0) redo_[static_cast<size_t>(parent_[s])] = 1;
    } else {
        std::fill(redo_.begin(), redo_.end(), 1);
    }
    refactored_flops_ = 0;
    for (size_t s = 0; s < S; ++s) {
        const std::ptrdiff_t columns = first_[s + 1] - first_[s];
        const std::ptrdiff_t m = (row_start_[s + 1] - row_start_[s]) - columns;
        if (redo_[s]) {
            reach_[s] = 0;
            refactored_flops_ += own_flops_[s];
            continue;
        }
        const int* r = row_index_.data() + row_start_[s] + columns;
        std::ptrdiff_t q = m;
        while (q > 0 && redo_[static_cast<size_t>(super_of_[static_cast<size_t>(r[q - 1])])]) --q;
        reach_[s] = q;
        const double left = static_cast<double>(m - q);
        refactored_flops_ += left * left * static_cast<double>(columns);
    }
    factored_ = kind;
    factored_values_.assign(values, values + count);
    return partial;
}

// Zeroes the panels of the supernodes redone.
void SupernodalCholesky::clear_redone(std::vector<double>& panels) const {
    for (size_t s = 0; s + 1 < first_.size(); ++s)
        if (redo_[s]) std::fill(panels.begin() + value_start_[s], panels.begin() + value_start_[s + 1], 0.0);
}

bool SupernodalCholesky::factor_lu(const SparseMatrix& pattern, const double* values) {
    const size_t S = first_.size() - 1;
    failed_ = -1;
    lu_ = true;
    if (plan(Factored::lu, pattern, values)) {
        clear_redone(values_);
        clear_redone(upper_);
    } else {
        values_.assign(static_cast<size_t>(value_start_.back()), 0.0);
        upper_.assign(values_.size(), 0.0);
    }
    // A's entry (i, j) of P A P^T: L's side (values_) of j's supernode where i >= j, U's side
    // (upper_, transposed) of i's where i < j.
    for (Eigen::Index col = 0; col < n_; ++col)
        for (int k = pattern.outerIndexPtr()[col]; k < pattern.outerIndexPtr()[col + 1]; ++k) {
            const int i = position_[static_cast<size_t>(pattern.innerIndexPtr()[k])],
                      j = position_[static_cast<size_t>(col)];
            const int a = std::max(i, j), b = std::min(i, j);
            const size_t s = static_cast<size_t>(super_of_[static_cast<size_t>(b)]);
            if (!redo_[s]) continue;
            const int* r = row_index_.data() + row_start_[s];
            const int rows = row_start_[s + 1] - row_start_[s];
            const std::ptrdiff_t place = std::lower_bound(r, r + rows, a) - r;
            (i >= j ? values_
                    : upper_)[static_cast<size_t>(value_start_[s] + (b - first_[s]) * rows + place)] +=
                values[k];
        }
    std::ptrdiff_t update_size = 0, largest_square = 0, largest_below = 0;
    for (size_t s = 0; s < S; ++s) {
        const std::ptrdiff_t c = first_[s + 1] - first_[s], m = (row_start_[s + 1] - row_start_[s]) - c;
        update_size = std::max(update_size, m * std::min(m, update_block));
        largest_square = std::max(largest_square, c * c);
        largest_below = std::max(largest_below, m);
    }
    gathered_.resize(largest_below);
    square_.resize(static_cast<size_t>(largest_square));
    if (update_.empty()) {  // else factor()'s, whose first worker's fit
        update_.resize(1);
        local_.resize(1);
    }
    update_[0].resize(static_cast<size_t>(update_size));
    local_[0].resize(static_cast<size_t>(n_));
    lu_targets_.resize(2 * S);  // L's panels, then U's
    for (size_t s = 0; s < S; ++s) {
        lu_targets_[s] = values_.data() + value_start_[s];
        lu_targets_[S + s] = upper_.data() + value_start_[s];
    }
    for (size_t s = 0; s < S; ++s) {
        if (!redo_[s]) {
            update_ancestors_lu(s, reach_[s], lu_targets_.data(), lu_targets_.data() + S);
            continue;
        }
        failed_ = factor_supernode_lu(s, lu_targets_.data(), lu_targets_.data() + S);
        if (failed_ >= 0) {
            factored_ = Factored::none;
            return false;
        }
    }
    return true;
}

// The diagonal block (L's lower triangle and U's transposed) gathered, factored by the dense
// LU and put back (L unit lower in values_, U^T in upper_); the rows below solved on each side
// (L21 = A21 U11^-1, U12^T = A12^T L11^-T); the update L21 U12 subtracted, its lower part from
// the ancestors' L and its upper part, as U12^T L21^T, from their U.
std::ptrdiff_t SupernodalCholesky::factor_supernode_lu(size_t s, double* const* lower, double* const* upper) {
    const std::ptrdiff_t columns = first_[s + 1] - first_[s], rows = row_start_[s + 1] - row_start_[s];
    const std::ptrdiff_t m = rows - columns;
    double* L = values_.data() + value_start_[s];
    double* U = upper_.data() + value_start_[s];
    double* D = square_.data();
    const SupernodalKernels& k = *kernels_;
    for (std::ptrdiff_t c = 0; c < columns; ++c)
        for (std::ptrdiff_t r = 0; r < columns; ++r)
            D[c * columns + r] = r >= c ? L[c * rows + r] : U[r * rows + c];
    const std::ptrdiff_t bad = k.lu(D, columns, columns);
    if (bad >= 0) return first_[s] + bad;
    for (std::ptrdiff_t c = 0; c < columns; ++c)
        for (std::ptrdiff_t r = c; r < columns; ++r) {
            L[c * rows + r] = r == c ? 1.0 : D[c * columns + r];
            U[c * rows + r] = D[r * columns + c];
        }
    if (m == 0) return -1;
    k.solve_right(U, columns, rows, L + columns, m, rows);
    k.solve_right(L, columns, rows, U + columns, m, rows);
    update_ancestors_lu(s, 0, lower, upper);
    return -1;
}

// The update's columns from `from` on, made by the same blocks as all of them (the same bits).
void SupernodalCholesky::update_ancestors_lu(size_t s, std::ptrdiff_t from, double* const* lower,
                                             double* const* upper) {
    const std::ptrdiff_t columns = first_[s + 1] - first_[s], rows = row_start_[s + 1] - row_start_[s];
    const std::ptrdiff_t m = rows - columns;
    const SupernodalKernels& k = *kernels_;
    const double* L21 = values_.data() + value_start_[s] + columns;
    const double* U12t = upper_.data() + value_start_[s] + columns;
    double* C = update_[0].data();
    int* local = local_[0].data();
    for (std::ptrdiff_t q0 = from / update_block * update_block; q0 < m; q0 += update_block) {
        const std::ptrdiff_t width = std::min(update_block, m - q0);
        k.product(L21 + q0, rows, U12t + q0, rows, m - q0, width, columns, C, m - q0);
        scatter(s, q0, q0 + width, C, m - q0, lower, local, false, from);
        k.product(U12t + q0, rows, L21 + q0, rows, m - q0, width, columns, C, m - q0);
        scatter(s, q0, q0 + width, C, m - q0, upper, local, true, from);
    }
}

// Right-looking: the diagonal block's Cholesky, the rows below by a triangular solve, their
// update C = L21 L21^T subtracted from the ancestors' panels. A panel of more than column_block
// columns is factored by blocks of them (each block's rows below solved, then the panel's
// columns after it updated), and C is made update_block columns at a time; blocks of rows and
// columns are the tasks of team.
std::ptrdiff_t SupernodalCholesky::factor_supernode(size_t s, double* const* targets, int worker,
                                                    const WorkerTeam* team) {
    const std::ptrdiff_t columns = first_[s + 1] - first_[s], rows = row_start_[s + 1] - row_start_[s];
    double* panel = values_.data() + value_start_[s];
    const SupernodalKernels& k = *kernels_;
    const auto run = [&](std::ptrdiff_t tasks, const auto& task) {
        if (team)
            team->run(static_cast<int>(tasks), task);
        else
            for (std::ptrdiff_t t = 0; t < tasks; ++t) task(static_cast<int>(t), worker);
    };
    const auto blocks = [](std::ptrdiff_t size, std::ptrdiff_t block) { return (size + block - 1) / block; };
    // Rows [from, rows) of columns [c0, c0 + width), solved against that block's diagonal.
    const auto solve_below = [&](std::ptrdiff_t c0, std::ptrdiff_t width, std::ptrdiff_t from) {
        const std::ptrdiff_t below = rows - from;
        if (below <= 0) return;
        const double* diagonal = panel + c0 * rows + c0;
        run(blocks(below, row_block), [&](int b, int) {
            const std::ptrdiff_t r0 = from + b * row_block, height = std::min(row_block, rows - r0);
            k.solve_right(diagonal, width, rows, panel + c0 * rows + r0, height, rows);
        });
    };
    if (columns <= column_block) {
        const std::ptrdiff_t bad = k.cholesky(panel, columns, rows);
        if (bad >= 0) return first_[s] + bad;
        solve_below(0, columns, columns);
    } else {
        for (std::ptrdiff_t c0 = 0; c0 < columns; c0 += column_block) {
            const std::ptrdiff_t width = std::min(column_block, columns - c0), next = c0 + width;
            const std::ptrdiff_t bad = k.cholesky(panel + c0 * rows + c0, width, rows);
            if (bad >= 0) return first_[s] + c0 + bad;
            solve_below(c0, width, next);
            run(blocks(columns - next, update_block), [&](int b, int) {
                const std::ptrdiff_t j0 = next + b * update_block, w = std::min(update_block, columns - j0);
                const double* a = panel + c0 * rows + j0;
                k.subtract_product(a, rows, a, rows, rows - j0, w, width, panel + j0 * rows + j0, rows);
            });
        }
    }
    update_ancestors(s, 0, targets, worker, team);
    return -1;
}

// C = L21 L21^T's columns from `from` on, subtracted: made by the same blocks as all of them
// (one SYRK up to update_block rows, else GEMMs of update_block columns), so the same bits.
void SupernodalCholesky::update_ancestors(size_t s, std::ptrdiff_t from, double* const* targets, int worker,
                                          const WorkerTeam* team) {
    const std::ptrdiff_t columns = first_[s + 1] - first_[s], rows = row_start_[s + 1] - row_start_[s];
    const std::ptrdiff_t m = rows - columns;
    if (from >= m) return;
    const SupernodalKernels& k = *kernels_;
    const double* L21 = values_.data() + value_start_[s] + columns;
    if (m <= update_block) {
        double* C = update_[static_cast<size_t>(worker)].data();
        k.lower_product(L21, rows, m, columns, C, m);
        scatter(s, 0, m, C, m, targets, local_[static_cast<size_t>(worker)].data(), false, from);
        return;
    }
    const std::ptrdiff_t first_block = from / update_block;
    const auto task = [&](int b, int w) {
        const std::ptrdiff_t q0 = (first_block + b) * update_block, width = std::min(update_block, m - q0);
        double* C = update_[static_cast<size_t>(w)].data();
        k.product(L21 + q0, rows, L21 + q0, rows, m - q0, width, columns, C, m - q0);
        scatter(s, q0, q0 + width, C, m - q0, targets, local_[static_cast<size_t>(w)].data(), false, from);
    };
    const std::ptrdiff_t tasks = (m + update_block - 1) / update_block - first_block;
    if (team)
        team->run(static_cast<int>(tasks), task);
    else
        for (std::ptrdiff_t b = 0; b < tasks; ++b) task(static_cast<int>(b), worker);
}

// Columns [q0, q1) of supernode s's update C (C's rows from q0 on, leading dimension ldc)
// subtracted from the panels that hold them, grouped by supernode (rows ascending), each group
// through that supernode's row places.
void SupernodalCholesky::scatter(size_t s, std::ptrdiff_t q0, std::ptrdiff_t q1, const double* C,
                                 std::ptrdiff_t ldc, double* const* targets, int* local, bool strict,
                                 std::ptrdiff_t from) const {
    const std::ptrdiff_t columns = first_[s + 1] - first_[s];
    const std::ptrdiff_t m = (row_start_[s + 1] - row_start_[s]) - columns;
    const int* r = row_index_.data() + row_start_[s] + columns;
    std::ptrdiff_t q = std::max(q0, from);
    while (q < q1) {
        const size_t t = static_cast<size_t>(super_of_[static_cast<size_t>(r[q])]);
        const int t_rows = row_start_[t + 1] - row_start_[t];
        for (int i = 0; i < t_rows; ++i) local[row_index_[static_cast<size_t>(row_start_[t] + i)]] = i;
        double* target = targets[t];
        for (; q < q1 && super_of_[static_cast<size_t>(r[q])] == static_cast<int>(t); ++q) {
            double* column = target + static_cast<std::ptrdiff_t>(r[q] - first_[t]) * t_rows;
            const double* c = C + (q - q0) * ldc - q0;
            for (std::ptrdiff_t p = strict ? q + 1 : q; p < m; ++p) column[local[r[p]]] -= c[p];
        }
    }
}

void SupernodalCholesky::solve(const Eigen::VectorXd& b, Eigen::VectorXd& x) const {
    const size_t S = first_.size() - 1;
    Eigen::VectorXd& y = permuted_;
    for (Eigen::Index i = 0; i < n_; ++i) y[position_[static_cast<size_t>(i)]] = b[i];
    for (size_t s = 0; s < S; ++s) {  // L y = P b
        const Eigen::Index columns = first_[s + 1] - first_[s], rows = row_start_[s + 1] - row_start_[s];
        const Eigen::Index m = rows - columns;
        kernels_->forward_panel(values_.data() + value_start_[s], rows, columns, y.data() + first_[s],
                                gathered_.data());
        const int* r = row_index_.data() + row_start_[s] + columns;
        for (Eigen::Index p = 0; p < m; ++p) y[r[p]] -= gathered_[p];
    }
    const double* back = lu_ ? upper_.data() : values_.data();  // U^T's panels, or L's
    for (size_t s = S; s-- > 0;) {                              // L^T z = y (U z = y)
        const Eigen::Index columns = first_[s + 1] - first_[s], rows = row_start_[s + 1] - row_start_[s];
        const Eigen::Index m = rows - columns;
        const int* r = row_index_.data() + row_start_[s] + columns;
        for (Eigen::Index p = 0; p < m; ++p) gathered_[p] = y[r[p]];
        kernels_->backward_panel(back + value_start_[s], rows, columns, y.data() + first_[s], gathered_.data());
    }
    x.resize(n_);
    for (Eigen::Index i = 0; i < n_; ++i) x[i] = y[position_[static_cast<size_t>(i)]];
}

}  // namespace contactbody
