#include "plyimpact/fem/block_mass.hpp"

#include "plyimpact/fem/element_loop.hpp"

#include <Eigen/Eigenvalues>
#include <fmt/format.h>

#include <numeric>
#include <stdexcept>

namespace plyimpact {

namespace {

/// The connected components of the graph of M's off-diagonal entries: the root of each DOF (union–find
/// with path halving; the smallest DOF of a component is its root).
std::vector<int> components(const SparseMatrix& M) {
  std::vector<int> parent(static_cast<std::size_t>(M.cols()));
  std::iota(parent.begin(), parent.end(), 0);
  const auto root = [&](int i) {
    while (parent[static_cast<std::size_t>(i)] != i) {
      auto& p = parent[static_cast<std::size_t>(i)];
      p = parent[static_cast<std::size_t>(p)];
      i = p;
    }
    return i;
  };
  for (int col = 0; col < M.outerSize(); ++col)
    for (SparseMatrix::InnerIterator it(M, col); it; ++it) {
      if (it.value() == 0.0) continue;
      const int a = root(static_cast<int>(it.row())), b = root(col);
      if (a != b) parent[static_cast<std::size_t>(std::max(a, b))] = std::min(a, b);
    }
  for (int i = 0; i < static_cast<int>(parent.size()); ++i)
    parent[static_cast<std::size_t>(i)] = root(i);
  return parent;
}

/// V f(Λ) Vᵀ of the symmetric positive definite block `m`.
Eigen::MatrixXd spectral(const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>& eig, double power) {
  const Eigen::VectorXd f = eig.eigenvalues().array().pow(power);
  return eig.eigenvectors() * f.asDiagonal() * eig.eigenvectors().transpose();
}

} // namespace

BlockDiagonalMass::BlockDiagonalMass(const SparseMatrix& M, int largest_block)
    : diagonal_inverse_(Eigen::VectorXd::Zero(M.cols())) {
  if (M.rows() != M.cols()) throw std::invalid_argument("BlockDiagonalMass: the mass must be square");
  const std::vector<int> root = components(M);
  std::vector<std::vector<int>> members(root.size());
  for (int i = 0; i < static_cast<int>(root.size()); ++i)
    members[static_cast<std::size_t>(root[static_cast<std::size_t>(i)])].push_back(i);
  for (auto& eqs : members) {
    if (eqs.empty()) continue;
    const auto n = static_cast<Eigen::Index>(eqs.size());
    if (n > largest_block)
      throw std::invalid_argument(fmt::format(
          "BlockDiagonalMass: {} DOFs coupled by the mass (at most {} expected: a mass coupling whole "
          "regions is not block-diagonal)",
          n, largest_block));
    Eigen::MatrixXd m = Eigen::MatrixXd::Zero(n, n);
    for (Eigen::Index a = 0; a < n; ++a)
      for (Eigen::Index b = 0; b < n; ++b)
        m(a, b) = M.coeff(eqs[static_cast<std::size_t>(a)], eqs[static_cast<std::size_t>(b)]);
    const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(m);
    if (eig.info() != Eigen::Success || !(eig.eigenvalues().minCoeff() > 0.0))
      throw std::invalid_argument(fmt::format(
          "BlockDiagonalMass: the mass of DOFs {}… is not positive definite (smallest eigenvalue {:.4g})",
          eqs.front(), eig.eigenvalues().minCoeff()));
    if (n == 1) {
      diagonal_inverse_[eqs.front()] = 1.0 / m(0, 0);
      continue;
    }
    largest_ = std::max(largest_, static_cast<int>(n));
    blocks_.push_back({std::move(eqs), spectral(eig, -1.0), spectral(eig, -0.5)});
  }
  diagonal_inverse_sqrt_ = diagonal_inverse_.cwiseSqrt();
}

void BlockDiagonalMass::solve(const Eigen::VectorXd& r, Eigen::VectorXd& x) const {
  apply(diagonal_inverse_, &Block::inverse, r, x);
}

void BlockDiagonalMass::apply_inverse_sqrt(const Eigen::VectorXd& r, Eigen::VectorXd& x) const {
  apply(diagonal_inverse_sqrt_, &Block::inverse_sqrt, r, x);
}

void BlockDiagonalMass::apply(const Eigen::VectorXd& diagonal, RowMajorMatrix Block::*power,
                              const Eigen::VectorXd& r, Eigen::VectorXd& x) const {
  parallel_cwise_product(diagonal, r, x);
  // Fixed runs of blocks, one per task: a block's work is too small to be one.
  for_each_block(static_cast<Eigen::Index>(blocks_.size()), [&](Eigen::Index first, Eigen::Index last) {
    for (Eigen::Index b = first; b < last; ++b) {
      const Block& block = blocks_[static_cast<std::size_t>(b)];
      const RowMajorMatrix& m = block.*power;
      const auto n = static_cast<Eigen::Index>(block.equations.size());
      for (Eigen::Index i = 0; i < n; ++i) {
        double sum = 0.0;
        for (Eigen::Index j = 0; j < n; ++j)
          sum += m(i, j) * r[block.equations[static_cast<std::size_t>(j)]];
        x[block.equations[static_cast<std::size_t>(i)]] = sum;
      }
    }
  });
}

} // namespace plyimpact
