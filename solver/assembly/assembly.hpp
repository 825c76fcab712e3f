// Assembly of the P1 stiffness A (plane strain in 2D, 3D elasticity on tetrahedra), the consistent mass M and the redistributed
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

// Stiffness on all dim*nodes dofs (no Dirichlet condition applied): plane strain in 2D.
SparseMatrix stiffness_matrix(const Mesh& mesh, double lambda, double mu);

// The strain energy 1/2 u^T A u of the same elements, evaluated so that it is >= 0 and exactly 0
// for any translation whatever its size: each cell's constant strain is formed from the
// displacements of its nodes relative to the first, and its energy density as
//   2D: (lambda + mu)/2 (tr e)^2 + mu/2 (e_xx - e_yy)^2 + mu/2 gamma_xy^2
//   3D: (lambda + 2mu/3)/2 (tr e)^2 + mu/3 sum_{i<j} (e_ii - e_jj)^2 + mu/2 sum_{i<j} gamma_ij^2
// (sums of squares with positive weights: mu > 0 and lambda + mu > 0, or in 3D the bulk
// modulus lambda + 2mu/3 > 0). The quadratic form
// u^T A u instead rounds |A| |u|^2, which for a body far from its reference position is far
// larger than the energy itself.
class StrainEnergy {
public:
    StrainEnergy() = default;
    StrainEnergy(const Mesh& mesh, double lambda, double mu);
    double operator()(const Eigen::VectorXd& u) const;

private:
    struct Element {
        std::array<int, 4> nodes;                   // dim + 1 of them
        std::array<std::array<double, 3>, 3> grad;  // gradients of the shape functions of nodes 1..dim
        double measure;                             // area or volume
    };
    std::vector<Element> elements_;
    int dim_ = 2;
    double lambda_ = 0, mu_ = 0;
};

// Consistent scalar P1 mass matrix (one entry per node pair), density rho.
SparseMatrix scalar_mass_matrix(const Mesh& mesh, double rho);

// Khenous-Laborde-Renard redistribution of a scalar mass matrix: contact nodes' rows and
// columns zeroed, the other entries (same pattern) corrected by the least change in the
// Frobenius norm that restores the total mass, first and second moments (in 2D or 3D); where that is not
// positive definite, by the least change relative to each entry (`notes` says so). Throws
// std::invalid_argument when the mesh is too coarse for the moments to be matched, or
// neither is positive definite.
SparseMatrix redistributed_mass(const Mesh& mesh, const SparseMatrix& scalar_mass,
                                std::vector<std::string>& notes);

// What certificates tell of whether m, a block of the consistent scalar P1 mass of a
// dim-dimensional mesh (every entry positive) with each entry changed by at most `fraction` of
// itself, is positive definite: a diagonal entry or a 2x2 principal minor that is not positive
// refutes it; fraction < 1/(dim+2) proves it (an element's mass is at least 1/(dim+2) of its
// lumped form); a principal submatrix on one of `cells` (up to four of m's indices each, -1
// where a cell's node is not in m) that is not positive definite refutes it. Else undecided: a
// factorization decides (docs/decisions.md, "M_r's positive definiteness by certificates").
enum class MassCertificate { definite, indefinite, undecided };
MassCertificate mass_definiteness_certificate(const SparseMatrix& m, double fraction, int dim,
                                              const std::vector<std::array<int, 4>>& cells = {});

// The moments used by the redistribution: sum m_ij, sum m_ij x_i, sum m_ij y_i (, z_i),
// then sum m_ij x_i x_j, sum m_ij x_i y_j, ... (each pair of coordinates once): 6 in 2D, 10 in 3D.
std::vector<double> mass_moments(const Mesh& mesh, const SparseMatrix& scalar_mass);

// Vector mass matrix on dim*nodes dofs: block `normal` on the y components, `tangential` on
// x (and z).
SparseMatrix vector_mass_matrix(int dim, const SparseMatrix& tangential, const SparseMatrix& normal);

}  // namespace contactbody
