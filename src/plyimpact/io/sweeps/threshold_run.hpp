#pragma once
// The criterion of a threshold search as the deck and the command line give it, the search itself and
// its summary.json fields: shared by `plyimpact threshold` and threshold sweeps.
#include "plyimpact/analysis/thresholds/threshold_search.hpp"
#include "plyimpact/io/deck/deck.hpp"

#include <nlohmann/json.hpp>

#include <atomic>
#include <string>
#include <variant>

namespace plyimpact {

/// A failure criterion reaching 1 on the plate (onset), or ply damage on a progressive-damage plate.
struct ThresholdCriterion {
  std::string name; ///< as given: "choi-chang-matrix", "matrix-damage", …
  std::variant<Criterion, DamageCriterion> criterion;
};

/// `name` when not empty (the command line's --criterion, named `option` in errors), else [threshold]
/// criterion, else the first of [damage] criteria. Throws DeckError when there is none, for an unknown
/// name, a damage criterion without [damage] model = "progressive", or "damage-area" without
/// threshold.damage_area.
[[nodiscard]] ThresholdCriterion threshold_criterion(const Deck& deck, const std::string& name,
                                                     const std::string& option = "--criterion");

/// find_threshold_velocity with the criterion's kind.
[[nodiscard]] ThresholdResult search_threshold(const ImpactCase& impact, const ThresholdCriterion& criterion,
                                               const ThresholdOptions& options,
                                               const std::atomic<bool>* cancel = nullptr);

/// summary.json of a search: criterion, threshold_velocity (null when not found), first_failure (null for
/// damage criteria), and for damage criteria damage_reached {mode, ply, element, time, force,
/// projected_damage_area} (null when not found), and damage_area (the limit) for "damage-area".
void put_threshold_summary(nlohmann::json& j, const ThresholdCriterion& criterion, const ThresholdResult& r);

/// The search options of the deck ([threshold] tolerance and max_velocity, the [damage] settings);
/// `tolerance` > 0 (the command line's --tolerance) replaces the deck's.
[[nodiscard]] ThresholdOptions threshold_options(const Deck& deck, double tolerance = 0.0);

/// summary.json of `plyimpact threshold` (the wall time, which the caller measures, aside): the header,
/// put_threshold_summary, lower_velocity, tolerance and every trial.
[[nodiscard]] nlohmann::json threshold_summary_json(const Deck& deck, const ThresholdCriterion& criterion,
                                                    const ThresholdOptions& options,
                                                    const ThresholdResult& r);

} // namespace plyimpact
