#pragma once
// Threshold velocity (SPEC §7; thesis Table 4.3): the smallest impact velocity at which a criterion
// first reaches 1 anywhere in the plate during the event, by bracketing and bisection. Every trial is
// a run of the same ImpactCase with another velocity: the linear or non-linear model the case was
// built with, one plate, one time step (linear: one factorization of K̄ for all trials).
#include "plyimpact/analysis/damage_tracker.hpp"
#include "plyimpact/analysis/impact_case.hpp"

#include <functional>
#include <optional>
#include <vector>

namespace plyimpact {

struct ThresholdTrial {
  double velocity = 0.0;
  bool failed = false;
  double peak_index = 0.0;
};

struct ThresholdOptions {
  double tolerance = 0.01;     ///< bracket width at the end [m/s]
  double max_velocity = 500.0; ///< give up above this [m/s]
  DamageOptions damage;
  /// After every trial run, with all the trials so far (the last one is new): a progress display.
  std::function<void(const std::vector<ThresholdTrial>&)> on_trial;
};

/// How far a search has narrowed its bracket, 0 to 1 on a log scale, from the first bracket
/// [no failure, failure] to `tolerance`: log(w0 / w) / log(w0 / tolerance); 0 while no trial has failed.
[[nodiscard]] double bracket_progress(const std::vector<ThresholdTrial>& trials, double tolerance);

struct ThresholdResult {
  bool found = false;
  double velocity = 0.0;                    ///< upper end of the final bracket: fails at this velocity [m/s]
  double lower = 0.0;                       ///< lower end: no failure [m/s]
  std::optional<DamageOnset> first_failure; ///< at `velocity`
  std::vector<ThresholdTrial> trials;       ///< in the order run
};

/// Runs the search starting from the case's impact velocity as the first trial.
[[nodiscard]] ThresholdResult find_threshold_velocity(const ImpactCase& impact, Criterion criterion,
                                                      const ThresholdOptions& options = {},
                                                      const std::atomic<bool>* cancel = nullptr);

} // namespace plyimpact
