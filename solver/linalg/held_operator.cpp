#include "linalg/held_operator.hpp"

#include <algorithm>
#include <stdexcept>

#include "linalg/pattern_lu.hpp"
#include "linalg/supernodal_kernels.hpp"
#include "linalg/trailing_cholesky.hpp"
#include "util/build_features.hpp"

namespace contactbody {

HeldOperator::HeldOperator(const SparseMatrix& K, std::vector<int> contact_dofs, int unknowns_per_node,
                           FactorOptions options)
    : K_(K), dofs_(std::move(contact_dofs)), baseline_kernels_(options.baseline_kernels) {
    K_.makeCompressed();
    lower_ = K_.triangularView<Eigen::Lower>();
    lower_.makeCompressed();
    held_lower_ = lower_;
    const Eigen::Index m = unknowns(), nf = K_.rows();
    std::vector<int> unknown_of(static_cast<size_t>(nf), -1);  // kept: unknown_of_
    for (Eigen::Index j = 0; j < m; ++j) unknown_of[static_cast<size_t>(dof(j))] = static_cast<int>(j);
    positions_.assign(static_cast<size_t>(m), {});
    diagonal_.assign(static_cast<size_t>(m), -1);
    for (Eigen::Index c = 0; c < nf; ++c) {
        for (int k = lower_.outerIndexPtr()[c]; k < lower_.outerIndexPtr()[c + 1]; ++k) {
            const int r = lower_.innerIndexPtr()[k];
            const int jr = unknown_of[static_cast<size_t>(r)], jc = unknown_of[static_cast<size_t>(c)];
            if (jc >= 0) positions_[static_cast<size_t>(jc)].push_back(k);
            if (jr >= 0 && r != c) positions_[static_cast<size_t>(jr)].push_back(k);
            if (jc >= 0 && r == c) diagonal_[static_cast<size_t>(jc)] = k;
        }
    }
    // K's rows at the contact dofs are its columns there (K is symmetric).
    std::vector<Eigen::Triplet<double>> entries;
    stiffness_.resize(m);
    for (Eigen::Index j = 0; j < m; ++j) {
        if (diagonal_[static_cast<size_t>(j)] < 0)
            throw std::logic_error("HeldOperator: a contact dof without a diagonal entry");
        stiffness_[j] = lower_.valuePtr()[diagonal_[static_cast<size_t>(j)]];
        for (SparseMatrix::InnerIterator it(K_, dof(j)); it; ++it)
            entries.emplace_back(static_cast<int>(j), static_cast<int>(it.row()), it.value());
    }
    rows_.resize(m, nf);
    rows_.setFromTriplets(entries.begin(), entries.end());
    factor_ = std::make_unique<TrailingCholesky>(K_, std::vector<int>{}, true,
                                                 options.supernodal ? TrailingCholesky::Kernel::supernodal
                                                                     : TrailingCholesky::Kernel::automatic,
                                                 options);
    held_.assign(static_cast<size_t>(m), 0);
    held_dof_.assign(static_cast<size_t>(nf), 0);
    // For slipping rows: each contact unknown's row entries in K_ (by symmetry, its column's
    // rows' columns), found in each column's sorted rows; a node's tangential and y columns
    // must share their rows (unknowns c n + i and i), so that K_j - sf K_y keeps K's pattern.
    unknown_of_ = std::move(unknown_of);
    row_positions_.assign(static_cast<size_t>(m), {});
    full_diagonal_.assign(static_cast<size_t>(m), -1);
    const int* outer = K_.outerIndexPtr();
    const int* inner = K_.innerIndexPtr();
    for (Eigen::Index j = 0; j < m; ++j) {
        const int c = dof(j);
        for (int k = outer[c]; k < outer[c + 1]; ++k) {
            const int r = inner[k];
            const int* at = std::lower_bound(inner + outer[r], inner + outer[r + 1], c);
            row_positions_[static_cast<size_t>(j)].push_back(static_cast<int>(at - inner));
            if (r == c) full_diagonal_[static_cast<size_t>(j)] = k;
        }
    }
    tangents_ = unknowns_per_node - 1;
    const Eigen::Index n = m / unknowns_per_node;
    slips_allowed_ = tangents_ >= 1;
    for (Eigen::Index j = n; slips_allowed_ && j < m; ++j) {
        const int y = dof(j % n), t = dof(j);
        slips_allowed_ = outer[t + 1] - outer[t] == outer[y + 1] - outer[y] &&
                         std::equal(inner + outer[t], inner + outer[t + 1], inner + outer[y]);
    }
    slip_.assign(static_cast<size_t>(tangents_ * n), 0.0);
}

HeldOperator::~HeldOperator() = default;

void HeldOperator::set_slip_coefficient(double friction) {
    if (friction == slip_coefficient_) return;
    slip_coefficient_ = friction;
    if (lu_held_) factor_held();
}

double HeldOperator::factor_nonzeros() const { return factor_->factor_nonzeros(); }

double HeldOperator::refactorization_in_solves() const {
    return factor_->factor_flops() / (4 * factor_->factor_nonzeros());
}

void HeldOperator::hold(const std::vector<char>& held, const std::vector<double>& slip) {
    const bool slips =
        slip_coefficient() > 0 && std::any_of(slip.begin(), slip.end(), [](double s) { return s != 0; });
    if (held == held_ && (slips ? slip == slip_ : !lu_held_)) return;
    held_ = held;
    if (slips)
        slip_ = slip;
    else
        std::fill(slip_.begin(), slip_.end(), 0.0);
    for (size_t j = 0; j < held.size(); ++j) held_dof_[static_cast<size_t>(dofs_[j])] = held[j];
    factor_held();
}

void HeldOperator::factor_held() {
    ++refactorizations_;
    factor_into_held();
    refactored_work_ += factor_->refactored_share();
}

void HeldOperator::factor_into_held() {
    lu_held_ = std::any_of(slip_.begin(), slip_.end(), [](double s) { return s != 0; });
    if (lu_held_ && factor_->kernel() == TrailingCholesky::Kernel::supernodal) {
        // The slipping rows in our supernodal factor's LU (a 3D body's: docs/decisions.md, "A 3D
        // body's factor holds its slipping nodes"), else in PatternLu.
        slip_values();
        if (factor_->refactor_lu(K_, lu_values_.data())) return;
        slips_allowed_ = false;
        lu_held_ = false;
        std::fill(slip_.begin(), slip_.end(), 0.0);
    }
    if (lu_held_) {
        if (!lu_) {
            std::vector<int> position(static_cast<size_t>(size()));
            for (Eigen::Index u = 0; u < size(); ++u)
                position[static_cast<size_t>(u)] = factor_->position(static_cast<int>(u));
            lu_ = std::make_unique<PatternLu>(K_, position);
        }
        slip_values();
        if (lu_->factor(lu_values_.data())) return;
        // No pivot without pivoting: the slips stay GCR's (SparseContactSolver), on K's Cholesky.
        slips_allowed_ = false;
        lu_held_ = false;
        std::fill(slip_.begin(), slip_.end(), 0.0);
    }
    std::copy(lower_.valuePtr(), lower_.valuePtr() + lower_.nonZeros(), held_lower_.valuePtr());
    for (size_t j = 0; j < held_.size(); ++j) {
        if (!held_[j]) continue;
        for (int k : positions_[j]) held_lower_.valuePtr()[k] = 0;
        held_lower_.valuePtr()[diagonal_[j]] = 1;
    }
    factor_->refactor(held_lower_);
}

// K_H's values with the slipping rows (K_j - sf K_y) and the held rows and columns the
// identity's, in K_'s pattern (both triangles), into lu_values_.
void HeldOperator::slip_values() {
    const double* k = K_.valuePtr();
    lu_values_.assign(k, k + K_.nonZeros());
    const size_t n = held_.size() / static_cast<size_t>(tangents_ + 1);
    for (size_t s = 0; s < slip_.size(); ++s) {  // K_j - sf K_y
        if (slip_[s] == 0) continue;
        const double sf = slip_[s] * slip_coefficient_;
        const std::vector<int>& t = row_positions_[n + s];
        const std::vector<int>& y = row_positions_[s % n];
        for (size_t e = 0; e < t.size(); ++e) lu_values_[static_cast<size_t>(t[e])] -= sf * k[y[e]];
    }
    for (size_t j = 0; j < held_.size(); ++j) {
        if (!held_[j]) continue;
        const int c = dofs_[j];
        std::fill(lu_values_.begin() + K_.outerIndexPtr()[c], lu_values_.begin() + K_.outerIndexPtr()[c + 1],
                  0.0);
        for (int p : row_positions_[j]) lu_values_[static_cast<size_t>(p)] = 0;
        lu_values_[static_cast<size_t>(full_diagonal_[j])] = 1;
    }
}

void HeldOperator::impose(Eigen::VectorXd& b, const Eigen::VectorXd& values) const {
    const size_t n = held_.size() / static_cast<size_t>(tangents_ + 1);
    if (lu_held_)  // a slipping row's right-hand side, from its y row's before that is held
        for (size_t s = 0; s < slip_.size(); ++s)
            if (slip_[s] != 0) b[dofs_[n + s]] -= slip_[s] * slip_coefficient_ * b[dofs_[s % n]];
    for (size_t j = 0; j < held_.size(); ++j) {
        if (!held_[j] || values[static_cast<Eigen::Index>(j)] == 0) continue;
        const double v = values[static_cast<Eigen::Index>(j)];
        for (SparseMatrix::InnerIterator it(K_, dofs_[j]); it; ++it) {
            const size_t r = static_cast<size_t>(it.row());
            if (!held_dof_[r]) {
                b[it.row()] -= it.value() * v;
            } else if (lu_held_) {  // a held y row's share in its node's slipping rows
                const int u = unknown_of_[r];
                if (u < 0 || static_cast<size_t>(u) >= n) continue;
                for (size_t s = static_cast<size_t>(u); s < slip_.size(); s += n)
                    if (slip_[s] != 0) b[dofs_[n + s]] += slip_[s] * slip_coefficient_ * it.value() * v;
            }
        }
    }
    for (size_t j = 0; j < held_.size(); ++j)
        if (held_[j]) b[dofs_[j]] = values[static_cast<Eigen::Index>(j)];
}

void HeldOperator::solve(const Eigen::VectorXd& b, Eigen::VectorXd& x) {
    if (lu_held_ && lu_)
        lu_->solve(b, x);
    else
        factor_->solve(b, x);
}

const SupernodalKernels* HeldOperator::dense_kernels() const {
    if constexpr (solid_bodies_built)
        if (factor_->kernel() == TrailingCholesky::Kernel::supernodal) return &supernodal_kernels(baseline_kernels_);
    return nullptr;
}

}  // namespace contactbody
