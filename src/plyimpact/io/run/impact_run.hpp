#pragma once
// An impact deck run end to end: the deck's observers (damage tracking, stress probes, ParaView frames,
// the displacement snapshot of report.txt) attached to an ImpactCase, the run, and the results folder.
// The impact command, sweep cases and the Python module all run impacts through here.
#include "plyimpact/analysis/fields/damage_tracker.hpp"
#include "plyimpact/analysis/impact/impact_case.hpp"
#include "plyimpact/io/deck/deck.hpp"
#include "plyimpact/io/results/history_csv.hpp"

#include <nlohmann/json.hpp>

#include <atomic>
#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace plyimpact {

struct ImpactRunOptions {
  /// Results folder: deck.toml, provenance.json, history.csv (written while the run goes), fields,
  /// damage tables and maps (damage_maps/), probes.csv, ParaView frames, report.txt and, last,
  /// summary.json. None: nothing is written. The caller claims the folder (io/results/output_folder.hpp).
  std::optional<std::filesystem::path> output_dir;
  bool history = true;                       ///< write history.csv (streamed while the run goes)
  bool pictures = true;                      ///< damage maps (gnuplot) in the results folder
  std::vector<ImpactObserver*> observers;    ///< more observers (progress display)
  const std::atomic<bool>* cancel = nullptr; ///< stop after the current step when set
  /// RunRequest::contact_point_response: where nothing else looks at the plate (no folder, no damage
  /// criteria, no probes, no observers), follow it at the contact point alone when that is exact
  bool contact_point_response = false;
  /// RunRequest::threads; 0: the deck's [run] threads, else the calling thread's OpenMP setting (all cores
  /// by default)
  int threads = 0;
};

// NOLINTNEXTLINE(bugprone-exception-escape): nlohmann::json's move does not throw
struct ImpactRunOutcome {
  ImpactSettings settings; ///< of the deck's own case: its impactor, k, Δt
  ImpactResult result;
  HistoryLayout history_layout; ///< the columns of its history rows (history.csv, the Python arrays)
  bool damage_tracked = false;
  std::vector<DamageOnset> first_failures; ///< per criterion, mode and ply or interface, in order of onset
  /// The elements at a rig's clamp tips (io/mesh/test_rigs.hpp, clamp_tip_elements), numbered from 1; empty
  /// without a rig or damage criteria
  std::vector<int> clamp_tip_elements;
  /// The earliest onset away from the clamp tips (io/results/damage_report.hpp)
  std::optional<DamageOnset> laminate_first_failure;
  std::vector<std::string> notes; ///< things the run could not do (e.g. no gnuplot for maps)
  /// What summary.json holds, also when no folder is written (the Python module returns it).
  nlohmann::json summary;
};

/// How a run solved its plate, as the sweep's records and Python's ImpactStudy name it: "contact point"
/// (through its impulse response there, analysis/contact/contact_point_response.hpp) or "full" (every step).
[[nodiscard]] const char* plate_response_name(const ImpactResult& result);

/// A run that stopped at a step it could not take: its iterations stopped converging or its step turned
/// unstable (NewtonFailure), or a ply mode started in an element larger than the mode's band limit
/// (BandLimitError, `[damage] oversize = "error"`). What it computed up to the last accepted step is written
/// first (summary.json marked incomplete, its `stop_reason` the error; the report, history.csv, ...); the
/// message is the step's error and says where those results are.
class RunFailure : public std::runtime_error {
public:
  using std::runtime_error::runtime_error;
};

/// Runs the impact of `deck` on `impact`, which was built from this deck or from one with the same
/// plate and time step (its factorization is reused; the deck's impactor and contact stiffness are
/// used). Throws std::invalid_argument when the time steps differ, RunFailure (after writing) when a step
/// cannot be taken.
[[nodiscard]] ImpactRunOutcome run_impact(const Deck& deck, const ImpactCase& impact,
                                          const ImpactRunOptions& options);

} // namespace plyimpact
