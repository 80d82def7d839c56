// plyimpact._core: the library's facade for Python (pybind11). The Pythonic layer,
// python/plyimpact/__init__.py, builds on these few functions; nothing here re-implements the engine:
// a deck is parsed by the deck parser, an impact runs through io/run/impact_run.hpp exactly as the
// `impact` command runs it, and the summary is the JSON of summary.json.
//
// The GIL is released while the C++ engine runs, so Python threads can run cases side by side.
#include "plyimpact/analysis/impact/impact_case.hpp"
#include "plyimpact/analysis/impact/recorders.hpp"
#include "plyimpact/io/deck/case_from_deck.hpp"
#include "plyimpact/io/deck/deck.hpp"
#include "plyimpact/io/deck/json_text.hpp"
#include "plyimpact/io/results/history_csv.hpp"
#include "plyimpact/io/results/laminate_report.hpp"
#include "plyimpact/io/results/output_folder.hpp"
#include "plyimpact/io/run/impact_run.hpp"
#include "plyimpact/io/run/plate_analyses.hpp"
#include "plyimpact/io/sweeps/sweep_runner.hpp"
#include "plyimpact/io/sweeps/sweep_spec.hpp"
#include "plyimpact/io/sweeps/threshold_run.hpp"
#include "plyimpact/io/system/memory_estimate.hpp"

#include <fmt/format.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <atomic>
#include <chrono>
#include <exception>
#include <fstream>
#include <iterator>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <thread>
#include <utility>
#include <vector>

namespace py = pybind11;

