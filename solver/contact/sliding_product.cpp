#include "contact/sliding_product.hpp"

namespace contactbody {

bool SlidingProduct::apply(const Eigen::MatrixXd& M, const Eigen::VectorXd& F,
                           const Eigen::Ref<const Eigen::VectorXd>& lambda, Eigen::Ref<Eigen::VectorXd> y) {
    const Eigen::Index n = F.size();
    if (s_.size() != n) {  // sized when M changes only: the time loop allocates nothing
        compact_ = M.leftCols(n);
        s_.setZero(n);
        next_s_.resize(n);
    }
    Eigen::Index corrections = 0;
    for (Eigen::Index i = 0; i < n; ++i) {
        const double lN = lambda[i], lT = lambda[n + i];
        next_s_[i] = lN == 0 ? s_[i] : lT == -F[i] * lN ? F[i] : lT == F[i] * lN ? -F[i] : 0.0;
        corrections += lT + next_s_[i] * lN != 0;
    }
    if (4 * corrections > n) return false;
    for (Eigen::Index i = 0; i < n; ++i) {
        if (next_s_[i] == s_[i]) continue;
        s_[i] = next_s_[i];
        if (s_[i] == 0)
            compact_.col(i) = M.col(i);
        else
            compact_.col(i).noalias() = M.col(i) - s_[i] * M.col(n + i);
    }
    y.noalias() = compact_ * lambda.head(n);
    for (Eigen::Index i = 0; i < n; ++i) {
        const double c = lambda[n + i] + s_[i] * lambda[i];
        if (c != 0) y.noalias() += c * M.col(n + i);
    }
    return true;
}

}  // namespace contactbody
