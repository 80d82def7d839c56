// plyimpact — low-velocity impact of laminated composite plates.
//
//   plyimpact impact   examples/thesis-3.6-v268.toml -o results/v268   # the default analysis
//   plyimpact laminate examples/annex2.toml          # ABD, F, inertias, Hertz constant
//   plyimpact laminate examples/annex2.toml --json   # the same as JSON (SI)
//   plyimpact static   examples/static-annex2-loads.toml -o results/static
//   plyimpact modal    examples/modal-annex2.toml -o results/modal
//   plyimpact buckling examples/buckling-annex2.toml -o results/buckling
#include "interruption.hpp"
#include "plyimpact/analysis/fields/damage_tracker.hpp"
#include "plyimpact/analysis/impact/capabilities.hpp"
#include "plyimpact/analysis/impact/impact_case.hpp"
#include "plyimpact/analysis/thresholds/threshold_search.hpp"
#include "plyimpact/io/deck/case_from_deck.hpp"
#include "plyimpact/io/deck/deck.hpp"
#include "plyimpact/io/deck/deck_schema.hpp"
#include "plyimpact/io/deck/material_library.hpp"
#include "plyimpact/io/deck/starting_deck.hpp"
#include "plyimpact/io/results/damage_report.hpp"
#include "plyimpact/io/results/history_check.hpp"
#include "plyimpact/io/results/impact_report.hpp"
#include "plyimpact/io/results/laminate_report.hpp"
#include "plyimpact/io/results/output_folder.hpp"
#include "plyimpact/io/results/plots.hpp"
#include "plyimpact/io/results/results.hpp"
#include "plyimpact/io/results/summary_keys.hpp"
#include "plyimpact/io/run/deck_preview.hpp"
#include "plyimpact/io/run/impact_progress.hpp"
#include "plyimpact/io/run/impact_run.hpp"
#include "plyimpact/io/run/plate_analyses.hpp"
#include "plyimpact/io/run/progress.hpp"
#include "plyimpact/io/sweeps/threshold_run.hpp"
#include "plyimpact/io/system/atomic_file.hpp"
#include "plyimpact/io/system/build_info.hpp"
#include "plyimpact/io/system/environment.hpp"
#include "plyimpact/io/system/memory_estimate.hpp"
#include "sweep_command.hpp"

#include <CLI/CLI.hpp>
#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <limits>
#include <new>
#include <optional>
#include <stdexcept>
#include <string>
#include <typeinfo>