namespace {

using plyimpact::Deck;

/// One row per recorded step, the columns of history.csv (io/results/history_csv.hpp).
py::array_t<double> history_array(const std::vector<plyimpact::ImpactSample>& samples, std::size_t columns) {
  py::array_t<double> a({samples.size(), columns});
  auto m = a.mutable_unchecked<2>();
  for (std::size_t i = 0; i < samples.size(); ++i) {
    std::size_t j = 0;
    plyimpact::for_each_history_value(samples[i], [&](double v) {
      if (j < columns) m(i, j) = v;
      ++j;
    });
    if (j != columns) throw std::logic_error("history row of another length than its header");
  }
  return a;
}

struct ImpactRunOutput {
  std::string summary_json;
  std::vector<std::string> notes;
  std::vector<plyimpact::ImpactSample> samples;
  plyimpact::HistoryLayout layout;
};

/// An impact run of `deck`, as `plyimpact impact DECK [-o DIR]` runs it (without the progress display).
/// `threads`: --threads (0: the deck's [run] threads, else the module's OpenMP setting).
ImpactRunOutput run_impact(const Deck& deck, const std::optional<std::filesystem::path>& output_dir,
                           bool overwrite, bool nonlinear, bool keep_history, int threads,
                           const std::atomic<bool>* cancel) {
  if (threads < 0 || threads > plyimpact::max_run_threads)
    throw std::invalid_argument(fmt::format("impact: threads must lie between 1 and {}, got {}",
                                            plyimpact::max_run_threads, threads));
  plyimpact::require_sections(deck, plyimpact::AnalysisKind::impact);
  // The case first: it refuses a mesh beyond the memory available before a folder is claimed.
  const plyimpact::ImpactCase impact(plyimpact::impact_case_description(deck, nonlinear));
  std::optional<plyimpact::OutputLock> lock;
  if (output_dir)
    lock.emplace(plyimpact::claim_output_folder(*output_dir, "python: plyimpact.impact",
                                                plyimpact::ClaimOptions{overwrite, {}}));
  plyimpact::HistoryRecorder history(deck.history_every);
  plyimpact::ImpactRunOptions options;
  if (lock) options.output_dir = lock->dir();
  if (keep_history) options.observers.push_back(&history);
  options.cancel = cancel;
  options.threads = threads;
  plyimpact::ImpactRunOutcome run = plyimpact::run_impact(deck, impact, options);
  ImpactRunOutput out;
  out.summary_json = plyimpact::json_text(run.summary);
  out.notes = std::move(run.notes);
  out.samples = std::move(history.samples());
  out.layout = std::move(run.history_layout);
  return out;
}

/// `work()` on a thread of its own while the caller's thread, the interpreter's, checks every 20 ms for
/// Ctrl-C (Python runs its signal handlers only there): at the first, `cancel` is set, the run finishes its
/// step and returns what it computed, and the result says it was interrupted. Exceptions of `work` are
/// rethrown here. The GIL is held by neither while they wait.
template <class Work>
auto interruptible(std::atomic<bool>& cancel, bool& interrupted, const Work& work) -> decltype(work()) {
  decltype(work()) result{};
  std::exception_ptr error;
  std::atomic<bool> done{false};
  {
    const py::gil_scoped_release release;
    std::thread worker([&] {
      try {
        result = work();
      } catch (...) {
        error = std::current_exception();
      }
      done = true;
    });
    while (!done) {
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
      const py::gil_scoped_acquire acquire;
      if (PyErr_CheckSignals() != 0) { // KeyboardInterrupt (or another handler's exception): stop the run
        PyErr_Clear();
        interrupted = true;
        cancel = true;
      }
    }
    worker.join();
  }
  if (error && interrupted) { // the work stopped on `cancel` by throwing: Python's KeyboardInterrupt
    PyErr_SetString(PyExc_KeyboardInterrupt, "plyimpact: interrupted (Ctrl-C)");
    throw py::error_already_set();
  }
  if (error) std::rethrow_exception(error);
  return result;
}

/// The threshold search of `plyimpact threshold DECK [--criterion C] [--tolerance T]`: its summary.json
/// (without the wall time).
std::string run_threshold(const Deck& deck, const std::string& criterion_name, double tolerance,
                          bool nonlinear, const std::atomic<bool>* cancel) {
  plyimpact::require_sections(deck, plyimpact::AnalysisKind::threshold);
  const plyimpact::ImpactCaseDescription description = plyimpact::impact_case_description(deck, nonlinear);
  const plyimpact::ThresholdCriterion criterion =
      plyimpact::threshold_criterion(deck, criterion_name, "criterion");
  const plyimpact::ThresholdOptions options = plyimpact::threshold_options(deck, tolerance);
  const plyimpact::ImpactCase impact(description);
  const plyimpact::ThresholdResult r = plyimpact::search_threshold(impact, criterion, options, cancel);
  return plyimpact::json_text(plyimpact::threshold_summary_json(deck, criterion, options, r));
}

/// `plyimpact static|modal|buckling DECK [-o DIR]`: (what the command prints, summary.json text).
std::pair<std::string, std::string> run_plate_analysis(const Deck& deck, const std::string& kind,
                                                       const std::optional<std::filesystem::path>& output_dir,
                                                       bool overwrite, bool nonlinear) {
  const auto analysis = plyimpact::parse_analysis_kind(kind);
  if (!analysis ||
      (*analysis != plyimpact::AnalysisKind::static_ && *analysis != plyimpact::AnalysisKind::modal &&
       *analysis != plyimpact::AnalysisKind::buckling))
    throw std::invalid_argument("analysis '" + kind + "': expected 'static', 'modal' or 'buckling'");
  plyimpact::require_sections(deck, *analysis);
  plyimpact::check_deck_fits_memory(deck);
  std::optional<plyimpact::OutputLock> lock;
  std::optional<plyimpact::ResultsFolder> folder;
  if (output_dir) {
    lock.emplace(plyimpact::claim_output_folder(*output_dir, "python: plyimpact." + kind,
                                                plyimpact::ClaimOptions{overwrite, {}}));
    folder.emplace(lock->dir(), deck);
  }
  const plyimpact::AnalysisOutcome out =
      *analysis == plyimpact::AnalysisKind::static_ ? plyimpact::run_static_analysis(deck, nonlinear, folder)
      : *analysis == plyimpact::AnalysisKind::modal ? plyimpact::run_modal_analysis(deck, folder)
                                                    : plyimpact::run_buckling_analysis(deck, folder);
  return {out.text, plyimpact::json_text(out.summary)};
}

struct SweepOutput {
  std::string table_csv; ///< sweep.csv (empty when cases are missing)
  int factorizations = 0;
  std::size_t missing = 0, failed = 0;
};

/// `plyimpact sweep DECK --set … -o DIR --jobs N` on threads (MPI stays with the command line): the same
/// folder, records and table.
SweepOutput run_sweep(const Deck& deck, const std::vector<std::string>& set_options, const std::string& mode,
                      const std::filesystem::path& dir, int jobs, bool overwrite,
                      const std::atomic<bool>* cancel) {
  if (jobs < 1 || jobs > plyimpact::max_sweep_jobs) // before the folder is claimed
    throw py::value_error(
        fmt::format("jobs must lie between 1 and {} threads, got {}", plyimpact::max_sweep_jobs, jobs));
  const plyimpact::Sweep sweep = plyimpact::Sweep::from_text(
      deck.text, deck.source, set_options,
      mode.empty()
          ? std::nullopt
          : std::optional(mode == "zip" ? plyimpact::SweepMode::zip : plyimpact::SweepMode::product));
  const plyimpact::SweepFolder folder(dir, sweep);
  plyimpact::ClaimOptions claim{overwrite, {}};
  if (!overwrite) claim.keep = plyimpact::SweepFolder::resumable_results();
  const plyimpact::OutputLock lock = plyimpact::claim_output_folder(dir, "python: plyimpact.sweep", claim);
  (void)folder.check(/*resume=*/true);
  folder.write_manifest();
  const std::vector<std::size_t> pending = folder.pending();
  std::atomic<std::size_t> position{0};
  const plyimpact::NextCase next = [&]() -> std::optional<std::size_t> {
    const std::size_t i = position++;
    return i < pending.size() ? std::optional(i) : std::nullopt;
  };
  SweepOutput out;
  plyimpact::SweepOptions options;
  options.cancel = cancel;
  out.factorizations = plyimpact::run_sweep_cases(sweep, folder, pending, jobs, next, options);
  const plyimpact::SweepFolder::TableStatus status = folder.write_table();
  out.missing = status.missing;
  out.failed = status.failed;
  if (status.missing == 0) {
    std::ifstream table(dir / "sweep.csv");
    out.table_csv.assign(std::istreambuf_iterator<char>(table), std::istreambuf_iterator<char>());
  }
  return out;
}

/// A plate built once (its matrices, factorization and, for a linear plate under a point load, its
/// impulse response at the impact point) and run for decks that differ only in the impactor and contact.k:
/// the engine's ImpactCase, without history or output folder.
class ImpactStudy {
public:
  ImpactStudy(const Deck& deck, bool nonlinear) {
    plyimpact::require_sections(deck, plyimpact::AnalysisKind::impact);
    case_ = std::make_unique<plyimpact::ImpactCase>(plyimpact::impact_case_description(deck, nonlinear));
  }

