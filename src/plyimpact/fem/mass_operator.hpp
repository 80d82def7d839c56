#pragma once
// The mass matrix as the integrators use it (analysis/): M x as a diagonal scaling where M is diagonal.
#include <Eigen/Core>
#include <Eigen/SparseCore>

namespace plyimpact {

using SparseMatrix = Eigen::SparseMatrix<double>;

/// The mass matrix as the time loop uses it: M x as a diagonal scaling when M is diagonal (lumped mass
/// with I1 = 0, or I1 at round-off level: off-diagonal entries below `tolerance` times the largest
/// diagonal entry are dropped), as a sparse product otherwise.
class MassOperator {
public:
  MassOperator(const SparseMatrix& M, double tolerance);
  /// The diagonal mass `diagonal` (a lumped mass, scaled or not).
  explicit MassOperator(const Eigen::VectorXd& diagonal);
  [[nodiscard]] Eigen::VectorXd times(const Eigen::VectorXd& x) const {
    Eigen::VectorXd out(x.size());
    apply(x, out);
    return out;
  }
  /// out = M x into `out` (sized once): the numbers of times(x) without a new vector. A sparse M that is
  /// symmetric to the bit (every mass the program builds) is applied on the element loops' threads, each
  /// row's sum gathered from its column in the order of the one-thread product M_ * x: the same bits for
  /// any thread count.
  void apply(const Eigen::VectorXd& x, Eigen::VectorXd& out) const;
  /// ½ vᵀMv.
  [[nodiscard]] double kinetic_energy(const Eigen::VectorXd& v) const { return 0.5 * v.dot(times(v)); }
  /// ½ vᵀMv with `scratch` for M v.
  [[nodiscard]] double kinetic_energy(const Eigen::VectorXd& v, Eigen::VectorXd& scratch) const {
    apply(v, scratch);
    return 0.5 * v.dot(scratch);
  }
  [[nodiscard]] const SparseMatrix& matrix() const { return M_; }
  /// M's diagonal when M is diagonal, else empty.
  [[nodiscard]] const Eigen::VectorXd& diagonal() const { return diagonal_; }

private:
  SparseMatrix M_;
  Eigen::VectorXd diagonal_; ///< M when diagonal, else empty
  bool symmetric_ = false;   ///< M sparse and M = Mᵀ to the bit: apply() gathers rows from columns
};

} // namespace plyimpact
