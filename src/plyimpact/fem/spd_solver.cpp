#include "plyimpact/fem/spd_solver.hpp"

#include <Eigen/CholmodSupport>
#include <Eigen/SparseCholesky>

namespace plyimpact {

struct SpdSolver::Impl {
  Eigen::CholmodSupernodalLLT<Eigen::SparseMatrix<double>> cholmod;
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> ldlt;
};

SpdSolver::SpdSolver(SparseSolverKind kind) : kind_(kind), impl_(std::make_unique<Impl>()) {}
SpdSolver::~SpdSolver() = default;
SpdSolver::SpdSolver(SpdSolver&&) noexcept = default;
SpdSolver& SpdSolver::operator=(SpdSolver&&) noexcept = default;

void SpdSolver::factorize(const Eigen::SparseMatrix<double>& A) {
  if (A.rows() == 0) throw NotPositiveDefinite("the system has no free degrees of freedom");
  if (kind_ == SparseSolverKind::cholmod) {
    impl_->cholmod.compute(A);
    if (impl_->cholmod.info() != Eigen::Success)
      throw NotPositiveDefinite("the matrix is not positive definite (CHOLMOD found a non-positive pivot)");
    return;
  }
  impl_->ldlt.compute(A);
  if (impl_->ldlt.info() != Eigen::Success || !(impl_->ldlt.vectorD().minCoeff() > 0.0))
    throw NotPositiveDefinite("the matrix is not positive definite (a pivot of LDLᵀ is zero or negative)");
  // A pivot many orders below the largest is a near-mechanism: round-off, not stiffness.
  const double dmax = impl_->ldlt.vectorD().maxCoeff();
  if (impl_->ldlt.vectorD().minCoeff() < 1e-13 * dmax)
    throw NotPositiveDefinite("the matrix is singular to working precision (pivot ratio below 1e-13)");
}

Eigen::VectorXd SpdSolver::solve(const Eigen::VectorXd& b) const {
  if (kind_ == SparseSolverKind::cholmod) return impl_->cholmod.solve(b);
  return impl_->ldlt.solve(b);
}

Eigen::MatrixXd SpdSolver::solve(const Eigen::MatrixXd& B) const {
  if (kind_ == SparseSolverKind::cholmod) return impl_->cholmod.solve(B);
  return impl_->ldlt.solve(B);
}

long SpdSolver::factor_nonzeros() const {
  if (kind_ == SparseSolverKind::cholmod) return -1;
  return static_cast<long>(impl_->ldlt.matrixL().nestedExpression().nonZeros());
}

} // namespace plyimpact
