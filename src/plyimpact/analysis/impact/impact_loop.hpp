#pragma once
// The one time loop of every impact run (SPEC §4; thesis 2.3–2.4, 3.5): plate M ü + K u = Fc s (2.2)
// (or its non-linear form), impactor m ẅi = −Fc (2.4), indentation α = wi − ws (2.8), contact law
// HertzContact, Newmark with constant Δt for both (or error-controlled steps, time_step_control.hpp).
//
//   initialise (u, v, a, impactor)               observers.on_start
//   for each step:
//     plate and contact force   (the step policy: the only part that differs between runs)
//     contact history, impactor, Newmark update of the plate, energies, guards
//     observers.on_step
//     end-of-event rule
//   summary                                       observers.on_finish
#include "plyimpact/analysis/impact/impact_observer.hpp"
#include "plyimpact/analysis/impact/parameters.hpp"
#include "plyimpact/analysis/integrators/step_policy.hpp"

#include <atomic>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace plyimpact {

/// The run's time stepping, resolved (no "auto").
struct LoopSettings {
  double dt = 1e-6;          ///< [s]
  std::optional<double> end; ///< [s]; empty: the SPEC §4 end-of-event rule
  double newmark_beta = 0.25, newmark_gamma = 0.5;
  long max_steps = 2'000'000;
  /// Stop where the running energy balance error passes this fraction of ½ m v0² (empty: never).
  std::optional<double> stop_at_energy_error;
  /// engaged: error-controlled steps of at most dt (time_step_control.hpp); the policy must allow them
  std::optional<AdaptiveTimeStep> adaptive;
  double fundamental_period = 0.0; ///< of the plate, for the end-of-event rule [s]
  /// engaged: end the event by separation (separation_end.hpp), c of the undamaged plate at the impact
  /// point [m/N]; the SPEC §4 rule stays the fallback. Ignored where `end` is given.
  std::optional<double> separation_compliance;
  const std::atomic<bool>* cancel = nullptr; ///< stop after the current step when set
  /// a step that fails (NewtonFailure, BandLimitError) ends the run (ImpactResult::failure), not a throw
  bool keep_failed_run = false;
  /// Laminate thickness under the impact point of a linear plate (empty: non-linear plate or rigid
  /// target): a peak deflection above guards.hpp's max_linear_deflection of it warns [m].
  std::optional<double> linear_thickness;
  std::vector<std::string> warnings; ///< found before the run (guards.hpp): start ImpactResult::warnings
  /// the plate followed at the contact point alone (StepPolicy::start) where the policy
  /// can; the observers must not ask for the field
  bool contact_point_response = false;
};

/// The running energy balance is checked every this many steps (StepView::energy_balance_error, and
/// LoopSettings::stop_at_energy_error): the plate's strain energy may cost an element loop.
inline constexpr long energy_check_every = 100;

/// The separation rule (separation_end.hpp) is checked once per this much simulated time after the
/// impactor has left (every step where the step is longer): the plate's strain energy may cost an element
/// loop [s].
inline constexpr double separation_check_interval = 1e-6;

/// Runs one impact event. The result's summary values are filled in; histories are the observers' job.
[[nodiscard]] ImpactResult run_impact_loop(const StepPolicy& policy, const Impactor& impactor, double k,
                                           const ContactLawParameters& contact, const LoopSettings& settings,
                                           std::span<ImpactObserver* const> observers);

} // namespace plyimpact
