#include "linalg/trailing_cholesky.hpp"

#include "linalg/supernodal_cholesky.hpp"
#include "linalg/supernodal_kernels.hpp"
#include "util/build_features.hpp"

#if CONTACTBODY_SOLID_BODIES
#include <Eigen/SparseLU>
#endif

#include <cholmod.h>

#include <algorithm>
#include <stdexcept>
#include <string>

namespace contactbody {

#if CONTACTBODY_SOLID_BODIES
// The supernodal LU of the prepermuted matrix (both triangles), and for each of its values
// the position of K's lower-triangle value it is.
struct TrailingCholesky::Lu {
    Eigen::SparseLU<SparseMatrix, Eigen::NaturalOrdering<int>> lu;
    SparseMatrix full;
    std::vector<int> value_map;
    Eigen::VectorXd rhs;

    // entries: triu(P K P^T), each value the position of K's lower-triangle value it is.
    void build(const std::vector<Eigen::Triplet<double>>& entries, Eigen::Index n,
               const double* lower_values) {
        // Both triangles in natural order, each value mapped to K's lower one.
        std::vector<Eigen::Triplet<double>> both;
        both.reserve(2 * entries.size());
        for (const auto& e : entries) {
            both.push_back(e);
            if (e.row() != e.col()) both.emplace_back(e.col(), e.row(), e.value());
        }
        full.resize(n, n);
        full.setFromTriplets(both.begin(), both.end());
        full.makeCompressed();
        value_map.resize(static_cast<size_t>(full.nonZeros()));
        for (Eigen::Index k = 0; k < full.nonZeros(); ++k)
            value_map[static_cast<size_t>(k)] = static_cast<int>(full.valuePtr()[k]);
        lu.setPivotThreshold(0.0);  // diagonal pivots: K is positive definite
        lu.analyzePattern(full);
        factorize(lower_values);
        rhs.resize(n);
    }
    double nonzeros() const { return static_cast<double>(lu.nnzL()); }
    void solve_in_place() { rhs = lu.solve(rhs); }

    void factorize(const double* lower_values) {
        for (size_t k = 0; k < value_map.size(); ++k) full.valuePtr()[k] = lower_values[value_map[k]];
        lu.factorize(full);
        if (lu.info() != Eigen::Success)
            throw std::runtime_error(
                "the held stiffness is singular (supernodal LU: " + lu.lastErrorMessage() + ")");
    }
};
#else
// Without solid bodies (build_features.hpp) there is no supernodal LU: its Eigen::SparseLU
// reports through an ostringstream, which would link the C++ library's locale machinery.
struct TrailingCholesky::Lu {
    Eigen::VectorXd rhs;
    [[noreturn]] static void missing() {
        throw std::logic_error("this build has no supernodal LU (CONTACTBODY_SOLID_BODIES=0)");
    }
    void build(const std::vector<Eigen::Triplet<double>>&, Eigen::Index, const double*) { missing(); }
    void factorize(const double*) { missing(); }
    double nonzeros() const { return 0; }
    void solve_in_place() { missing(); }
};
#endif

struct TrailingCholesky::Cholmod {
    cholmod_common common;
    cholmod_factor* factor = nullptr;
    // Solve buffers, owned by CHOLMOD so that solve2 reuses them instead of allocating.
    cholmod_dense *permuted = nullptr, *y = nullptr, *x = nullptr;
    cholmod_dense *work_y = nullptr, *work_e = nullptr;

