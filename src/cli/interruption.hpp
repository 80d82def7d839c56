#pragma once
// Ctrl-C and SIGTERM (docs/robustness.md, "Interrupting a run"; issue 77). The first signal sets a flag
// that the runs poll at every step: an impact stops after the step it is in and writes what it computed
// (complete: false), a sweep records no case it had not finished, so --resume runs it. Whatever the
// program is doing — a pre-check, gmsh meshing, one long step, gnuplot drawing — it ends within a second:
// a watchdog thread wakes on the signal, gives that cooperative path `interruption_grace` to end, then ends
// the process with exit 130. Results are written atomically (temporary name, then rename), so what was
// written stays whole; the children (gmsh, gnuplot) die with the process (PR_SET_PDEATHSIG). A second
// signal ends the process at once.
#include <atomic>
#include <chrono>

namespace plyimpact::cli {

/// The exit code of an interrupted command (128 + SIGINT, as a shell reports it).
inline constexpr int exit_interrupted = 130;

/// How long the watchdog lets a run stop by itself before it ends the process.
inline constexpr std::chrono::milliseconds interruption_grace{800};

/// Installs the handlers of SIGINT and SIGTERM and starts the watchdog. Once, first thing in main().
void handle_interruptions();

/// Set by the first SIGINT or SIGTERM.
[[nodiscard]] const std::atomic<bool>& interrupted();

} // namespace plyimpact::cli
