#pragma once
// The impact analysis as the deck describes it, and its results: history.csv, summary.json,
// field CSVs and the short table printed on stdout.
#include "plyimpact/analysis/impact/impact_case.hpp"
#include "plyimpact/io/deck/deck.hpp"
#include "plyimpact/io/results/results.hpp"

#include <string>

namespace plyimpact {

[[nodiscard]] nlohmann::json impact_summary_json(const Deck& deck, const ImpactSettings& settings,
                                                 const ImpactResult& result);
[[nodiscard]] std::string impact_history_csv(const ImpactResult& result);
[[nodiscard]] std::string impact_summary_text(const ImpactSettings& settings, const ImpactResult& result);
/// field_<t>.csv for every snapshot and, last, summary.json (`summary`, from impact_summary_json);
/// history.csv is streamed during the run (io/results/history_csv.hpp).
void write_impact_results(const ResultsFolder& folder, const DiscretePlate* model, const ImpactResult& result,
                          const nlohmann::json& summary);

} // namespace plyimpact
