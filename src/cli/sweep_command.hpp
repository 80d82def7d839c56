#pragma once
// `plyimpact sweep DECK -o DIR`: parameter studies on all cores (--jobs) and across machines
// (mpirun/srun, docs/cluster.md), resumable (--resume). See docs/sweep.md.
#include "plyimpact/io/run/progress.hpp"

#include <CLI/CLI.hpp>

#include <atomic>
#include <string>
#include <vector>

namespace plyimpact {

struct SweepCommandOptions {
  std::string deck_path;
  std::string output_dir;
  std::vector<std::string> set; ///< KEY=V1,V2,… or KEY=start:stop:count
  std::string mode;             ///< product | zip (default: [sweep] mode, else product)
  std::string analysis;         ///< impact | threshold (default: [sweep] analysis, else the deck's)
  int jobs = 0;                 ///< threads per process; 0: all cores (1 per rank under MPI)
  bool resume = false;
  bool overwrite = false; ///< replace another run's results (another sweep's too) in the folder
  std::string command;    ///< this command line, recorded in the folder's lock
  bool case_folders = false;
  bool no_sharing = false; ///< factor K̄ for every case (benchmarks)
  bool strict = false;     ///< refuse the sweep when any case's deck has a plausibility warning
  ProgressSettings progress;
};

/// --quiet and --progress-every on a subcommand (impact, threshold, sweep).
void add_progress_options(CLI::App& sub, ProgressSettings& progress);

CLI::App* add_sweep_command(CLI::App& app, SweepCommandOptions& o);

/// Runs the sweep; `interrupted` is set by SIGINT/SIGTERM. Exit codes: 0 table written, 3 cases
/// missing (a worker could not finish), 130 interrupted. Throws DeckError for a bad deck or spec.
int run_sweep_command(const SweepCommandOptions& o, const std::atomic<bool>& interrupted);

} // namespace plyimpact
