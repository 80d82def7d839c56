// The block-diagonal mass of selective mass scaling (fem/block_mass.hpp): its blocks are the connected
// components of the matrix, M⁻¹ r equals a sparse Cholesky solve of the whole matrix, M^-½ M M^-½ is the
// identity, the same bits come out for one thread or two, and a matrix that is not positive definite or
// couples too many DOFs is refused.
#include "plyimpact/fem/block_mass.hpp"
#include "plyimpact/fem/element_loop.hpp"

#include <Eigen/SparseCholesky>
#include <gtest/gtest.h>

#include <stdexcept>
#include <vector>

namespace plyimpact::block_mass_tests {
namespace {

/// A mass like a stack's: a lumped diagonal, plus 2 × 2 couplings k [1 −1; −1 1] (an interface spring's
/// pattern) between DOFs i and i + n/2 for every third i.
SparseMatrix coupled_mass(int n, double k) {
  std::vector<Eigen::Triplet<double>> t;
  for (int i = 0; i < n; ++i)
    t.emplace_back(i, i, 1.0 + 0.1 * i);
  for (int i = 0; i < n / 2; i += 3) {
    const int j = i + n / 2;
    t.emplace_back(i, i, k);
    t.emplace_back(j, j, k);
    t.emplace_back(i, j, -k);
    t.emplace_back(j, i, -k);
  }
  SparseMatrix M(n, n);
  M.setFromTriplets(t.begin(), t.end());
  return M;
}

TEST(BlockDiagonalMass, ItsBlocksAreTheCoupledPairsAndItsSolveIsTheWholeMatrixs) {
  const int n = 40;
  const SparseMatrix M = coupled_mass(n, 7.0);
  const BlockDiagonalMass blocks(M);
  EXPECT_EQ(blocks.coupled_blocks(), 7); // i = 0, 3, …, 18
  EXPECT_EQ(blocks.largest_block(), 2);
  const Eigen::VectorXd r = Eigen::VectorXd::LinSpaced(n, -3.0, 5.0);
  Eigen::VectorXd x(n);
  blocks.solve(r, x);
  const Eigen::SimplicialLDLT<SparseMatrix> ldlt(M);
  const Eigen::VectorXd expected = ldlt.solve(r);
  EXPECT_LT((x - expected).norm(), 1e-13 * expected.norm());
}

TEST(BlockDiagonalMass, ItsInverseSquareRootWhitensTheMass) {
  const SparseMatrix M = coupled_mass(30, 50.0);
  const BlockDiagonalMass blocks(M);
  Eigen::MatrixXd S(30, 30); // column j: M^-½ e_j
  Eigen::VectorXd column(30);
  for (int j = 0; j < 30; ++j) {
    blocks.apply_inverse_sqrt(Eigen::VectorXd::Unit(30, j), column);
    S.col(j) = column;
  }
  const Eigen::MatrixXd I = S * Eigen::MatrixXd(M) * S;
  EXPECT_LT((I - Eigen::MatrixXd::Identity(30, 30)).cwiseAbs().maxCoeff(), 1e-12);
  EXPECT_LT((S - S.transpose()).cwiseAbs().maxCoeff(), 1e-15);
}

TEST(BlockDiagonalMass, OneThreadAndTwoGiveTheSameBits) {
  const int n = 3000;
  const BlockDiagonalMass blocks(coupled_mass(n, 3.0));
  const Eigen::VectorXd r = Eigen::VectorXd::LinSpaced(n, 1.0, 2.0).array().sin();
  Eigen::VectorXd one(n), two(n), one_sqrt(n), two_sqrt(n);
  {
    const ElementThreads threads(1);
    blocks.solve(r, one);
    blocks.apply_inverse_sqrt(r, one_sqrt);
  }
  {
    const ElementThreads threads(2);
    blocks.solve(r, two);
    blocks.apply_inverse_sqrt(r, two_sqrt);
  }
  EXPECT_EQ(one, two);
  EXPECT_EQ(one_sqrt, two_sqrt);
}

TEST(BlockDiagonalMass, RefusesAMassThatIsNotPositiveOrCouplesTooMuch) {
  SparseMatrix singular = coupled_mass(10, 1.0);
  singular.coeffRef(0, 0) = 0.3; // the block of DOFs 0 and 5, [0.3 −1; −1 2.5], has a negative determinant
  EXPECT_THROW({ const BlockDiagonalMass b(singular); }, std::invalid_argument);
  // A chain coupling every neighbour: one block of 20 DOFs, more than 8.
  std::vector<Eigen::Triplet<double>> t;
  for (int i = 0; i < 20; ++i) {
    t.emplace_back(i, i, 3.0);
    if (i > 0) {
      t.emplace_back(i, i - 1, -1.0);
      t.emplace_back(i - 1, i, -1.0);
    }
  }
  SparseMatrix chain(20, 20);
  chain.setFromTriplets(t.begin(), t.end());
  EXPECT_THROW({ const BlockDiagonalMass b(chain, 8); }, std::invalid_argument);
  EXPECT_NO_THROW({ const BlockDiagonalMass b(chain); });
}

} // namespace
} // namespace plyimpact::block_mass_tests
