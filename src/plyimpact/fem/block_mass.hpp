#pragma once
// A mass matrix that is block-diagonal: the lumped mass plus a mass that couples a few DOFs at a time —
// the selective mass scaling of a stack's interfaces (analysis/impact/mass_scaling.hpp), whose nodal penalty
// ties the faces of the sub-laminates at one node only. Central differences need M⁻¹ r every step
// (analysis/integrators/central_difference_step.cpp), and the stable step needs products with the symmetric
// form M^-½ K M^-½ (analysis/plate_analyses/modal_analysis.hpp). Both are exact and cheap here: the blocks
// are the connected components of M's graph, each inverted once (Eigen's self-adjoint eigensolver: M_b = V Λ
// Vᵀ, M_b⁻¹ = V Λ⁻¹ Vᵀ, M_b^-½ = V Λ^-½ Vᵀ); a DOF that nothing couples is a 1 × 1 block, its inverse a
// division.
#include "plyimpact/fem/mass_operator.hpp"

#include <Eigen/Core>

#include <vector>

namespace plyimpact {

class BlockDiagonalMass {
public:
  /// The blocks of `M` (symmetric, both triangles stored). Throws std::invalid_argument where a block is
  /// not positive definite or has more than `largest_block` DOFs (M is then not the mass of a model whose
  /// coupling is local).
  explicit BlockDiagonalMass(const SparseMatrix& M, int largest_block = 64);

  [[nodiscard]] Eigen::Index size() const { return diagonal_inverse_.size(); }
  /// x = M⁻¹ r (x sized by the caller; no allocation). Blocks on the element-loop threads, each written
  /// to its own DOFs: the same bits for any number of threads.
  void solve(const Eigen::VectorXd& r, Eigen::VectorXd& x) const;
  /// x = M^-½ r, M^-½ symmetric and block-diagonal as M: A = M^-½ K M^-½ has the eigenvalues ω² of
  /// K φ = ω² M φ. As solve: no allocation, the same bits for any number of threads.
  void apply_inverse_sqrt(const Eigen::VectorXd& r, Eigen::VectorXd& x) const;
  /// Blocks of more than one DOF, and the largest.
  [[nodiscard]] int coupled_blocks() const { return static_cast<int>(blocks_.size()); }
  [[nodiscard]] int largest_block() const { return largest_; }

private:
  using RowMajorMatrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;
  struct Block {
    std::vector<int> equations;  ///< ascending
    RowMajorMatrix inverse;      ///< M_b⁻¹, stored by rows: the products read it row by row
    RowMajorMatrix inverse_sqrt; ///< M_b^-½
  };
  /// x = D r, then each block's rows of x from its matrix `Block::*power` (M_b⁻¹ or M_b^-½) and r.
  void apply(const Eigen::VectorXd& diagonal, RowMajorMatrix Block::*power, const Eigen::VectorXd& r,
             Eigen::VectorXd& x) const;

  Eigen::VectorXd diagonal_inverse_;      ///< 1/M_ii of the DOFs that nothing couples, 0 for the others
  Eigen::VectorXd diagonal_inverse_sqrt_; ///< its square roots
  std::vector<Block> blocks_;
  int largest_ = 1;
};

} // namespace plyimpact
