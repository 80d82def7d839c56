#pragma once
// The linear plate seen from the contact point (issue 22, "reuse across cases that share the plate").
//
// The linear step (linear_step.cpp) is a linear, time-invariant map from the sequence of contact forces
// F_1, F_2, … to the plate's state: u_{n+1} = K̄⁻¹(M(c0 uₙ + c2 vₙ + c3 aₙ) + F_{n+1} s) with Newmark's
// updates of v and a, from rest. So the deflection under the impactor is a discrete convolution
//
//   ws_n = Σ_{k=1..n} g_{n−k} F_k,                                                              (CP1)
//
// g_j = swᵀu_{1+j} of one run from rest with F_1 = 1 and every other force 0: the impulse response of the
// Newmark-discretised plate at the contact point, g_0 = c = swᵀK̄⁻¹s its compliance. It depends on the
// plate, Δt, β, γ and the impact point, not on the impactor's mass, speed or contact law: computed once,
// it serves every run that changes only those, and each step of such a run costs the sum (CP1) over the
// steps in contact so far instead of a solve with K̄. Exact in exact arithmetic: the numbers differ from
// the full run's by the rounding of the different sums
// (tests/analysis/contact/test_contact_point_response.cpp).
//
// What it cannot give: the field (stresses, damage tracking, ParaView frames, probes) and the split of the
// plate's energy into kinetic and strain. With the trapezoidal rule (β = ¼, γ = ½) the plate's energy
// ½vᵀMv + ½uᵀKu changes by exactly the work ½(Fₙ + F_{n+1})(ws_{n+1} − wsₙ) of a point force, so the total
// (and the energy balance) is still known. Hence it is used only for the linear plate under a point load
// with the trapezoidal rule and fixed Δt, in runs that look at nothing but the contact point
// (RunRequest::contact_point_response).
#include "plyimpact/analysis/integrators/step_policy.hpp"

#include <functional>
#include <memory>
#include <mutex>
#include <vector>

namespace plyimpact {

/// g_0, g_1, … of (CP1), computed as far as runs ask for them. Runs on several threads may share one:
/// each holds a snapshot, replaced by a longer one when it needs more.
class ContactPointResponse {
public:
  /// Advances the impulse run by one step with the contact force `force` (1 first, then 0) and returns
  /// the deflection swᵀu at the contact point after it.
  using ImpulseStep = std::function<double(double force)>;

  explicit ContactPointResponse(ImpulseStep step) : step_(std::move(step)) {}

  /// g_0 … g_{n−1} at least (more: the series grows by max(256 steps, a sixteenth) at a time).
  [[nodiscard]] std::shared_ptr<const std::vector<double>> at_least(std::size_t n) const;

private:
  mutable std::mutex mutex_;
  mutable ImpulseStep step_;
  mutable std::shared_ptr<const std::vector<double>> g_ = std::make_shared<const std::vector<double>>();
};

/// A run's plate through (CP1): the loop's plate state is the contact point's (ws, ẇs, ẅs) alone. The
/// scalar contact problem of each step has the compliance g_0 = swᵀK̄⁻¹s, the same double as the full run's
/// (ContactLoading's for the point load: the same vectors, the same dot product).
class ContactPointStepper final : public PlateStepper {
public:
  explicit ContactPointStepper(std::shared_ptr<const ContactPointResponse> response);

  ContactSolution advance(long step, double t, const PlateState& s, const CondensedContact& contact,
                          Eigen::VectorXd& u_next) override;
  void accept(const PlateState& before, const Eigen::VectorXd& u_next) override;
  /// 0: the split of the plate's energy is not known (strain_energy() holds all of it).
  [[nodiscard]] double kinetic_energy(const PlateState& /*s*/) const override { return 0.0; }
  /// The plate's whole mechanical energy ½vᵀMv + ½uᵀKu, from the work of the contact force.
  [[nodiscard]] double strain_energy(const PlateState& /*s*/, double /*force*/) const override {
    return energy_;
  }
  [[nodiscard]] double contact_deflection(const Eigen::VectorXd& u) const override { return u(0); }
  /// Throws std::logic_error: this stepper has no field.
  void to_model(const Eigen::VectorXd& u, Eigen::VectorXd& out) const override;

private:
  /// ŵ_n = Σ_{k=1..n−1} g_{n−k} F_k over the steps in contact (the others have F_k = 0).
  [[nodiscard]] double free_deflection(long n, const std::vector<double>& g) const;

  std::shared_ptr<const ContactPointResponse> response_;
  std::shared_ptr<const std::vector<double>> g_;
  /// F_k of step k at index size − 1 − k, in reverse order, so that the sum (CP1) over a span is the dot
  /// product of two contiguous, increasing ranges (vectorised by Eigen); grown at the front when full
  Eigen::VectorXd reversed_forces_;
  /// F_k into reversed_forces_, growing it when k is beyond its size.
  void store_force(long k, double force);
  struct Span {
    long begin = 0, end = 0; ///< steps [begin, end) with F ≠ 0
  };
  std::vector<Span> in_contact_;
  double force_ = 0.0, previous_force_ = 0.0;
  double energy_ = 0.0; ///< Σ ½(F_k + F_{k+1})(ws_{k+1} − ws_k)
};

} // namespace plyimpact
