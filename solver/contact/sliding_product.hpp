// Products M lambda with a matrix of the contact unknowns' columns, M = [M_N, M_T] (n normal,
// n tangential), at multipliers where most nodes slide: there lambda_T = -s lambda_N with
// s = +-F, exactly where the contact solver projects a slipping node onto its Coulomb bound
// (ContactSolverOptions::project_slip). For any s,
//   M lambda = M_C lambda_N + M_T (lambda_T + s lambda_N),   M_C = M_N - M_T diag(s),
// and node i's correction lambda_T + s lambda_N is zero where it slides: the product reads
// M_C, half of M's columns. The contact solver makes its products with W so (the reduced
// body's contact forces do not: docs/decisions.md, "Tried and dropped: the forces through the
// same compaction as W's products").
#pragma once

#include <Eigen/Dense>

namespace contactbody {

class SlidingProduct {
public:
    // Forgets M_C: the next product forms it from M (call when M changes).
    void reset() { s_.resize(0); }
    // y = M lambda for friction coefficients F (n): s_i = +-F_i where lambda_T = -+F_i lambda_N
    // exactly, else 0, a function of lambda alone, so that y's last bits do not depend on
    // earlier products (a restored state repeats them); a node with lambda_N = 0 adds nothing
    // through M_C and keeps its s. A column of M_C is formed again when its s changes. False,
    // y untouched, where more than n/4 corrections are nonzero (a shortened Newton step):
    // M lambda then costs less.
    bool apply(const Eigen::MatrixXd& M, const Eigen::VectorXd& F,
               const Eigen::Ref<const Eigen::VectorXd>& lambda, Eigen::Ref<Eigen::VectorXd> y);

private:
    Eigen::MatrixXd compact_;  // M_C
    Eigen::VectorXd s_, next_s_;
};

}  // namespace contactbody
