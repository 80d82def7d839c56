#pragma once
// Threshold velocity (SPEC §7; thesis Table 4.3): the smallest impact velocity at which a criterion
// first reaches 1 anywhere in the plate during the event, by bracketing and bisection. Every trial is
// a run of the same ImpactCase with another velocity: the linear or non-linear model the case was
// built with, one plate, one time step (linear: one factorization of K̄ for all trials).
//
// On a progressive-damage plate the search can also look for damage itself (DamageCriterion): the
// first fibre or matrix damage (some d > 0) or a projected damaged area above a limit. Each trial is
// then a whole progressive run from the virgin plate: the damage step policy starts every run with a
// virgin damage field and factors its own K̄ (newton_newmark_step.cpp), nothing damaged is carried between
// trials.
#include "plyimpact/analysis/fields/damage_tracker.hpp"
#include "plyimpact/analysis/impact/impact_case.hpp"
#include "plyimpact/laminate/ply_damage.hpp"

#include <functional>
#include <optional>
#include <string_view>
#include <vector>

namespace plyimpact {

struct ThresholdTrial {
  double velocity = 0.0;
  bool failed = false;
  double peak_index = 0.0; ///< criterion: its peak index; damage-area: area / limit; first damage: 0
};

/// What a threshold search on a progressive-damage plate looks for.
struct DamageCriterion {
  enum class Kind {
    fibre_damage,  ///< "fibre-damage": d > 0 in fibre tension or compression, anywhere
    matrix_damage, ///< "matrix-damage": d > 0 in matrix tension or compression, anywhere
    damage_area,   ///< "damage-area": projected damaged area (DamageField) above `area`
  };
  Kind kind = Kind::matrix_damage;
  double area = 0.0; ///< damage_area: the limit [m²]
};

/// "fibre-damage", "matrix-damage", "damage-area".
[[nodiscard]] std::string_view to_string(DamageCriterion::Kind kind);
/// Exact deck name → kind; nullopt for another name.
[[nodiscard]] std::optional<DamageCriterion::Kind> parse_damage_criterion(std::string_view name);
/// The fibre modes for fibre_damage, the matrix modes for matrix_damage; all modes for damage_area.
[[nodiscard]] bool counts_for(DamageCriterion::Kind kind, DamageMode mode);

/// Where a damage criterion was met in the run at the threshold velocity (the first step it held).
struct DamageReached {
  /// fibre-/matrix-damage: a mode of that kind damaged at that step; damage-area: the run's first damage
  DamageMode mode = DamageMode::matrix_tension;
  int ply = 0;                 ///< 1-based
  int element = 0;             ///< 1-based, as DamageOnset
  double time = 0.0;           ///< [s]
  double force = 0.0;          ///< contact force then [N]
  double projected_area = 0.0; ///< projected damaged area then [m²]
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
  std::optional<DamageOnset> first_failure; ///< at `velocity` (failure criteria)
  std::optional<DamageReached> damage;      ///< at `velocity` (damage criteria)
  std::vector<ThresholdTrial> trials;       ///< in the order run
};

/// Runs the search starting from the case's impact velocity as the first trial.
[[nodiscard]] ThresholdResult find_threshold_velocity(const ImpactCase& impact, Criterion criterion,
                                                      const ThresholdOptions& options = {},
                                                      const std::atomic<bool>* cancel = nullptr);
/// The same search for damage on a progressive-damage case (throws std::invalid_argument otherwise, or
/// for a damage-area limit that is not positive). Plain bisection: a run without damage has no index
/// that predicts the threshold. options.damage is not used.
[[nodiscard]] ThresholdResult find_threshold_velocity(const ImpactCase& impact,
                                                      const DamageCriterion& criterion,
                                                      const ThresholdOptions& options = {},
                                                      const std::atomic<bool>* cancel = nullptr);

} // namespace plyimpact
