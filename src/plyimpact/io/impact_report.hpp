#pragma once
// The impact analysis as the deck describes it, and its results: history.csv, summary.json,
// field CSVs and the short table printed on stdout.
#include "plyimpact/analysis/damage_tracker.hpp"
#include "plyimpact/analysis/impact_analysis.hpp"
#include "plyimpact/io/deck.hpp"
#include "plyimpact/io/results.hpp"

#include <functional>
#include <string>

namespace plyimpact {

/// Impactor, contact law and time stepping from the deck (k "auto" → SPEC §4 formula; dt "auto" →
/// Hertz contact time on a rigid target / 1000).
[[nodiscard]] ImpactSettings impact_settings_from_deck(const Deck& deck);

/// The plate of an impact deck: the deck's mesh, or a single element when the target is rigid
/// (plate.rigid = true: the plate only carries the impact point, closed-form checks).
[[nodiscard]] PlateModel impact_model_from_deck(const Deck& deck, bool rigid_target);

/// [damage] every and delamination_ply_n as the damage tracker takes them.
[[nodiscard]] DamageOptions damage_options_from_deck(const Deck& deck);

/// Time step chosen for dt = "auto": the rigid-target Hertz contact time 3.21807 (m²/(k² v0))^(1/5)
/// divided by 1000, rounded down to two significant digits.
[[nodiscard]] double automatic_time_step(double mass, double k, double velocity);

[[nodiscard]] nlohmann::json impact_summary_json(const Deck& deck, const ImpactSettings& settings,
                                                 const ImpactResult& result);
[[nodiscard]] std::string impact_history_csv(const ImpactResult& result);
[[nodiscard]] std::string impact_summary_text(const ImpactSettings& settings, const ImpactResult& result);
/// history.csv, field_<t>.csv for every snapshot and, last, summary.json (`extend` may add keys).
void write_impact_results(const ResultsFolder& folder, const Deck& deck, const PlateModel* model,
                          const ImpactSettings& settings, const ImpactResult& result,
                          const std::function<void(nlohmann::json&)>& extend = {});

} // namespace plyimpact
