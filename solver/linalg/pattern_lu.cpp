#include "linalg/pattern_lu.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace contactbody {

PatternLu::PatternLu(const SparseMatrix& pattern, const std::vector<int>& position) : n_(pattern.cols()) {
    if (!pattern.isCompressed() || pattern.rows() != n_ || static_cast<Eigen::Index>(position.size()) != n_)
        throw std::logic_error("PatternLu: a compressed square pattern and a position per unknown");
    const size_t n = static_cast<size_t>(n_);
    order_.assign(n, 0);
    for (size_t u = 0; u < n; ++u) order_[static_cast<size_t>(position[u])] = static_cast<int>(u);
    // P A P^T by columns, each entry the place of A's value it is.
    const int* outer = pattern.outerIndexPtr();
    const int* inner = pattern.innerIndexPtr();
    column_start_.assign(n + 1, 0);
    for (size_t c = 0; c < n; ++c)
        column_start_[static_cast<size_t>(position[c]) + 1] = outer[c + 1] - outer[c];
    for (size_t j = 0; j < n; ++j) column_start_[j + 1] += column_start_[j];
    column_rows_.resize(static_cast<size_t>(pattern.nonZeros()));
    value_of_.resize(column_rows_.size());
    for (size_t c = 0; c < n; ++c) {
        int place = column_start_[static_cast<size_t>(position[c])];
        for (int k = outer[c]; k < outer[c + 1]; ++k, ++place) {
            column_rows_[static_cast<size_t>(place)] = position[static_cast<size_t>(inner[k])];
            value_of_[static_cast<size_t>(place)] = k;
        }
    }
    // The elimination tree (Liu's, with path compression), then each row's pattern in L as the
    // reach of its entries left of the diagonal up that tree.
    std::vector<int> parent(n, -1), ancestor(n, -1);
    for (size_t j = 0; j < n; ++j) {
        for (int p = column_start_[j]; p < column_start_[j + 1]; ++p) {
            for (int i = column_rows_[static_cast<size_t>(p)]; i != -1 && i < static_cast<int>(j);) {
                const int next = ancestor[static_cast<size_t>(i)];
                ancestor[static_cast<size_t>(i)] = static_cast<int>(j);
                if (next == -1) parent[static_cast<size_t>(i)] = static_cast<int>(j);
                i = next;
            }
        }
    }
    parent_ = parent;
    std::vector<int> mark(n, -1), row_pattern, row_start(n + 1, 0), count(n, 0);
    for (size_t j = 0; j < n; ++j) {
        mark[j] = static_cast<int>(j);
        const size_t first = row_pattern.size();
        for (int p = column_start_[j]; p < column_start_[j + 1]; ++p) {
            for (int k = column_rows_[static_cast<size_t>(p)];
                 k >= 0 && k < static_cast<int>(j) && mark[static_cast<size_t>(k)] != static_cast<int>(j);
                 k = parent[static_cast<size_t>(k)]) {
                mark[static_cast<size_t>(k)] = static_cast<int>(j);
                row_pattern.push_back(k);
                ++count[static_cast<size_t>(k)];
            }
        }
        std::sort(row_pattern.begin() + static_cast<std::ptrdiff_t>(first), row_pattern.end());
        row_start[j + 1] = static_cast<int>(row_pattern.size());
    }
    start_.assign(n + 1, 0);
    for (size_t k = 0; k < n; ++k) start_[k + 1] = start_[k] + count[k];
    rows_.resize(row_pattern.size());
    across_.resize(row_pattern.size());
    across_start_ = row_start;
    std::vector<int> next(start_.begin(), start_.end() - 1);
    for (size_t j = 0; j < n; ++j) {  // rows ascending in each column
        for (int q = row_start[j]; q < row_start[j + 1]; ++q) {
            const int place = next[static_cast<size_t>(row_pattern[static_cast<size_t>(q)])]++;
            rows_[static_cast<size_t>(place)] = static_cast<int>(j);
            across_[static_cast<size_t>(q)] = place;
        }
    }
    column_of_.resize(rows_.size());
    for (size_t k = 0; k < n; ++k)
        for (int p = start_[k]; p < start_[k + 1]; ++p)
            column_of_[static_cast<size_t>(p)] = static_cast<int>(k);
    // Groups of up to four columns of a chain (column k's pattern k + 1 and then column
    // k + 1's), from the first; group_[k]: the size of the group that starts at k, or ends
    // there (solve: forward from a group's first column, backward from its last).
    group_.assign(n, 1);
    const auto chained = [&](size_t k) {
        return k + 1 < n && start_[k + 1] > start_[k] &&
               rows_[static_cast<size_t>(start_[k])] == static_cast<int>(k + 1) &&
               start_[k + 1] - start_[k] == start_[k + 2] - start_[k + 1] + 1;
    };
    for (size_t k = 0; k < n;) {
        char size = 1;
        while (size < 4 && chained(k + static_cast<size_t>(size) - 1)) ++size;
        group_[k] = group_[k + static_cast<size_t>(size) - 1] = size;
        k += static_cast<size_t>(size);
    }
    lower_.assign(rows_.size(), 0.0);
    upper_.assign(rows_.size(), 0.0);
    diagonal_.assign(n, 0.0);
    factored_.assign(column_rows_.size(), 0.0);
    stale_.assign(n, 1);
    work_.setZero(n_);
}

