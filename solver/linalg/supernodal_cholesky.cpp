#include "linalg/supernodal_cholesky.hpp"

#include <algorithm>
#include <stdexcept>

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
                                       bool baseline_kernels)
    : n_(lower.cols()), position_(position), kernels_(&supernodal_kernels(baseline_kernels)) {
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
    std::vector<int> merged_first(fundamental.begin(), fundamental.end());
    std::vector<double> zeros(f, 0);
    first_.assign(1, 0);
    {
        // Walk from the first: keep a current group [first, end) with its panel rows and zeros.
        int group_first = 0;
        double group_zeros = 0, group_entries = 0;
        for (size_t s = 0; s < f; ++s) {
            const int a = fundamental[s], b = fundamental[s + 1];
            double entries = 0;  // of s alone: the lower triangle of its panel
            for (int j = a; j < b; ++j) entries += count[static_cast<size_t>(j)];
            if (s == 0) {
                group_first = a;
                group_entries = entries;
                group_zeros = 0;
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
                group_zeros = new_zeros;
                group_entries += entries;
                (void)group_zeros;
                continue;
            }
            first_.push_back(a);
            group_first = a;
            group_entries = entries;
            group_zeros = 0;
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
        if (!r.empty())
            child_supernodes[static_cast<size_t>(super_of_[static_cast<size_t>(r.front())])].push_back(
                static_cast<int>(s));
        const std::ptrdiff_t columns = b - a, panel_rows = columns + static_cast<std::ptrdiff_t>(r.size());
        for (int j = a; j < b; ++j) row_index_.push_back(j);
        row_index_.insert(row_index_.end(), r.begin(), r.end());
        row_start_.push_back(static_cast<int>(row_index_.size()));
        value_start_.push_back(value_start_.back() + panel_rows * columns);
        // Flops: the diagonal block's Cholesky, the panel's triangular solve and its update.
        const double c = static_cast<double>(columns), m = static_cast<double>(r.size());
        flops_ += c * c * c / 3 + m * c * c + m * m * c;
    }
    for (size_t s = 0; s < S; ++s) std::vector<int>().swap(below[s]);
    local_.assign(n, -1);
    permuted_.resize(n_);
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
    values_.assign(static_cast<size_t>(value_start_.back()), 0.0);
    // K's entries into the panels: entry (i, j) of P K P^T (i >= j) into j's supernode.
    for (Eigen::Index col = 0; col < n_; ++col)
        for (SparseMatrix::InnerIterator it(lower, col); it; ++it) {
            int i = position_[static_cast<size_t>(it.row())], j = position_[static_cast<size_t>(col)];
            if (i < j) std::swap(i, j);
            const size_t s = static_cast<size_t>(super_of_[static_cast<size_t>(j)]);
            const int* r = row_index_.data() + row_start_[s];
            const int rows = row_start_[s + 1] - row_start_[s];
            const std::ptrdiff_t place = std::lower_bound(r, r + rows, i) - r;
            values_[static_cast<size_t>(value_start_[s] + (j - first_[s]) * rows + place)] += it.value();
        }
    Eigen::Index largest_below = 0;
    for (size_t s = 0; s < S; ++s)
        largest_below = std::max<Eigen::Index>(
            largest_below, (row_start_[s + 1] - row_start_[s]) - (first_[s + 1] - first_[s]));
    update_.resize(static_cast<size_t>(largest_below * largest_below));
    gathered_.resize(largest_below);
    SupernodalLayout layout;
    layout.supernodes = S;
    layout.first = first_.data();
    layout.super_of = super_of_.data();
    layout.row_start = row_start_.data();
    layout.row_index = row_index_.data();
    layout.value_start = value_start_.data();
    failed_ = kernels_->factor(layout, values_.data(), update_.data(), local_.data());
    return failed_ < 0;
}

void SupernodalCholesky::solve(const Eigen::VectorXd& b, Eigen::VectorXd& x) const {
    const size_t S = first_.size() - 1;
    Eigen::VectorXd& y = permuted_;
    for (Eigen::Index i = 0; i < n_; ++i) y[position_[static_cast<size_t>(i)]] = b[i];
    using Panel = Eigen::Map<const Eigen::MatrixXd, 0, Eigen::OuterStride<>>;
    for (size_t s = 0; s < S; ++s) {  // L y = P b
        const Eigen::Index columns = first_[s + 1] - first_[s], rows = row_start_[s + 1] - row_start_[s];
        const Eigen::Index m = rows - columns;
        const Panel panel(values_.data() + value_start_[s], rows, columns, Eigen::OuterStride<>(rows));
        auto ys = y.segment(first_[s], columns);
        panel.topRows(columns).triangularView<Eigen::Lower>().solveInPlace(ys);
        if (m == 0) continue;
        auto g = gathered_.head(m);
        g.noalias() = panel.bottomRows(m) * ys;
        const int* r = row_index_.data() + row_start_[s] + columns;
        for (Eigen::Index p = 0; p < m; ++p) y[r[p]] -= g[p];
    }
    for (size_t s = S; s-- > 0;) {  // L^T z = y
        const Eigen::Index columns = first_[s + 1] - first_[s], rows = row_start_[s + 1] - row_start_[s];
        const Eigen::Index m = rows - columns;
        const Panel panel(values_.data() + value_start_[s], rows, columns, Eigen::OuterStride<>(rows));
        auto ys = y.segment(first_[s], columns);
        if (m > 0) {
            auto g = gathered_.head(m);
            const int* r = row_index_.data() + row_start_[s] + columns;
            for (Eigen::Index p = 0; p < m; ++p) g[p] = y[r[p]];
            ys.noalias() -= panel.bottomRows(m).transpose() * g;
        }
        panel.topRows(columns).triangularView<Eigen::Lower>().adjoint().solveInPlace(ys);
    }
    x.resize(n_);
    for (Eigen::Index i = 0; i < n_; ++i) x[i] = y[position_[static_cast<size_t>(i)]];
}

}  // namespace contactbody
