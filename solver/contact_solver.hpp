// Frictional contact problem condensed to the contact unknowns of one substep.
//
// With n nodes, multipliers lambda = (lambda_N[0..n), lambda_T[0..n)) and the affine map
//   u_hat = a + W lambda   (u_hat = (u_N, u_T) at the nodes, W the Delassus operator B K^-1 B^T),
// find lambda such that at every node i
//   lambda_N <= 0,  u_N - gap_limit <= 0,  lambda_N (u_N - gap_limit) = 0,
//   lambda_T in F lambda_N Sgn(u_T - slip_origin)          (Coulomb on the slip).
// Without friction (F == 0) the tangential part is absent: lambda and u_hat have n entries.
#pragma once

#include <Eigen/Dense>
#include <stdexcept>
#include <string>

namespace contactbody {

enum class NodeStatus : unsigned char { open, stick, slip };

struct ContactProblem {
    Eigen::MatrixXd W;           // 2n x 2n (or n x n without friction)
    Eigen::VectorXd a;           // u_hat at lambda = 0
    Eigen::VectorXd gap_limit;   // n: u_N must not exceed it
    Eigen::VectorXd slip_origin; // n: slip is u_T - slip_origin (unused without friction)
    double friction = 0;         // F
    bool has_friction() const { return W.rows() == 2 * gap_limit.size(); }
};

struct ContactSolverOptions {
    double tolerance = 1e-10;  // on the Alart-Curnier residual, relative to max |lambda|
    int max_iterations = 100;
};

struct ContactSolveInfo {
    int iterations = 0;
    double residual = 0;  // relative, as compared with the tolerance
};

class ContactSolveError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

class ContactSolver {
public:
    // Solves in place from the warm start in lambda; throws ContactSolveError on failure.
    ContactSolveInfo solve(const ContactProblem& problem, const ContactSolverOptions& options,
                           Eigen::VectorXd& lambda);
    // Node states of the last solution (open / sticking / slipping).
    const Eigen::Matrix<NodeStatus, Eigen::Dynamic, 1>& status() const { return status_; }

private:
    double residual(const ContactProblem& p, const Eigen::VectorXd& lambda,
                    Eigen::VectorXd& phi);
    void jacobian(const ContactProblem& p, const Eigen::VectorXd& lambda);

    // Workspace kept between calls so that steady stepping does not reallocate.
    Eigen::VectorXd u_hat_, r_, phi_, trial_phi_, step_, trial_;
    Eigen::MatrixXd jacobian_;
    Eigen::PartialPivLU<Eigen::MatrixXd> lu_;
    Eigen::Matrix<NodeStatus, Eigen::Dynamic, 1> status_;
};

}  // namespace contactbody
