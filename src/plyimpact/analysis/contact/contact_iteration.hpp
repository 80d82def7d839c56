#pragma once
// The iterations of one implicit Newmark step on the plate and the contact together (SPEC §4), as the
// Newton–Newmark policy (newton_newmark_step.cpp) solves it for every model. Step n → n+1, unknowns u and Fc;
// with the Newmark acceleration a = c0 (u − uₙ) − c2 vₙ − c3 aₙ the plate's residual is
//   r(u, Fc) = Fc s − M a(u) − f(u),   Fc = F(α),  α = wᵢ(Fc) − sᵀu,
// and each iteration solves with an iteration matrix K̄ that the policy owns:
//   û = u_k + K̄⁻¹ g(u_k),  g = −M a(u_k) − f(u_k),   u_{k+1} = û + Fc K̄⁻¹ s,
// so that sᵀu_{k+1} is affine in Fc and the contact law is solved exactly inside every iteration.
// The policies differ in f, in K̄ and in when they refresh it; the vectors and the arithmetic of an
// iteration are the same, and live here, sized once per run: an iteration allocates nothing.
#include "plyimpact/analysis/contact/contact_load.hpp"
#include "plyimpact/analysis/integrators/step_policy.hpp"

#include <Eigen/Dense>

namespace plyimpact {

class ContactIteration {
public:
  explicit ContactIteration(int equations);

  /// The iterate u_k.
  [[nodiscard]] Eigen::VectorXd& uk() { return uk_; }

  /// u_k = uₙ + Δt vₙ + ½ Δt² aₙ: the first iterate, at constant acceleration.
  void predict(const PlateState& s, const NewmarkCoefficients& nc);
  /// M a(u_k): Newmark's a = c0 (u_k − uₙ) − c2 vₙ − c3 aₙ, or with `two_point` the trapezoidal rule's
  /// two-point form a = c0 (u_k − uₙ − Δt vₙ), where aₙ does not enter (DL7; its mean force then carries
  /// the start force, which the caller adds to the internal force).
  void step_inertia(const PlateState& s, const NewmarkCoefficients& nc, const MassOperator& M,
                    bool two_point);
  /// g = −M a(u_k) − f, f the internal force at u_k.
  void set_internal_force(const Eigen::VectorXd& f) { g_.noalias() = -inertia_ - f; }

  /// Has u_k converged with the contact solution `cs` of the last iteration: the residual
  /// r = g + Fc s(α) is small against |f| + |M a| + |Fc| |s(α)|, and so is the next correction, estimated
  /// without a solve by the diagonal of K̄ (δ ≈ diag(K̄)⁻¹ r), against |u_k|. Sets residual_norm().
  [[nodiscard]] bool converged(const ContactLoading& loading, const ContactSolution& cs,
                               const Eigen::VectorXd& f, const Eigen::VectorXd& kbar_diagonal,
                               double residual_tolerance, double displacement_tolerance);
  /// |r| of the last converged() call.
  [[nodiscard]] double residual_norm() const { return residual_norm_; }

  /// One iteration from u_k: `solve(g, x)` puts K̄⁻¹ g into x; the contact problem at û is solved into
  /// `cs`, and u_k becomes u_{k+1}. Returns the length of the correction |u_{k+1} − u_k|.
  template <class Solve>
  double correct(const Solve& solve, const ContactLoading& loading, const CondensedContact& contact,
                 ContactSolution& cs) {
    solve(g_, correction_);
    u_iterate_.noalias() = uk_ + correction_; // û, the iterate before the contact force
    cs = loading.solve(contact, loading.sampler().dot(u_iterate_));
    loading.add_response(cs.alpha, cs.force, u_iterate_);
    const double length = (u_iterate_ - uk_).norm();
    uk_.swap(u_iterate_);
    return length;
  }

private:
  Eigen::VectorXd uk_, ak_, inertia_, g_, s_load_, residual_, correction_, u_iterate_;
  double residual_norm_ = 0.0;
};

} // namespace plyimpact
