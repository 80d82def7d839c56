#pragma once
// Explicit central differences on a lumped mass, for every model (central_difference_step.cpp):
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

#include <memory>
#include <string>

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

} // namespace plyimpact
