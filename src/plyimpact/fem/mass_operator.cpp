// The mass operator (mass_operator.hpp).
#include "plyimpact/fem/mass_operator.hpp"

#include "plyimpact/fem/element_loop.hpp"

#include <algorithm>
#include <cmath>

namespace plyimpact {

namespace {

/// M = Mᵀ entry for entry and bit for bit (M compressed).
bool bitwise_symmetric(const SparseMatrix& M) {
  if (M.rows() != M.cols()) return false;
  const SparseMatrix T = M.transpose();
  const auto n = static_cast<std::size_t>(M.nonZeros());
  return T.nonZeros() == M.nonZeros() &&
         std::equal(M.outerIndexPtr(), M.outerIndexPtr() + M.outerSize() + 1, T.outerIndexPtr()) &&
         std::equal(M.innerIndexPtr(), M.innerIndexPtr() + n, T.innerIndexPtr()) &&
         std::equal(M.valuePtr(), M.valuePtr() + n, T.valuePtr());
}

} // namespace

MassOperator::MassOperator(const SparseMatrix& M, double tolerance) : M_(M) {
  M_.makeCompressed();
  const double m_max = M_.rows() > 0 ? M_.diagonal().cwiseAbs().maxCoeff() : 0.0;
  for (int col = 0; col < M_.outerSize(); ++col)
    for (SparseMatrix::InnerIterator it(M_, col); it; ++it)
      if (it.row() != col && std::abs(it.value()) > tolerance * m_max) {
        symmetric_ = bitwise_symmetric(M_);
        return;
      }
  diagonal_ = M_.diagonal();
}

void MassOperator::apply(const Eigen::VectorXd& x, Eigen::VectorXd& out) const {
  if (diagonal_.size() > 0) {
    out = diagonal_.cwiseProduct(x);
    return;
  }
  if (!symmetric_) {
    out.noalias() = M_ * x;
    return;
  }
  // Row i of M is its column i: (M x)_i = Σ_k M_ki x_k over k ascending, the sum M_ * x makes for row i.
  out.resize(M_.rows());
  for_each_block(M_.cols(), [&](Eigen::Index first, Eigen::Index last) {
    for (Eigen::Index i = first; i < last; ++i) {
      double sum = 0.0;
      for (SparseMatrix::InnerIterator it(M_, i); it; ++it)
        sum += it.value() * x[it.row()];
      out[i] = sum;
    }
  });
}

MassOperator::MassOperator(const Eigen::VectorXd& diagonal)
    : M_(diagonal.size(), diagonal.size()), diagonal_(diagonal) {
  M_.reserve(Eigen::VectorXi::Ones(diagonal.size()));
  for (Eigen::Index i = 0; i < diagonal.size(); ++i)
    M_.insert(i, i) = diagonal[i];
  M_.makeCompressed();
}

} // namespace plyimpact