// Left-looking, a column at a time: column j of L^-1 (P A P^T) by a sparse triangular solve
// over the columns k < j that row j of L reaches (ascending), then U's column and L's. Only
// the stale columns: where the held set changed at the contact zone's ends, 1,000-2,400 of the
// 45,222 on the pad at 3,170 contact nodes (the separators above them carry a quarter to a
// half of the flops; docs/decisions.md).
bool PatternLu::factor(const double* values) {
    for (size_t j = 0; j < stale_.size(); ++j) {
        bool changed = !factored_all_;
        for (int p = column_start_[j]; p < column_start_[j + 1]; ++p) {
            const double a = values[value_of_[static_cast<size_t>(p)]];
            changed = changed || a != factored_[static_cast<size_t>(p)];
            factored_[static_cast<size_t>(p)] = a;
        }
        stale_[j] = stale_[j] || changed;
        if (stale_[j] && parent_[j] >= 0) stale_[static_cast<size_t>(parent_[j])] = 1;
    }
    factored_all_ = false;
    columns_factored_ = 0;
    double* w = work_.data();
    for (Eigen::Index jj = 0; jj < n_; ++jj) {
        const size_t j = static_cast<size_t>(jj);
        if (!stale_[j]) continue;
        stale_[j] = 0;
        ++columns_factored_;
        double largest = 0;
        for (int p = column_start_[j]; p < column_start_[j + 1]; ++p) {
            const double a = values[value_of_[static_cast<size_t>(p)]];
            w[column_rows_[static_cast<size_t>(p)]] = a;
            largest = std::max(largest, std::abs(a));
        }
        for (int q = across_start_[j]; q < across_start_[j + 1]; ++q) {
            const int place = across_[static_cast<size_t>(q)];
            const int k = column_of_[static_cast<size_t>(place)];
            const double ukj = w[k];
            w[k] = 0;
            upper_[static_cast<size_t>(place)] = ukj;
            if (ukj == 0) continue;
            for (int p = start_[static_cast<size_t>(k)]; p < start_[static_cast<size_t>(k) + 1]; ++p)
                w[rows_[static_cast<size_t>(p)]] -= lower_[static_cast<size_t>(p)] * ukj;
        }
        const double d = w[j];
        w[j] = 0;
        if (!(std::abs(d) > 1e-12 * largest)) {
            work_.setZero();
            std::fill(stale_.begin(), stale_.end(), 1);
            return false;
        }
        diagonal_[j] = d;
        for (int p = start_[j]; p < start_[j + 1]; ++p) {
            double& x = w[rows_[static_cast<size_t>(p)]];
            lower_[static_cast<size_t>(p)] = x / d;
            x = 0;
        }
    }
    factored_all_ = true;
    return true;
}