namespace {

/// Exit code of an internal error (docs/robustness.md): 1 is a run that failed, 2 a bad deck or command
/// line, 130 an interrupt.
constexpr int exit_internal_error = 4;
constexpr const char* report_internal_error =
    "This is a bug in plyimpact, not in your deck: please report it with the deck and the command "
    "(docs/robustness.md, \"Exit codes\")";

/// A command-line value that must be a positive, finite number (NaN, inf, 0 and negatives refused with
/// what the value is).
CLI::Validator positive_finite(const std::string& what) {
  return {[what](const std::string& text) -> std::string {
            if (plyimpact::positive_number(text)) return "";
            return "must be a positive number (" + what + "), got " + text;
          },
          "POSITIVE"};
}

using namespace plyimpact;

struct Options {
  std::string deck_path;
  std::string output_dir;
  bool json = false;
  std::string criterion;
  double tolerance = 0.0;
  bool nonlinear = false; ///< --nonlinear (or the deck's top-level nonlinear = true)
  ProgressSettings progress;
  bool strict = false;    ///< --strict: plausibility warnings of the deck are errors
  bool overwrite = false; ///< --overwrite: replace another run's results in the folder
  std::string command;    ///< this command line, recorded in the folder's lock
  int threads = 0;        ///< --threads: the run's element loops (0: all cores)
};

/// The deck, checked for the sections of `analysis` (none: the deck's own) and for the memory its mesh needs
/// (before assembly); prints its plausibility warnings (docs/deck.md) and refuses it under --strict.
Deck read_deck_for(const Options& o, std::optional<AnalysisKind> analysis) {
  Deck deck = load_deck(o.deck_path);
  const AnalysisKind kind = analysis.value_or(deck.analysis);
  require_sections(deck, kind);
  for (const std::string& w : deck.warnings)
    fmt::print(stderr, "{}: {}: {}\n", deck.source, o.strict ? "error" : "warning", w);
  if (o.strict && !deck.warnings.empty())
    throw DeckError(fmt::format("{}: error: {} implausible value{} refused by --strict (fix the deck, or run "
                                "without --strict to see the results anyway)",
                                deck.source, deck.warnings.size(), deck.warnings.size() == 1 ? "" : "s"));
  // The plate analyses' mesh; an impact's is checked where the deck becomes its case.
  if (kind == AnalysisKind::static_ || kind == AnalysisKind::modal || kind == AnalysisKind::buckling)
    check_deck_fits_memory(deck);
  return deck;
}

/// The results folder of this run (-o, else <[output] dir>/<deck name>/), locked for the run and
/// cleared of another run's results (--overwrite) or refused (io/results/output_folder.hpp). Says where.
OutputLock claim_folder(const Options& o, const Deck& deck) {
  const std::filesystem::path dir = o.output_dir.empty() ? default_output_dir(deck.output_dir, o.deck_path)
                                                         : std::filesystem::path(o.output_dir);
  OutputLock lock = claim_output_folder(dir, o.command, ClaimOptions{o.overwrite, {}});
  fmt::print("results: {}\n", dir.string());
  std::fflush(stdout);
  return lock;
}

std::optional<ResultsFolder> results_folder(const OutputLock& lock, const Deck& deck) {
  return ResultsFolder(lock.dir(), deck);
}

int run_laminate(const Options& o) {
  const Deck deck = read_deck_for(o, AnalysisKind::laminate);
  fmt::print("{}", o.json ? laminate_report_json(deck) : laminate_report_text(deck));
  return 0;
}

/// Prints what the analysis has to say; the command then exits with 0.
int finish(const AnalysisOutcome& outcome) {
  fmt::print("{}", outcome.text);
  return 0;
}

int run_static(const Options& o) {
  const Deck deck = read_deck_for(o, AnalysisKind::static_);
  const OutputLock lock = claim_folder(o, deck);
  return finish(run_static_analysis(deck, o.nonlinear, results_folder(lock, deck)));
}

int run_modal(const Options& o) {
  const Deck deck = read_deck_for(o, AnalysisKind::modal);
  const OutputLock lock = claim_folder(o, deck);
  return finish(run_modal_analysis(deck, results_folder(lock, deck)));
}

int run_buckling(const Options& o) {
  const Deck deck = read_deck_for(o, AnalysisKind::buckling);
  const OutputLock lock = claim_folder(o, deck);
  return finish(run_buckling_analysis(deck, results_folder(lock, deck)));
}

int run_impact(const Options& o) {
  const Deck deck = read_deck_for(o, AnalysisKind::impact);
  // The case first: it refuses a mesh beyond the memory available before a folder is claimed.
  const ImpactCase impact(impact_case_description(deck, o.nonlinear));
  const OutputLock lock = claim_folder(o, deck);
  ImpactRunOptions options;
  options.output_dir = lock.dir();
  options.cancel = &cli::interrupted();
  options.threads = o.threads;
  ImpactProgress progress(impact.settings(), impact.fundamental_period(), progress_style(o.progress, stderr),
                          o.progress.line_interval_s);
  options.observers = {&progress};
  const ImpactRunOutcome run = run_impact(deck, impact, options);
  const ImpactResult& r = run.result;
  if (impact.settings().nonlinear && impact.settings().integration == Integrator::central_difference)
    fmt::print("non-linear ({}): explicit central differences, {} steps, nothing factored\n",
               to_string(impact.settings().nonlinear->measure), r.steps);
  else if (r.newton && impact.settings().nonlinear)
    fmt::print("non-linear ({}): {} Newton iterations in {} steps ({:.2f} per step, at most {}), {} "
               "factorizations of K_T + c0 M\n",
               to_string(impact.settings().nonlinear->measure), r.newton->iterations, r.steps,
               static_cast<double>(r.newton->iterations) / static_cast<double>(std::max(1L, r.steps)),
               r.newton->max_iterations_per_step, r.newton->factorizations);
  if (!deck.rig_description.empty()) fmt::print("rig: {}\n", deck.rig_description);
  fmt::print("{}", impact_summary_text(run.settings, r));
  for (const std::string& w : r.warnings) // also in summary.json "warnings" (docs/robustness.md)
    fmt::print(stderr, "plyimpact: warning: {}\n", w);
  for (const std::string& n : run.notes)
    fmt::print(stderr, "plyimpact: warning: {}\n", n);
  if (run.damage_tracked)
    fmt::print("first failures (per criterion, mode and ply/interface):\n{}",
               first_failures_text(run.first_failures, run.clamp_tip_elements, run.laminate_first_failure));
  if (cli::interrupted().load()) return cli::exit_interrupted;
  return r.stop_reason.empty() ? 0 : 3; // 3: stopped early; a run cut short by time.end only warns
}

/// `plyimpact preview DECK [-o DIR]`: the model before its run — the plan of the mesh with supports, rig and
/// impact point, the ply stack, and the settings the run would use (io/run/deck_preview.hpp).
int run_preview(const Options& o) {
  const Deck deck = read_deck_for(o, std::nullopt);
  const ModelPreview preview = deck_preview(deck, o.nonlinear);
  const std::filesystem::path dir =
      o.output_dir.empty()
          ? std::filesystem::path(default_output_dir(deck.output_dir, o.deck_path).string() + "-preview")
          : std::filesystem::path(o.output_dir);
  const ModelPreviewFiles files = write_model_preview(dir, preview);
  fmt::print("{}\n", preview.settings);
  if (!files.warning.empty()) fmt::print(stderr, "plyimpact: warning: {}\n", files.warning);
  fmt::print("preview: {}\n", (dir / "preview.html").string());
  for (const auto& f : files.written)
    if (f.extension() == ".png") fmt::print("picture: {}\n", f.string());
  return 0;
}

/// `plyimpact plot DIR... [-o OUT]`: PNG and SVG pictures of one run, or overlays of several.
int run_plot(const std::vector<std::string>& dirs, const std::string& output_dir) {
  const std::filesystem::path out =
      !output_dir.empty() ? std::filesystem::path(output_dir) : std::filesystem::path(dirs.front()) / "plots";
  std::vector<PlotRun> runs;
  for (std::size_t i = 0; i < dirs.size(); ++i) {
    const std::filesystem::path history = std::filesystem::path(dirs[i]) / "history.csv";
    if (!std::filesystem::exists(history))
      throw HistoryFileError(fmt::format(
          "{0}: not an impact results folder (no history.csv; run plyimpact impact DECK -o {0})", dirs[i]));
    // a regular file of well-formed rows, thinned where gnuplot would take minutes
    // (io/results/history_check.hpp)
    const CheckedHistory checked =
        check_history_for_plot(history, out / fmt::format("history-{}.thinned.csv", i + 1));
    if (checked.plotted < checked.rows)
      fmt::print(stderr,
                 "plyimpact: note: {}: {} rows, drawn from {} of them (every peak of the force kept)\n",
                 history.string(), checked.rows, checked.plotted);
    runs.push_back({dirs[i], run_label(dirs[i]), checked.file});
  }
  const PlotFiles files = draw_plots(impact_plots(runs), out);
  for (const auto& f : files.images)
    fmt::print("{}\n", f.string());
  return 0;
}

int run_threshold(const Options& o) {
  const Deck deck = read_deck_for(o, AnalysisKind::threshold);
  const ThresholdCriterion criterion = threshold_criterion(deck, o.criterion);
  ThresholdOptions options = threshold_options(deck, o.tolerance);
  const auto t0 = std::chrono::steady_clock::now();
  // The case first: it refuses a mesh beyond the memory available before a folder is claimed.
  const ImpactCase impact(impact_case_description(deck, o.nonlinear));
  const OutputLock lock = claim_folder(o, deck);
  Progress progress("threshold", 1.0, progress_style(o.progress, stderr), o.progress.line_interval_s);
  options.on_trial = [&](const std::vector<ThresholdTrial>& trials) {
    const ThresholdTrial& t = trials.back();
    progress.update(bracket_progress(trials, options.tolerance),
                    fmt::format("trial {}: v = {:.4g} m/s {}", trials.size(), t.velocity,
                                t.failed             ? std::string("fails")
                                : t.peak_index > 0.0 ? fmt::format("holds, peak index {:.3f}", t.peak_index)
                                                     : std::string("holds")));
  };
  const ThresholdResult r = search_threshold(impact, criterion, options);
  progress.finish(fmt::format("{} trials", r.trials.size()));
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  fmt::print("{}", threshold_text(criterion.name, r));
  if (const auto out = results_folder(lock, deck)) {
    nlohmann::json j = threshold_summary_json(deck, criterion, options, r);
    j["wall_time"] = wall;
    out->write_summary(j);
  }
  return 0; // no failure up to the limit is a result (threshold_velocity null), not an error
}

/// `plyimpact capabilities`: the table of what runs and its restrictions, as docs/deck.md has them.
int print_capabilities() {
  fmt::print("What runs: plate models x time integrators ([time], [damage] and [delamination] "
             "integration)\n\n{}\nWhat the models and integrators restrict (after each, the deck key that is "
             "refused):\n\n{}",
             capability_table_markdown(), restrictions_markdown());
  return 0;
}

/// `plyimpact materials [CARD] [--toml]`: the material library's cards with their sources (docs/deck.md,
/// "Material library"); one card with its values; or the library as TOML.
int print_materials(const std::string& card, bool as_toml) {
  if (as_toml) {
    fmt::print("{}", material_library_toml());
    return 0;
  }
  const toml::table library = material_library();
  if (!card.empty() && !library.contains(card)) {
    fmt::print(stderr, "plyimpact: error: no card '{}' in the material library (cards: {})\n", card,
               fmt::join(material_library_names(), ", "));
    return 2;
  }
  if (card.empty())
    fmt::print("Material library: a deck takes a card with [materials.NAME] library = \"CARD\"; its own keys "
               "replace the card's (docs/deck.md).\n\n");
  for (auto&& [name, node] : library) {
    if (!card.empty() && name.str() != card) continue;
    const toml::table& t = *node.as_table();
    fmt::print("{}\n  source: {}\n", name.str(), t[library_source_key].value_or(std::string_view{}));
    if (const auto note = t[library_note_key].value<std::string_view>()) fmt::print("  note: {}\n", *note);
    if (card.empty()) continue;
    for (auto&& [key, value] : t)
      if (const std::string_view unit = material_key_unit(key.str()); !unit.empty())
        fmt::print("  {:<15} {:>12.6g} {}\n", key.str(), value.value_or(0.0), unit);
  }
  return 0;
}

/// `plyimpact init [FILE] [--rig R] [--material CARD]`: a commented starting deck (docs/deck.md).
int write_starting_deck(const std::string& path, const StartingDeckChoice& choice, bool overwrite) {
  std::string text;
  try {
    text = starting_deck(choice);
  } catch (const std::invalid_argument& e) { // a slip on the command line: a usage error
    fmt::print(stderr, "plyimpact: error: {}\n", e.what());
    return 2;
  }
  if (path.empty()) {
    fmt::print("{}", text);
    return 0;
  }
  if (std::filesystem::exists(path) && !overwrite) {
    fmt::print(stderr, "plyimpact: error: {} exists: give another name, or --overwrite to replace it\n",
               path);
    return 2;
  }
  write_file_atomically(path, text);
  fmt::print("{}: a starting deck ({} rig, {}); run it with: plyimpact impact {}\n", path, choice.rig,
             choice.material, path);
  return 0;
}

CLI::App* add_analysis(CLI::App& app, const std::string& name, const std::string& what, Options& o) {
  CLI::App* sub = app.add_subcommand(name, what);
  sub->add_option("deck", o.deck_path, "TOML input deck")->required();
  sub->add_option("-o,--output", o.output_dir,
                  "results folder (default: <[output] dir>/<deck name>, i.e. results/<deck name>)");
  sub->add_flag("--overwrite", o.overwrite, "replace the results of another run in the folder");
  sub->add_flag("--strict", o.strict,
                "treat the deck's plausibility warnings (values that look like unit slips) as errors");
  return sub;
}

const std::vector<std::string>& command_names() {
  static const std::vector<std::string> names{"laminate",  "static",  "modal", "buckling",     "impact",
                                              "threshold", "plot",    "sweep", "capabilities", "materials",
                                              "init",      "preview", "schema"};
  return names;
}

/// A first argument that is neither a command nor a deck (no such file, no .toml): its name, a
/// command it may be a slip for, and the valid commands.
std::optional<std::string> unknown_command(const std::vector<std::string>& args) {
  const std::vector<std::string>& commands = command_names();
  if (args.empty() || args[0].empty() || args[0][0] == '-' ||
      std::find(commands.begin(), commands.end(), args[0]) != commands.end() || args[0].ends_with(".toml") ||
      std::filesystem::exists(args[0]))
    return std::nullopt;
  std::string list;
  for (const std::string& c : commands)
    list += (list.empty() ? "" : ", ") + c;
  const auto slip = std::find_if(commands.begin(), commands.end(), [&](const std::string& c) {
    return args[0].starts_with(c.substr(0, 3)) || c.starts_with(args[0].substr(0, 3));
  });
  return fmt::format("plyimpact: error: unknown command '{}'{}; the commands are {} (plyimpact --help), or "
                     "give a deck file: plyimpact DECK.toml",
                     args[0], slip != commands.end() ? fmt::format(" (did you mean '{}'?)", *slip) : "",
                     list);
}

/// `plyimpact DECK [options]` runs the deck's own `analysis` (impact by default).
std::vector<std::string> with_default_command(int argc, char** argv) {
  std::vector<std::string> args(argv + 1, argv + argc);
  const std::vector<std::string>& commands = command_names();
  if (args.empty() || args[0].empty() || args[0][0] == '-' ||
      std::find(commands.begin(), commands.end(), args[0]) != commands.end())
    return args;
  std::string command = "impact";
  try {
    command = std::string(to_string(load_deck(args[0]).analysis));
  } catch (const DeckError&) {
    // reported with file, line and column when the impact command reads the deck
  }
  args.insert(args.begin(), command);
  return args;
}

int run(int argc, char** argv) {
  CLI::App app{"plyimpact: low-velocity impact analysis of laminated composite plates\n"
               "  plyimpact DECK [-o DIR] runs the deck's analysis (impact by default)"};
  app.set_version_flag(
      "--version", fmt::format("plyimpact {} (commit {})", PLYIMPACT_VERSION, plyimpact::source_commit()));
  app.require_subcommand(1);
  Options o;
  o.command = command_line(argc, argv);
  CLI::App* laminate =
      app.add_subcommand("laminate", "Ply and laminate properties (A, B, D, F, inertias, Hertz k)");
  laminate->add_option("deck", o.deck_path, "TOML input deck")->required();
  laminate->add_flag("--json", o.json, "print JSON (SI units) instead of text");
  laminate->add_flag("--strict", o.strict, "treat the deck's plausibility warnings (unit slips) as errors");
  CLI::App* impact =
      add_analysis(app, "impact", "Impact of a rigid sphere: contact force, deflection, energies", o);
  impact
      ->add_option("--threads", o.threads,
                   "threads of the element loops (ply damage); the results are the same bits for any "
                   "number (default: the deck's [run] threads, else all cores or OMP_NUM_THREADS)")
      ->check(CLI::Range(1, max_run_threads));
  CLI::App* threshold = add_analysis(
      app, "threshold",
      "Smallest impact velocity at which a failure criterion first reaches 1 (or, with progressive "
      "damage, the plies are damaged)",
      o);
  threshold->add_option("--criterion", o.criterion,
                        "criterion name (default: [threshold] or the first [damage] one)");
  threshold->add_option("--tolerance", o.tolerance, "bracket width in m/s (default 0.01)")
      ->check(positive_finite("the bracket width in m/s"));
  CLI::App* stat = add_analysis(app, "static", "Static analysis (point, patch, pressure loads)", o);
  for (CLI::App* sub : {impact, stat, threshold})
    sub->add_flag("--nonlinear", o.nonlinear,
                  "large deflections: geometrically non-linear plate (or nonlinear = true in the deck)");
  for (CLI::App* sub : {impact, threshold})
    add_progress_options(*sub, o.progress);
  CLI::App* modal = add_analysis(app, "modal", "Natural frequencies and mode shapes", o);
  CLI::App* buckling = add_analysis(app, "buckling", "Linear buckling under in-plane loads", o);
  CLI::App* preview = app.add_subcommand(
      "preview",
      "The model before its run: mesh, supports, rig, impact point, ply stack and the settings the "
      "run would use (preview.html, preview.png); nothing is solved");
  preview->add_option("deck", o.deck_path, "TOML input deck")->required();
  preview->add_option("-o,--output", o.output_dir,
                      "folder for the preview (default: <[output] dir>/<deck name>-preview)");
  preview->add_flag("--nonlinear", o.nonlinear, "preview the large-deflection (non-linear) plate");
  preview->add_flag("--strict", o.strict, "treat the deck's plausibility warnings (unit slips) as errors");
  std::string schema_of = "deck";
  CLI::App* schema = app.add_subcommand(
      "schema", "The JSON Schema of a deck (for editors that complete and check TOML) or of summary.json "
                "(docs/schemas.md)");
  schema->add_option("of", schema_of, "deck (the default) or summary")
      ->check(CLI::IsMember({"deck", "summary"}));
  std::vector<std::string> plot_dirs;
  CLI::App* plot =
      app.add_subcommand("plot", "PNG and SVG plots of impact results (several folders: overlaid curves)");
  plot->add_option("results", plot_dirs, "impact results folder(s) written with -o")->required();
  plot->add_option("-o,--output", o.output_dir, "folder for the pictures (default: RESULTS/plots)");
  CLI::App* capabilities = app.add_subcommand(
      "capabilities", "What runs: plate models × time integrators, and the options they restrict");
  std::string material_card;
  bool materials_toml = false;
  CLI::App* materials =
      app.add_subcommand("materials", "The material library: ply cards with their sources, usable by name");
  materials->add_option("card", material_card, "one card to show with its values");
  materials->add_flag("--toml", materials_toml, "print the whole library as TOML (SI units)");
  std::string init_path;
  StartingDeckChoice init_choice;
  CLI::App* init =
      app.add_subcommand("init", "Write a commented starting deck: a coupon rig and a library material");
  init->add_option("file", init_path, "the deck to write (default: print it)");
  init->add_option("--rig", init_choice.rig, "astm-d7136 or aitm-1-0010 (default)");
  init->add_option("--material", init_choice.material, "a card of `plyimpact materials` (default T300-976)");
  init->add_flag("--overwrite", o.overwrite, "replace the file if it exists");
  SweepCommandOptions sweep_options;
  sweep_options.command = o.command;
  CLI::App* sweep = add_sweep_command(app, sweep_options);

  if (const auto message = unknown_command({argv + std::min(argc, 1), argv + argc})) {
    fmt::print(stderr, "{}\n", *message);
    return 2;
  }
  try {
    std::vector<std::string> args = with_default_command(argc, argv);
    std::reverse(args.begin(), args.end()); // CLI11 takes the arguments in reverse order
    app.parse(args);
  } catch (const CLI::ParseError& e) {
    // --help and --version exit 0; a bad command line exits 2, as a bad deck does (docs/robustness.md)
    if (e.get_exit_code() == 0) return app.exit(e);
    fmt::print(stderr, "plyimpact: error: {}\nRun with --help for more information.\n", e.what());
    return 2;
  }
  try {
    if (const auto note = check_openmp_threads()) fmt::print(stderr, "plyimpact: note: {}\n", *note);
    if (*capabilities) return print_capabilities();
    if (*materials) return print_materials(material_card, materials_toml);
    if (*init) return write_starting_deck(init_path, init_choice, o.overwrite);
    if (*laminate) return run_laminate(o);
    if (*impact) return run_impact(o);
    if (*threshold) return run_threshold(o);
    if (*stat) return run_static(o);
    if (*modal) return run_modal(o);
    if (*buckling) return run_buckling(o);
    if (*plot) return run_plot(plot_dirs, o.output_dir);
    if (*preview) return run_preview(o);
    if (*schema) {
      fmt::print("{}\n", (schema_of == "summary" ? summary_json_schema() : deck_json_schema()).dump(2));
      return 0;
    }
    if (*sweep) return run_sweep_command(sweep_options, cli::interrupted());
  } catch (const DeckError& e) {
    fmt::print(stderr, "{}\n", e.what());
    return 2;
  } catch (const HistoryFileError& e) { // a results folder given to plot is input, like a deck
    fmt::print(stderr, "{}\n", e.what());
    return 2;
  } catch (const EnvironmentValueError& e) { // a bad setting of the user's, like a bad option
    fmt::print(stderr, "plyimpact: error: {}\n", e.what());
    return 2;
  } catch (const std::bad_alloc&) {
    fmt::print(stderr, "plyimpact: error: out of memory: the run needed more memory than this machine could "
                       "give (std::bad_alloc); use a coarser mesh ([mesh] nx, ny) or a machine with more "
                       "memory (docs/robustness.md)\n");
    return 1;
  } catch (const std::exception& e) {
    if (typeid(e) == typeid(std::logic_error)) { // a broken invariant of the program, not of the input
      fmt::print(stderr, "plyimpact: internal error: {}\n{}\n", e.what(), report_internal_error);
      return exit_internal_error;
    }
    fmt::print(stderr, "plyimpact: error: {}\n", e.what());
    return 1;
  }
  return 0;
}

/// What escapes every handler (an exception of no std::exception type, or one thrown where nothing can
/// catch it): a message and exit code 4, never an abort's core dump and exit 134.
[[noreturn]] void on_terminate() {
  std::fputs("plyimpact: internal error: an exception escaped every handler\n", stderr);
  std::fputs(report_internal_error, stderr);
  std::fputs("\n", stderr);
  std::_Exit(exit_internal_error);
}

} // namespace

int main(int argc, char** argv) {
  std::set_terminate(on_terminate);
  cli::handle_interruptions(); // first: an interrupt during set-up ends as one during the run (exit 130)
  try {
    const int code = run(argc, argv);
    // whatever a step, gmsh or gnuplot made of the signal (an error, a cut-short run), it is an interrupt
    return cli::interrupted().load() ? cli::exit_interrupted : code;
  } catch (...) { // nothing in plyimpact throws a type not derived from std::exception (Exceptions.*)
    std::fputs("plyimpact: internal error: an exception that is not a std::exception\n", stderr);
    std::fputs(report_internal_error, stderr);
    std::fputs("\n", stderr);
    return exit_internal_error;
  }
}
