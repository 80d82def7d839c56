#pragma once
// The plate analyses besides the impact — static (linear or large-deflection), modal and buckling — as
// the commands run them: the lines they print and their summary.json, with or without a results
// folder. The command line and the Python module both run them through here.
#include "plyimpact/io/deck/deck.hpp"
#include "plyimpact/io/results/results.hpp"

#include <nlohmann/json.hpp>

#include <optional>
#include <string>

namespace plyimpact {

// NOLINTNEXTLINE(bugprone-exception-escape): nlohmann::json's move does not throw
struct AnalysisOutcome {
  std::string text;       ///< what the command prints on stdout
  nlohmann::json summary; ///< summary.json
};

/// `plyimpact static DECK [--nonlinear]`: deflections; with a folder, displacements.csv, ParaView files
/// ([output] vtk) and summary.json.
[[nodiscard]] AnalysisOutcome run_static_analysis(const Deck& deck, bool nonlinear,
                                                  const std::optional<ResultsFolder>& folder);
/// `plyimpact modal DECK`: frequencies; with a folder, modes.csv, ParaView files and summary.json.
[[nodiscard]] AnalysisOutcome run_modal_analysis(const Deck& deck,
                                                 const std::optional<ResultsFolder>& folder);
/// `plyimpact buckling DECK`: load factors; with a folder, modes.csv, ParaView files and summary.json.
[[nodiscard]] AnalysisOutcome run_buckling_analysis(const Deck& deck,
                                                    const std::optional<ResultsFolder>& folder);

} // namespace plyimpact