namespace {
// Forward over the group of G columns from k: within the group, then the rows all its columns
// share (the last column's), read once for the G columns.
template <int G>
void forward_group(const int* start, const int* rows, const double* lower, double* y, Eigen::Index k) {
    double yk[G];
    int place[G];
    for (int i = 0; i < G; ++i) {
        place[i] = start[k + i];
        yk[i] = y[k + i];
        for (int j = 0; j < i; ++j) yk[i] -= lower[place[j]++] * yk[j];
        y[k + i] = yk[i];
    }
    bool zero = true;  // a direction's right-hand side: zero but on its path up the tree
    for (int i = 0; i < G; ++i) zero = zero && yk[i] == 0;
    if (zero) return;
    const int length = start[k + G] - start[k + G - 1];
    for (int t = 0; t < length; ++t) {
        double sum = 0;
        for (int i = 0; i < G; ++i) sum += lower[place[i] + t] * yk[i];
        y[rows[place[G - 1] + t]] -= sum;
    }
}

// Backward over the group of G columns that ends at k (U by its rows, L's columns).
template <int G>
void backward_group(const int* start, const int* rows, const double* upper, const double* diagonal, double* y,
                    Eigen::Index k) {
    const Eigen::Index first = k - G + 1;
    double s[G];
    int place[G];
    for (int i = 0; i < G; ++i) {
        place[i] = start[first + i] + (G - 1 - i);
        s[i] = y[first + i];
    }
    const int length = start[k + 1] - start[k];
    for (int t = 0; t < length; ++t) {
        const double yr = y[rows[place[G - 1] + t]];
        for (int i = 0; i < G; ++i) s[i] -= upper[place[i] + t] * yr;
    }
    for (int i = G - 1; i >= 0; --i) {
        for (int j = i + 1; j < G; ++j) s[i] -= upper[start[first + i] + (j - i - 1)] * y[first + j];
        y[first + i] = s[i] / diagonal[first + i];
    }
}
}  // namespace

// A group's columns go together (as CHOLMOD's simplicial solves take chains of up to four):
// y is read and written once for them, and the shared rows' indices read once
// (docs/decisions.md, "The LU's solve by groups of up to four columns").
void PatternLu::solve(const Eigen::VectorXd& b, Eigen::VectorXd& x) {
    double* y = work_.data();
    const int* start = start_.data();
    const int* rows = rows_.data();
    const double* lower = lower_.data();
    const double* upper = upper_.data();
    const double* diagonal = diagonal_.data();
    const int* order = order_.data();
    const char* group = group_.data();
    for (Eigen::Index k = 0; k < n_; ++k) y[k] = b[order[k]];
    for (Eigen::Index k = 0; k < n_; k += group[k]) {  // L (unit diagonal)
        switch (group[k]) {
            case 4:
                forward_group<4>(start, rows, lower, y, k);
                break;
            case 3:
                forward_group<3>(start, rows, lower, y, k);
                break;
            case 2:
                forward_group<2>(start, rows, lower, y, k);
                break;
            default:
                forward_group<1>(start, rows, lower, y, k);
        }
    }
    for (Eigen::Index k = n_ - 1; k >= 0; k -= group[k]) {  // U
        switch (group[k]) {
            case 4:
                backward_group<4>(start, rows, upper, diagonal, y, k);
                break;
            case 3:
                backward_group<3>(start, rows, upper, diagonal, y, k);
                break;
            case 2:
                backward_group<2>(start, rows, upper, diagonal, y, k);
                break;
            default:
                backward_group<1>(start, rows, upper, diagonal, y, k);
        }
    }
    x.resize(n_);
    for (Eigen::Index k = 0; k < n_; ++k) {
        x[order[k]] = y[k];
        y[k] = 0;
    }
}

}  // namespace contactbody
