#pragma once
// Explicit central differences on a lumped mass, what the explicit step policies share (the ply damage
// elastic, damaging and stacked plates of central_difference_step.cpp, one integrator for every model):
//
//   u_{n+1} = uₙ + Δt vₙ + ½Δt² aₙ                                    (CD1: Newmark with β = 0)
//   Fc_{n+1} = F(α),  α = w_i,n+1 − sᵀu_{n+1}                         (CD2: u_{n+1} does not depend on
//                                                                       Fc_{n+1}; the plate's contact
//                                                                       compliance is 0)
//   a_{n+1} = M⁻¹ (Fc_{n+1} s_load − f_int(u_{n+1}))                   (CD3: the law once, at u_{n+1})
//   v_{n+1} = vₙ + ½Δt (aₙ + a_{n+1})                                  (CD4: γ = ½, the time loop's update)
//
// Stability: the undamped central-difference step is stable for Δt ω_max < 2, ω_max the highest
// frequency of K₀ φ = ω² M φ with K₀ the undamaged stiffness (damage only lowers it). A policy refuses
// Δt > 0.9 · 2/ω_max (CD5); the contact spring adds ω_c² = k_c sᵀM⁻¹s at the impact point, which each
// step checks with the secant k_c of the contact law (CD6), stopping the run, with the step to use, where
// Δt √(ω_max² + ω_c²) > 2.
#include "plyimpact/analysis/step_policy.hpp"
#include "plyimpact/fem/mechanical_model.hpp"

#include <optional>
#include <string>
#include <string_view>

namespace plyimpact {

/// CD5: the largest Δt accepted for a plate whose highest angular frequency is ω_max: 0.9 · 2/ω_max [s].
[[nodiscard]] double stable_time_step(double omega_max);
/// ω_max of K0 φ = ω² M φ for the plate of undamaged stiffness K0 and mass M [rad/s]. Throws
/// std::invalid_argument, naming `key`, where M is not diagonal with mass on every DOF.
[[nodiscard]] double explicit_highest_frequency(const SparseMatrix& K0, const MassOperator& M,
                                                const std::string& key);
/// ω_max of `model`'s virgin undeformed stiffness on its mass (the bound CD5 takes) [rad/s]; throws as above.
[[nodiscard]] double explicit_highest_frequency(const MechanicalModel& model, const std::string& key);

/// Central differences (CD1 to CD6) on any plate model with a diagonal mass: the one explicit step
/// policy (central_difference_step.cpp). `key` is the deck key that chose it, for its messages. Throws
/// std::invalid_argument where the mass is not diagonal or Δt of `options` is above the stable step.
[[nodiscard]] std::unique_ptr<StepPolicy>
central_difference_step_policy(std::unique_ptr<const MechanicalModel> model, const StepPolicyOptions& options,
                               std::string key);

class CentralDifference {
public:
  /// The scheme with step `dt` on the plate of undamaged stiffness K0 and mass M. Throws
  /// std::invalid_argument, the message naming `key` (the deck key that chose the scheme), where M is
  /// not diagonal with mass on every DOF, where `gamma` is not ½, or where dt is above the stable step.
  /// `omega_max`: ω_max of K0 and M where the caller has it (the case computed it for dt = "auto"),
  /// else computed here.
  CentralDifference(const SparseMatrix& K0, const MassOperator& M, const NewmarkCoefficients& newmark,
                    std::string key, std::optional<double> omega_max = std::nullopt);

  [[nodiscard]] double omega_max() const { return omega_max_; }
  [[nodiscard]] double time_step() const { return dt_; }
  /// ½ vᵀMv.
  [[nodiscard]] double kinetic_energy(const Eigen::VectorXd& v) const {
    return 0.5 * v.dot(mass_.cwiseProduct(v));
  }
  /// sᵀM⁻¹s: one over the mass that a contact spring acting through the load s moves [1/kg].
  [[nodiscard]] double flexibility(const Eigen::VectorXd& s) const {
    return s.dot(inverse_mass_.cwiseProduct(s));
  }

  /// CD1: u_{n+1} from the state at the start of the step.
  void predict(const PlateState& s, Eigen::VectorXd& u_next) const;
  /// CD3: a = M⁻¹ f into `a`; throws NewtonFailure where a is not finite (step `step` ending at t).
  void accelerate(const Eigen::VectorXd& force, long step, double t, Eigen::VectorXd& a) const;
  /// CD6: throws NewtonFailure, naming the step to use, where the contact spring of the step's secant
  /// stiffness on the mass 1/`flexibility` makes Δt unstable.
  void check_contact(long step, double t, const ContactSolution& cs, const ContactStep& contact,
                     double flexibility) const;

private:
  std::string key_;
  double dt_ = 0.0;
  Eigen::VectorXd mass_, inverse_mass_;
  double omega_max_ = 0.0;
};

} // namespace plyimpact
