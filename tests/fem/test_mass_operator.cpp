// The mass operator (fem/mass_operator.hpp): M x as the time loops use it, on threads where M is a sparse
// matrix symmetric to the bit (issue 50).
#include "plyimpact/fem/element_loop.hpp"
#include "plyimpact/fem/mass_operator.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace plyimpact::mass_operator_tests {
namespace {

/// A symmetric sparse matrix of n rows with many terms of mixed magnitude per row, where another order
/// of summation would change the last bits, diagonally dominant like a mass.
SparseMatrix symmetric_mass(int n) {
  std::vector<Eigen::Triplet<double>> t;
  for (int i = 0; i < n; ++i) {
    t.emplace_back(i, i, 100.0 + i % 13);
    for (int k = 1; k <= 40; k += 3) {
      const int j = (i + k) % n;
      const double c =
          std::sin(1.0 + 0.37 * std::min(i, j) + 0.11 * std::max(i, j)) * std::pow(10.0, (i + j) % 7 - 3);
      t.emplace_back(i, j, c);
      t.emplace_back(j, i, c);
    }
  }
  SparseMatrix M(n, n);
  M.setFromTriplets(t.begin(), t.end());
  return M;
}

Eigen::VectorXd mixed_vector(int n) {
  Eigen::VectorXd x(n);
  for (int i = 0; i < n; ++i)
    x(i) = std::cos(0.3 * i) * std::pow(10.0, i % 5 - 2);
  return x;
}

TEST(MassOperator, ASymmetricSparseMassOnThreadsIsTheOneThreadProductToTheBit) {
  const int n = 5000;
  const SparseMatrix M = symmetric_mass(n);
  const Eigen::VectorXd x = mixed_vector(n);
  const Eigen::VectorXd serial = M * x;
  const MassOperator op(M, 0.0);
  ASSERT_EQ(op.diagonal().size(), 0) << "the test matrix must not be taken for a diagonal";
  for (const int threads : {1, 2, 4}) {
    const ElementThreads setting(threads);
    Eigen::VectorXd out;
    op.apply(x, out);
    ASSERT_EQ(out.size(), n);
    for (int i = 0; i < n; ++i)
      ASSERT_EQ(out(i), serial(i)) << "row " << i << " with " << threads << " threads";
    EXPECT_EQ(op.kinetic_energy(x), 0.5 * x.dot(serial)) << threads << " threads";
  }
}

TEST(MassOperator, AnUnsymmetricSparseMatrixIsMultipliedAsItIs) {
  // Not symmetric to the bit: rows are not columns, so the product is Eigen's own, M x all the same.
  const int n = 300;
  SparseMatrix M = symmetric_mass(n);
  M.coeffRef(0, 5) += 1e-3;
  const Eigen::VectorXd x = mixed_vector(n);
  const Eigen::VectorXd expected = M * x;
  const ElementThreads setting(2);
  EXPECT_EQ(MassOperator(M, 0.0).times(x), expected);
}

TEST(MassOperator, ALumpedMassIsADiagonalScaling) {
  const Eigen::VectorXd m = (Eigen::VectorXd(3) << 1.0, 2.0, 4.0).finished();
  const MassOperator op(m);
  const Eigen::VectorXd x = (Eigen::VectorXd(3) << 3.0, -1.0, 0.5).finished();
  EXPECT_EQ(op.times(x), (Eigen::VectorXd(3) << 3.0, -2.0, 2.0).finished());
  EXPECT_DOUBLE_EQ(op.kinetic_energy(x), 0.5 * (9.0 + 2.0 + 1.0));
}

} // namespace
} // namespace plyimpact::mass_operator_tests
