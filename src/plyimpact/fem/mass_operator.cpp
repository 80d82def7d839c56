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

} // namespace plyimpact
