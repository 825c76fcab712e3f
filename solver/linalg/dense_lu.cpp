#include "linalg/dense_lu.hpp"

namespace contactbody {

bool LeadingLu::factor(Eigen::Index k) {
    k_ = 0;
    if (k == 0) return true;
    int transpositions = 0;
    if (Eigen::internal::partial_lu_impl<double, Eigen::ColMajor, int>::blocked_lu(
            k, k, buffer_.data(), buffer_.rows(), pivots_.data(), transpositions) >= 0)
        return false;
    k_ = k;
    return true;
}

void RowColumnUpdate::reserve(Eigen::Index m, Eigen::Index max_changed) {
    rows_.resize(max_changed, m);
    z_.resize(m, 2 * max_changed);
    capacitance_.reserve(2 * max_changed);
    t_.resize(2 * max_changed);
    changed_.reserve(static_cast<size_t>(m));
}

}  // namespace contactbody
