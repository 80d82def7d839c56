// The mass operator (mass_operator.hpp).
#include "plyimpact/fem/mass_operator.hpp"

#include <cmath>

namespace plyimpact {

MassOperator::MassOperator(const SparseMatrix& M, double tolerance) : M_(M) {
  const double m_max = M_.rows() > 0 ? M_.diagonal().cwiseAbs().maxCoeff() : 0.0;
  for (int col = 0; col < M_.outerSize(); ++col)
    for (SparseMatrix::InnerIterator it(M_, col); it; ++it)
      if (it.row() != col && std::abs(it.value()) > tolerance * m_max) return;
  diagonal_ = M_.diagonal();
}

MassOperator::MassOperator(const Eigen::VectorXd& diagonal)
    : M_(diagonal.size(), diagonal.size()), diagonal_(diagonal) {
  M_.reserve(Eigen::VectorXi::Ones(diagonal.size()));
  for (Eigen::Index i = 0; i < diagonal.size(); ++i)
    M_.insert(i, i) = diagonal[i];
  M_.makeCompressed();
}

} // namespace plyimpact