    Cholmod() {
        cholmod_start(&common);
        common.print = 0;  // failures reach the caller as exceptions, never as text on stderr
    }
    ~Cholmod() {
        for (cholmod_dense** d : {&permuted, &y, &x, &work_y, &work_e}) cholmod_free_dense(d, &common);
        cholmod_free_factor(&factor, &common);
        cholmod_finish(&common);
    }
    // A simplicial solve2 asks for Y as 4 x n, then leaves it reshaped to 1 x n, so the next
    // call would free and reallocate it: restore the shape first (same storage, nzmax = 4 n).
    void reshape_workspace() {
        if (work_y && work_y->nzmax >= 4 * factor->n) {
            work_y->nrow = work_y->d = 4;
            work_y->ncol = factor->n;
        }
    }
    void check(const char* what) const {
        if (common.status < CHOLMOD_OK)
            throw std::runtime_error(std::string("CHOLMOD ") + what + " failed (status " +
                                     std::to_string(common.status) + ")");
    }
};

namespace {

// A read-only CHOLMOD view of the lower triangle of a compressed Eigen matrix.
cholmod_sparse lower_view(const SparseMatrix& lower) {
    cholmod_sparse a{};
    a.nrow = a.ncol = static_cast<size_t>(lower.rows());
    a.nzmax = static_cast<size_t>(lower.nonZeros());
    a.p = const_cast<int*>(lower.outerIndexPtr());
    a.i = const_cast<int*>(lower.innerIndexPtr());
    a.x = const_cast<double*>(lower.valuePtr());
    a.stype = -1;
    a.itype = CHOLMOD_INT;
    a.xtype = CHOLMOD_REAL;
    a.dtype = CHOLMOD_DOUBLE;
    a.sorted = 1;
    a.packed = 1;
    return a;
}

// Symbolic analysis for a given permutation, without the postorder that could move the
// trailing unknowns away from the end.
cholmod_factor* analyze_given(cholmod_sparse& a, std::vector<int>& perm, cholmod_common& c) {
    c.nmethods = 1;
    c.method[0].ordering = CHOLMOD_GIVEN;
    c.postorder = 0;
    return cholmod_analyze_p(&a, perm.data(), nullptr, 0, &c);
}

}  // namespace

TrailingCholesky::TrailingCholesky(const SparseMatrix& K, const std::vector<int>& trailing, bool refactorable,
                                   Kernel kernel, FactorOptions options)
    : c_(std::make_unique<Cholmod>()), n_(K.rows()), m_(static_cast<Eigen::Index>(trailing.size())) {
    cholmod_common& c = c_->common;
    // Simplicial L L^T: with one right-hand side its solves are faster than the supernodal
    // ones, and the factor is computed once (docs/decisions.md, "One sparse solve per substep").
    c.final_ll = 1;
    c.supernodal = CHOLMOD_SIMPLICIAL;
    SparseMatrix lower = K.triangularView<Eigen::Lower>();
    lower.makeCompressed();
    cholmod_sparse a = lower_view(lower);
    const size_t n = static_cast<size_t>(n_);

    // Two candidate orderings with the trailing set last; keep the one with less fill.
    // 1) CAMD constrained to order the trailing set after all others.
    std::vector<int> member(n, 0);
    for (int t : trailing) member[static_cast<size_t>(t)] = 1;
    std::vector<int> camd(n);
    if (!cholmod_camd(&a, nullptr, 0, member.data(), camd.data(), &c))
        throw std::runtime_error("CHOLMOD CAMD ordering failed (status " + std::to_string(c.status) + ")");
    // 2) METIS nested dissection with the trailing set moved to the end (stable order).
    std::vector<int> metis(n);
    bool have_metis = n > 64 && cholmod_metis(&a, nullptr, 0, 1, metis.data(), &c);
    if (have_metis)
        std::stable_partition(metis.begin(), metis.end(),
                              [&](int k) { return member[static_cast<size_t>(k)] == 0; });
    c.status = CHOLMOD_OK;

    std::vector<int>* best = &camd;
    if (have_metis) {
        cholmod_factor* probe = analyze_given(a, camd, c);
        c_->check("analysis");
        const double camd_fill = c.lnz;
        cholmod_free_factor(&probe, &c);
        probe = analyze_given(a, metis, c);
        c_->check("analysis");
        if (c.lnz < camd_fill) best = &metis;
        cholmod_free_factor(&probe, &c);
    }
    if (refactorable) {
        if (m_ != 0) throw std::logic_error("TrailingCholesky: a refactorable factor has no trailing block");
        // The factor may be refactored (refactor()). CHOLMOD permutes and
        // transposes a lower-triangular matrix into a new one at every factorization, so it
        // is given triu(P K P^T) itself, in natural order: refactoring then allocates nothing.
        perm_ = *best;
        std::vector<int> inverse(n);
        for (size_t k = 0; k < n; ++k) inverse[static_cast<size_t>(perm_[k])] = static_cast<int>(k);
        std::vector<Eigen::Triplet<double>> entries;
        entries.reserve(static_cast<size_t>(lower.nonZeros()));
        for (Eigen::Index col = 0; col < lower.outerSize(); ++col)
            for (int k = lower.outerIndexPtr()[col]; k < lower.outerIndexPtr()[col + 1]; ++k) {
                const int pr = inverse[static_cast<size_t>(lower.innerIndexPtr()[k])];
                const int pc = inverse[static_cast<size_t>(col)];
                entries.emplace_back(std::min(pr, pc), std::max(pr, pc), static_cast<double>(k));
            }
        permuted_upper_.resize(n_, n_);
        permuted_upper_.setFromTriplets(entries.begin(), entries.end());
        permuted_upper_.makeCompressed();
        value_map_.resize(static_cast<size_t>(permuted_upper_.nonZeros()));
        for (Eigen::Index k = 0; k < permuted_upper_.nonZeros(); ++k) {
            value_map_[static_cast<size_t>(k)] = static_cast<int>(permuted_upper_.valuePtr()[k]);
            permuted_upper_.valuePtr()[k] = lower.valuePtr()[value_map_[static_cast<size_t>(k)]];
        }
        cholmod_sparse upper = lower_view(permuted_upper_);
        upper.stype = 1;
        c.nmethods = 1;
        c.method[0].ordering = CHOLMOD_NATURAL;
        c.postorder = 0;
        c_->factor = cholmod_analyze(&upper, &c);
        c_->check("analysis");
        factor_flops_ = c.fl;
        const Kernel chosen = kernel != Kernel::automatic                               ? kernel
                              : solid_bodies_built && supernodal_pays(factor_flops_, c.lnz) ? Kernel::supernodal
                                                                                            : Kernel::simplicial;
        if (chosen == Kernel::supernodal) {
            // (only in builds with solid bodies: the 2D FMU's binaries leave its code out)
            if constexpr (!solid_bodies_built)
                throw std::logic_error("this build has no supernodal Cholesky");
            inverse_perm_.assign(n, 0);
            for (size_t k = 0; k < n; ++k) inverse_perm_[static_cast<size_t>(perm_[k])] = static_cast<int>(k);
            if constexpr (solid_bodies_built) {
                supernodal_ = std::make_unique<SupernodalCholesky>(lower, inverse_perm_,
                                                                   options.baseline_kernels, options.threads);
                factor_supernodal(lower, "4/dt^2 M + A");
            }
            return;
        }
        if (chosen == Kernel::supernodal_lu) {
            lu_ = std::make_unique<Lu>();
            lu_->build(entries, n_, lower.valuePtr());
            inverse_perm_.assign(n, 0);
            for (size_t k = 0; k < n; ++k) inverse_perm_[static_cast<size_t>(perm_[k])] = static_cast<int>(k);
            return;
        }
        cholmod_factorize(&upper, c_->factor, &c);
    } else {
        c_->factor = analyze_given(a, *best, c);
        c_->check("analysis");
        factor_flops_ = c.fl;
        cholmod_factorize(&a, c_->factor, &c);
        const int* given = static_cast<const int*>(c_->factor->Perm);
        perm_.assign(given, given + n);
    }
    if (c.status == CHOLMOD_NOT_POSDEF)
        throw std::runtime_error("4/dt^2 M + A is not positive definite (Cholesky failed at column " +
                                 std::to_string(c_->factor->minor) + ")");
    c_->check("factorization");
    cholmod_factor& L = *c_->factor;
    if (!L.is_ll) throw std::runtime_error("CHOLMOD returned an LDL' factor");

    inverse_perm_.assign(n, 0);
    for (size_t k = 0; k < n; ++k) inverse_perm_[static_cast<size_t>(perm_[k])] = static_cast<int>(k);
    for (int t : trailing)
        if (position(t) < n_ - m_) throw std::logic_error("trailing unknowns not ordered last");

    // Copy the trailing block of L: columns (and so rows) >= n - m.
    const Eigen::Index first = n_ - m_;
    trailing_block_.setZero(m_, m_);
    if (L.is_super) {
        const int* super = static_cast<const int*>(L.super);
        const int* pi = static_cast<const int*>(L.pi);
        const int* px = static_cast<const int*>(L.px);
        const int* rows = static_cast<const int*>(L.s);
        const double* x = static_cast<const double*>(L.x);
        for (size_t s = 0; s < L.nsuper; ++s) {
            const int nrows = pi[s + 1] - pi[s];
            for (int col = std::max<int>(super[s], static_cast<int>(first)); col < super[s + 1]; ++col) {
                const double* values = x + px[s] + static_cast<size_t>(col - super[s]) * nrows;
                for (int r = 0; r < nrows; ++r) {
                    const int row = rows[pi[s] + r];
                    if (row >= col) trailing_block_(row - first, col - first) = values[r];
                }
            }
        }
    } else {
        const int* p = static_cast<const int*>(L.p);
        const int* nz = static_cast<const int*>(L.nz);
        const int* rows = static_cast<const int*>(L.i);
        const double* x = static_cast<const double*>(L.x);
        for (Eigen::Index col = first; col < n_; ++col)
            for (int k = p[col]; k < p[col] + nz[col]; ++k)
                trailing_block_(rows[k] - first, col - first) = x[k];
    }

    c_->permuted = cholmod_allocate_dense(n, 1, n, CHOLMOD_REAL, &c);
    c_->check("allocation");
}

TrailingCholesky::~TrailingCholesky() = default;

void TrailingCholesky::refactor(const SparseMatrix& K2) {
    if (value_map_.empty()) throw std::logic_error("TrailingCholesky::refactor: not refactorable");
    if constexpr (solid_bodies_built) {
        if (supernodal_) {
            factor_supernodal(K2, "the held stiffness");
            return;
        }
    }
    if (lu_) {
        lu_->factorize(K2.valuePtr());
        return;
    }
    cholmod_common& c = c_->common;
    // K2 holds its lower triangle in K's pattern: its values, permuted as in the factor.
    for (size_t k = 0; k < value_map_.size(); ++k)
        permuted_upper_.valuePtr()[k] = K2.valuePtr()[value_map_[k]];
    cholmod_sparse upper = lower_view(permuted_upper_);
    upper.stype = 1;
    cholmod_factorize(&upper, c_->factor, &c);
    if (c.status == CHOLMOD_NOT_POSDEF)
        throw std::runtime_error("the held stiffness is not positive definite (Cholesky failed at column " +
                                 std::to_string(c_->factor->minor) + ")");
    c_->check("refactorization");
}

const char* TrailingCholesky::supernodal_kernel_set(bool baseline_kernels) {
    if constexpr (solid_bodies_built) return supernodal_kernels(baseline_kernels).name;
    return nullptr;
}

void TrailingCholesky::factor_supernodal(const SparseMatrix& lower, const char* what) {
    if constexpr (solid_bodies_built) {
        if (!supernodal_->factor(lower))
            throw std::runtime_error(std::string(what) +
                                     " is not positive definite (Cholesky failed at column " +
                                     std::to_string(supernodal_->failed_column()) + ")");
    }
}

double TrailingCholesky::refactored_share() const {
    return supernodal_ ? supernodal_->refactored_share() : 1.0;
}

bool TrailingCholesky::refactor_lu(const SparseMatrix& pattern, const double* values) {
    if constexpr (solid_bodies_built)
        if (supernodal_) return supernodal_->factor_lu(pattern, values);
    return false;
}

double TrailingCholesky::factor_nonzeros() const {
    if constexpr (solid_bodies_built)
        if (supernodal_) return supernodal_->factor_nonzeros();
    if (lu_) return lu_->nonzeros();
    const cholmod_factor& L = *c_->factor;
    return static_cast<double>(L.is_super ? L.xsize : static_cast<size_t>(static_cast<const int*>(L.p)[L.n]));
}

void TrailingCholesky::solve(const Eigen::VectorXd& b, Eigen::VectorXd& x) {
    if constexpr (solid_bodies_built) {
        if (supernodal_) {
            supernodal_->solve(b, x);
            return;
        }
    }
    if (!lu_) {
        forward(b);
        backward(x);
        return;
    }
    for (Eigen::Index k = 0; k < n_; ++k) lu_->rhs[k] = b[perm_[static_cast<size_t>(k)]];
    lu_->solve_in_place();
    x.resize(n_);
    for (Eigen::Index k = 0; k < n_; ++k) x[perm_[static_cast<size_t>(k)]] = lu_->rhs[k];
}

Eigen::Map<Eigen::VectorXd> TrailingCholesky::forward(const Eigen::VectorXd& b) {
    if (lu_ || supernodal_)
        throw std::logic_error("TrailingCholesky::forward: a supernodal factor has no separate L solve");
    Cholmod& c = *c_;
    double* permuted = static_cast<double*>(c.permuted->x);
    for (Eigen::Index k = 0; k < n_; ++k) permuted[k] = b[perm_[static_cast<size_t>(k)]];
    c.reshape_workspace();
    if (!cholmod_solve2(CHOLMOD_L, c.factor, c.permuted, nullptr, &c.y, nullptr, &c.work_y, &c.work_e,
                        &c.common))
        throw std::runtime_error("CHOLMOD forward solve failed (status " + std::to_string(c.common.status) +
                                 ")");
    return Eigen::Map<Eigen::VectorXd>(static_cast<double*>(c.y->x), n_);
}

void TrailingCholesky::backward(Eigen::VectorXd& x) {
    Cholmod& c = *c_;
    c.reshape_workspace();
    if (!cholmod_solve2(CHOLMOD_Lt, c.factor, c.y, nullptr, &c.x, nullptr, &c.work_y, &c.work_e, &c.common))
        throw std::runtime_error("CHOLMOD backward solve failed (status " + std::to_string(c.common.status) +
                                 ")");
    const double* result = static_cast<const double*>(c.x->x);
    x.resize(n_);
    for (Eigen::Index k = 0; k < n_; ++k) x[perm_[static_cast<size_t>(k)]] = result[k];
}

}  // namespace contactbody
