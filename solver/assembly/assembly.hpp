// Assembly of the P1 plane-strain stiffness A, the consistent mass M and the redistributed
// mass M_r (paper section 3), and the contact operators B_N, B_T.
#pragma once

#include <Eigen/Dense>
#include <Eigen/Sparse>
#include <array>
#include <vector>

#include "mesh/mesh.hpp"

namespace contactbody {

using SparseMatrix = Eigen::SparseMatrix<double>;  // column major, int indices
using RowMajorSparseMatrix = Eigen::SparseMatrix<double, Eigen::RowMajor>;

// Plane-strain stiffness on all 2*nodes dofs (no Dirichlet condition applied).
SparseMatrix stiffness_matrix(const Mesh& mesh, double lambda, double mu);

// The strain energy 1/2 u^T A u of the same elements, evaluated so that it is >= 0 and exactly 0
// for any translation whatever its size: each triangle's constant strain is formed from the
// displacements of two nodes relative to the third, and its energy density as
//   (lambda + mu)/2 (tr e)^2 + mu/2 (e_xx - e_yy)^2 + mu/2 gamma_xy^2
// (a sum of squares with positive weights: mu > 0, lambda + mu > 0). The quadratic form
// u^T A u instead rounds |A| |u|^2, which for a body far from its reference position is far
// larger than the energy itself.
class StrainEnergy {
public:
    StrainEnergy() = default;
    StrainEnergy(const Mesh& mesh, double lambda, double mu);
    double operator()(const Eigen::VectorXd& u) const;

private:
    struct Element {
        std::array<int, 3> nodes;
        double dx1, dy1, dx2, dy2;  // gradients of the shape functions of nodes 1 and 2
        double area;
    };
    std::vector<Element> elements_;
    double lambda_ = 0, mu_ = 0;
};

// Consistent scalar P1 mass matrix (one entry per node pair), density rho.
SparseMatrix scalar_mass_matrix(const Mesh& mesh, double rho);

// Khenous-Laborde-Renard redistribution of a scalar mass matrix: contact nodes' rows and
// columns zeroed, the other entries (same pattern) corrected by the least change in the
// Frobenius norm that restores the total mass, first and second moments; where that is not
// positive definite, by the least change relative to each entry (`notes` says so). Throws
// std::invalid_argument when the mesh is too coarse for the six moments to be matched, or
// neither is positive definite.
SparseMatrix redistributed_mass(const Mesh& mesh, const SparseMatrix& scalar_mass,
                                std::vector<std::string>& notes);

// The six moments used by the redistribution: sum m_ij, sum m_ij x_i, sum m_ij y_i,
// sum m_ij x_i x_j, sum m_ij x_i y_j, sum m_ij y_i y_j.
std::array<double, 6> mass_moments(const Mesh& mesh, const SparseMatrix& scalar_mass);

// Vector mass matrix on 2*nodes dofs with block mass_x on the x components and mass_y on y.
SparseMatrix vector_mass_matrix(const SparseMatrix& mass_x, const SparseMatrix& mass_y);

}  // namespace contactbody
