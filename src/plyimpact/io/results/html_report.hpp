#pragma once
// report.html of an impact run (docs/output.md): one self-contained file — inline CSS and SVG, no
// script, no network — that reads as a test report: the case in words with the ply stack, the warnings,
// the summary table (with the first load drop F_d and the absorbed energy by mechanism), the force–time,
// force–displacement and energy curves, and the damage onsets (first failures with their places, those at
// a rig's clamp tips marked, and a map) when damage was tracked, and a C-scan of the delaminations of a
// stacked plate.
#include "plyimpact/analysis/fields/damage_tracker.hpp"
#include "plyimpact/analysis/impact/impact_case.hpp"
#include "plyimpact/fem/stacked_plate.hpp"
#include "plyimpact/io/deck/deck.hpp"

#include <nlohmann/json.hpp>

#include <optional>
#include <string>
#include <vector>

namespace plyimpact {

struct ImpactReportInput {
  const Deck& deck;
  const ImpactSettings& settings;
  const nlohmann::json& summary;                    ///< the run's summary.json
  const std::vector<ImpactSample>& history;         ///< the curves (ThinnedHistory: a few thousand samples)
  const Mesh* mesh = nullptr;                       ///< the plate's mesh (none: rigid target)
  const std::vector<DamageOnset>* onsets = nullptr; ///< every onset (map), when damage was tracked
  const std::vector<DamageOnset>* first_failures = nullptr; ///< per criterion, mode and layer
  std::vector<int> clamp_tip_elements; ///< the rig's clamp-tip elements (io/mesh/test_rigs.hpp), from 1
  std::optional<DamageOnset> laminate_first_failure; ///< the earliest onset away from the clamp tips
  std::vector<std::string> notes;                    ///< what the run could not do (also printed)
  const DelaminationResult* delamination = nullptr;  ///< the interfaces of a stacked plate
};

/// The HTML text of report.html.
[[nodiscard]] std::string impact_report_html(const ImpactReportInput& in);

} // namespace plyimpact
