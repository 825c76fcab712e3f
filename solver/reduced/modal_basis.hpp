// The basis of the reduced body (docs/decisions.md, "The reduced body"): the lowest modes of
// the free dofs, the residual attachment modes of the contact dofs, and the clamp's static
// lift. Built once from a Discretization; nothing here depends on the substep size.
#pragma once

#include <Eigen/Dense>
#include <functional>

#include "assembly/discretization.hpp"

namespace contactbody {

struct ModalBasis {
    // m modes of A phi = omega^2 M phi on the free dofs, ascending: modes^T M modes = I,
    // modes^T A modes = diag(omega2). M is the variant's: M_r's massless contact normal dofs
    // take part in each mode statically.
    Eigen::VectorXd omega2;
    Eigen::MatrixXd modes;  // n_f x m
    // Psi' = (A^-1 - modes omega2^-1 modes^T) B^T V g^-1/2 for the contact unknowns (N, T),
    // where G = B (A^-1 - ...) B^T = V g V^T has rank: residual^T A residual = I,
    // modes^T A residual = 0, modes^T M residual = 0. Taken massless in the reduced body;
    // with every finite mode kept only the massless contact dofs' columns remain, and
    // residual^T M residual = 0 there.
    Eigen::MatrixXd residual;  // n_f x k
    // The tangential-mass edge (hold_tangential): the contact x (and a 3D body's z) dofs kept
    // as coordinates of their own, X (tangential_contact_dofs' order). The modes and the residual are then those of the body with X held (zero
    // on X's rows; the residual of the contact normal dofs only), and these are Craig-Bampton's
    // constraint modes: identity on X's rows, -A_II^-1 A_IX on the rest (I). They carry the
    // mass of X and of the interior they drag along. n_f x n_X; n_f x 0 for the massless edge.
    Eigen::MatrixXd constraint;
    // -A_ff^-1 A_fc e: the free dofs' static response to a unit top displacement (displacement
    // control: every clamped y dof moves by 1, the x ones stay), X free in either edge.
    Eigen::VectorXd lift;
    // What it cost: wall seconds, and the eigensolver's restarts and operator applications
    // (0 for the dense path).
    double setup_seconds = 0;
    int eigensolver_iterations = 0, operator_applications = 0;
    bool dense = false;  // true when the modes came from a dense solve (small bodies)
};

// The modes of the lowest `modes` frequencies (at most the number of finite ones: the free
// dofs less the massless ones). Bodies of at most dense_limit free dofs are solved densely,
// others with Spectra's Lanczos on L^-1 P M P^T L^-T (P A P^T = L L^T, CHOLMOD), whose
// largest eigenvalues are 1 / omega^2. Throws std::invalid_argument for a count out of range
// or force control (A_ff is then singular: the plate and body translate freely), and
// std::runtime_error naming the cause when the eigensolver does not converge.
// hold_tangential builds the tangential-mass edge's basis (constraint above).
ModalBasis build_modal_basis(const Discretization& d, int modes, bool hold_tangential = false,
                             int dense_limit = 400);

// The lowest `modes` modes of A x = omega^2 M x (A positive definite, M semi-definite),
// ascending, mass-normalized, and A^-1 for the residual and static shapes that follow: dense
// up to dense_limit dofs, else Lanczos on the CHOLMOD factor (as build_modal_basis).
// Above these the eigensolver takes minutes (lowest_modes refuses): the most modes Lanczos is
// asked for, and the largest body solved densely for more than a quarter of its modes.
constexpr int max_lanczos_modes = 500;
constexpr Eigen::Index max_dense_modes_dofs = 2000;
struct LowestModes {
    Eigen::VectorXd omega2;
    Eigen::MatrixXd modes;
    std::function<Eigen::MatrixXd(const Eigen::MatrixXd&)> solve;  // A^-1 B for dense B
    bool dense = false;
    int iterations = 0, applications = 0;
};
LowestModes lowest_modes(const SparseMatrix& A, const SparseMatrix& M, int modes, int dense_limit = 400);

// The contact nodes' tangential free positions: x, then a 3D body's z (the order of the
// tangential contact unknowns and of the tangential-mass edge's coordinates).
std::vector<int> tangential_contact_dofs(const Discretization& d);

// The columns `positions` of an identity of n rows: a sparse selection (P^T A P picks a block).
SparseMatrix selection(Eigen::Index n, const std::vector<int>& positions);

// Free dofs minus those without mass: the number of finite modes; with the contact x dofs held,
// those of the rest (the modes build_modal_basis can compute).
int finite_mode_count(const Discretization& d, bool hold_tangential = false);

}  // namespace contactbody