  /// summary.json's text of `deck` run on this plate, with "plate_response" added.
  [[nodiscard]] std::string run(const Deck& deck) const {
    plyimpact::ImpactRunOptions options;
    options.history = false;
    options.contact_point_response = true;
    const plyimpact::ImpactRunOutcome out = plyimpact::run_impact(deck, *case_, options);
    nlohmann::json summary = out.summary;
    summary["plate_response"] = plyimpact::plate_response_name(out.result);
    return plyimpact::json_text(summary);
  }

private:
  std::unique_ptr<plyimpact::ImpactCase> case_;
};

} // namespace

PYBIND11_MODULE(_core, m) {
  m.doc() = "plyimpact's C++ engine (use the plyimpact package, not this module)";
  m.attr("__version__") = PLYIMPACT_VERSION;
  py::register_exception<plyimpact::DeckError>(m, "DeckError", PyExc_ValueError);
  py::register_exception<plyimpact::FolderInUse>(m, "FolderInUse", PyExc_RuntimeError);
  py::register_exception<plyimpact::FolderHoldsResults>(m, "FolderHoldsResults", PyExc_FileExistsError);

  py::class_<Deck, std::shared_ptr<Deck>>(m, "Deck", "A parsed, validated deck (SI inside)")
      .def_property_readonly("source", [](const Deck& d) { return d.source; })
      .def_property_readonly("text", [](const Deck& d) { return d.text; })
      .def_property_readonly("title", [](const Deck& d) { return d.title; })
      .def_property_readonly("analysis",
                             [](const Deck& d) { return std::string(plyimpact::to_string(d.analysis)); })
      .def_property_readonly("warnings", [](const Deck& d) { return d.warnings; })
      .def_property_readonly("nonlinear", [](const Deck& d) { return d.nonlinear; });

  m.def(
      "load_deck",
      [](const std::filesystem::path& path) { return std::make_shared<Deck>(plyimpact::load_deck(path)); },
      py::arg("path"), "Reads and validates a deck file; raises DeckError with file:line:column.");
  m.def(
      "parse_deck",
      [](const std::string& text, const std::string& source) {
        return std::make_shared<Deck>(plyimpact::parse_deck(text, source));
      },
      py::arg("text"), py::arg("source"), "Validates deck text; `source` names it in messages.");
  m.def(
      "laminate_json",
      [](const Deck& deck) {
        plyimpact::require_sections(deck, plyimpact::AnalysisKind::laminate);
        return plyimpact::laminate_report_json(deck);
      },
      py::arg("deck"), "The JSON of `plyimpact laminate DECK --json`.");
  m.def(
      "run_impact",
      [](const Deck& deck, const std::optional<std::filesystem::path>& output_dir, bool overwrite,
         bool nonlinear, bool keep_history, int threads) {
        std::atomic<bool> cancel{false};
        bool interrupted = false;
        ImpactRunOutput out = interruptible(cancel, interrupted, [&] {
          return run_impact(deck, output_dir, overwrite, nonlinear, keep_history, threads, &cancel);
        });
        const std::vector<std::string> columns = plyimpact::history_columns(out.layout);
        return py::make_tuple(out.summary_json, out.notes, columns,
                              history_array(out.samples, columns.size()), interrupted);
      },
      py::arg("deck"), py::arg("output_dir") = py::none(), py::arg("overwrite") = false,
      py::arg("nonlinear") = false, py::arg("history") = true, py::arg("threads") = 0,
      "Runs the deck's impact (threads: of the element loops, 0 for the deck's); returns (summary JSON text, "
      "notes, history column names, history rows, "
      "whether Ctrl-C stopped it).");
  py::class_<ImpactStudy>(m, "ImpactStudy", "A plate built once, run for many impactors")
      .def(py::init([](const Deck& deck, bool nonlinear) {
             const py::gil_scoped_release release;
             return std::make_unique<ImpactStudy>(deck, nonlinear);
           }),
           py::arg("deck"), py::arg("nonlinear") = false)
      .def(
          "run",
          [](const ImpactStudy& study, const Deck& deck) {
            const py::gil_scoped_release release;
            return study.run(deck);
          },
          py::arg("deck"), "summary.json text of `deck`'s impactor on the study's plate");
  m.def(
      "run_plate_analysis",
      [](const Deck& deck, const std::string& kind, const std::optional<std::filesystem::path>& output_dir,
         bool overwrite, bool nonlinear) {
        const py::gil_scoped_release release;
        return run_plate_analysis(deck, kind, output_dir, overwrite, nonlinear);
      },
      py::arg("deck"), py::arg("kind"), py::arg("output_dir") = py::none(), py::arg("overwrite") = false,
      py::arg("nonlinear") = false,
      "A static, modal or buckling analysis; returns (the command's printed text, summary.json text).");
  m.def(
      "run_threshold",
      [](const Deck& deck, const std::string& criterion, double tolerance, bool nonlinear) {
        std::atomic<bool> cancel{false};
        bool interrupted = false;
        return interruptible(cancel, interrupted,
                             [&] { return run_threshold(deck, criterion, tolerance, nonlinear, &cancel); });
      },
      py::arg("deck"), py::arg("criterion") = "", py::arg("tolerance") = 0.0, py::arg("nonlinear") = false,
      "The threshold search of the deck; returns its summary.json text (without wall_time).");
  m.def(
      "run_sweep",
      [](const Deck& deck, const std::vector<std::string>& set_options, const std::string& mode,
         const std::filesystem::path& dir, int jobs, bool overwrite) {
        std::atomic<bool> cancel{false};
        bool interrupted = false;
        const SweepOutput out = interruptible(cancel, interrupted, [&] {
          return run_sweep(deck, set_options, mode, dir, jobs, overwrite, &cancel);
        });
        return py::make_tuple(out.table_csv, out.factorizations, out.missing, out.failed, interrupted);
      },
      py::arg("deck"), py::arg("set_options"), py::arg("mode"), py::arg("output_dir"), py::arg("jobs"),
      py::arg("overwrite") = false,
      "Runs a sweep on threads into output_dir (resuming its records); returns (sweep.csv text, "
      "factorizations, cases without a record, failed cases, whether Ctrl-C stopped it).");
}
