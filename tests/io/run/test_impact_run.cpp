// The outputs of a progressive-damage impact run (io/run/impact_run): the ParaView frames and
// damage_elements.csv hold the plies' damage of the run itself — the last frame and the file equal the
// result's element_ply_damage value for value, elements the run never lists are zero, and damage_max is
// the largest over plies and modes — on the shipped example examples/damage-progressive.toml; a run's
// element loops get the deck's [run] threads unless the caller gives its own.
#include "plyimpact/analysis/plate_analyses/nonlinear_static.hpp"
#include "plyimpact/fem/element_loop.hpp"
#include "plyimpact/io/deck/case_from_deck.hpp"
#include "plyimpact/io/deck/deck.hpp"
#include "plyimpact/io/results/ply_damage_maps.hpp"
#include "plyimpact/io/run/impact_run.hpp"
#include "support/impact_decks.hpp"
#include "test_paths.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkNew.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLDataElement.h>
#include <vtkXMLDataParser.h>
#include <vtkXMLUnstructuredGridReader.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>

namespace plyimpact::impact_run_tests {
namespace {

namespace fs = std::filesystem;

vtkSmartPointer<vtkUnstructuredGrid> read_vtu(const fs::path& file) {
  vtkNew<vtkXMLUnstructuredGridReader> reader;
  reader->SetFileName(file.string().c_str());
  reader->Update();
  return reader->GetOutput();
}

/// The files of a .pvd collection, in order.
std::vector<std::string> pvd_files(const fs::path& pvd) {
  vtkNew<vtkXMLDataParser> parser;
  parser->SetFileName(pvd.string().c_str());
  EXPECT_EQ(parser->Parse(), 1);
  vtkXMLDataElement* collection = parser->GetRootElement()->FindNestedElementWithName("Collection");
  std::vector<std::string> files;
  for (int i = 0; collection != nullptr && i < collection->GetNumberOfNestedElements(); ++i)
    files.emplace_back(collection->GetNestedElement(i)->GetAttribute("file"));
  return files;
}

/// Options that write a run's results, without the gnuplot maps, into the empty folder `name` under the
/// system's temporary folder.
ImpactRunOptions into_scratch(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / name;
  fs::remove_all(dir);
  ImpactRunOptions options;
  options.output_dir = dir;
  options.pictures = false;
  return options;
}

/// The threads the element loops of the run's steps are given (element_threads() on the run's thread).
class ThreadsSeen final : public ImpactObserver {
public:
  void on_step(const StepView& /*view*/) override { seen = element_threads(); }
  int seen = 0;
};

TEST(ImpactRun, TheElementLoopsRunOnTheDecksThreadsUnlessTheCallerGivesOthers) {
  // [run] threads = 3 reaches the run, capped to the machine's cores (issue 77); --threads
  // (ImpactRunOptions::threads) overrides it; after the run the calling thread's setting is what it was.
  const int before = element_threads();
  const Deck deck =
      parse_deck(test::with_key(test::example_text("damage-progressive.toml"), "end", "1.4e-5") +
                     "\n[run]\nthreads = 3\n",
                 "threads.toml");
  EXPECT_EQ(deck.threads, 3);
  const ImpactCase impact(impact_case_description(deck));
  for (const int given : {0, 1}) {
    ThreadsSeen threads;
    ImpactRunOptions options;
    options.threads = given;
    options.observers = {&threads};
    (void)run_impact(deck, impact, options);
    EXPECT_EQ(threads.seen, given > 0 ? given : std::min(3, hardware_threads()));
    EXPECT_EQ(element_threads(), before);
  }
}

/// What a run that fails at a step left: the error's message, and the folder it wrote before failing.
struct FailedRun {
  std::string what;
  fs::path dir;
  nlohmann::json summary;
  long history_rows = 0; ///< history.csv's lines after the header
};

/// Runs `text` into a scratch folder `name`, expecting RunFailure.
FailedRun failing_run(const std::string& text, const std::string& name) {
  const Deck deck = parse_deck(text, name + ".toml");
  const ImpactCase impact(impact_case_description(deck));
  const ImpactRunOptions options = into_scratch(name);
  FailedRun run;
  run.dir = *options.output_dir;
  try {
    (void)run_impact(deck, impact, options);
    ADD_FAILURE() << "expected RunFailure";
  } catch (const RunFailure& e) {
    run.what = e.what();
  }
  std::ifstream in(run.dir / "summary.json");
  EXPECT_TRUE(in.good()) << "no summary.json in " << run.dir;
  if (in.good()) run.summary = nlohmann::json::parse(in);
  std::ifstream history(run.dir / "history.csv");
  run.history_rows = -1; // the header
  for (std::string line; std::getline(history, line);)
    ++run.history_rows;
  return run;
}

/// The folder of a failed run holds the results up to its last accepted step, summary.json marked
/// incomplete with the error as stop_reason (`error_says` in both), and the message names the folder.
void expect_written_before_failing(const FailedRun& run, const std::string& error_says) {
  EXPECT_NE(run.what.find(error_says), std::string::npos) << run.what;
  EXPECT_NE(run.what.find(run.dir.string()), std::string::npos) << run.what;
  ASSERT_TRUE(run.summary.is_object());
  EXPECT_FALSE(run.summary["complete"].get<bool>());
  EXPECT_NE(run.summary["stop_reason"].get<std::string>().find(error_says), std::string::npos);
  const long steps = run.summary["steps"].get<long>();
  EXPECT_GT(steps, 0);
  EXPECT_TRUE(fs::exists(run.dir / "report.html"));
  EXPECT_EQ(run.history_rows, steps + 1); // t = 0 and every accepted step
}

TEST(ImpactRun, ARunWhoseStepCannotBeSolvedWritesWhatItComputedAndThenFails) {
  // At 3 m/s and 1.75 µs many points soften at once and the iterated secant stops converging
  // (test_progressive_impact.cpp): the results up to the last accepted step are written, summary.json
  // last and marked incomplete, and the run then ends in the solver's error naming the folder.
  const std::string text =
      test::with_key(test::with_key(test::example_text("damage-progressive-lagged.toml"), "dt", "1.75e-6"),
                     "integration", "\"implicit\"");
  expect_written_before_failing(failing_run(text, "plyimpact-failed-run"), "progressive damage:");
}

TEST(ImpactRun, ARunStoppedByTheBandLimitWritesWhatItComputedAndThenFails) {
  // examples/damage-progressive-explicit.toml's 1.7 mm elements lie above the band limit of its matrix
  // modes (its deck lowers their strengths: oversize = "reduce-strength"). Without that, the first mode to
  // start there stops the run (oversize = "error"): what the steps before it computed is written,
  // summary.json marked incomplete with the law's message, and the run then fails naming the folder.
  const std::string text =
      test::with_key(test::example_text("damage-progressive-explicit.toml"), "oversize", "\"error\"");
  const FailedRun run = failing_run(text, "plyimpact-band-limit-run");
  expect_written_before_failing(run, "exceeds the band limit of mode");
  EXPECT_NE(run.summary["incomplete_reason"].get<std::string>().find("band limit"), std::string::npos);
  EXPECT_GT(run.summary["peak_force"].get<double>(), 0.0); // the contact had begun: a real part of the event
}

TEST(ImpactRun, ProgressiveRunWritesTheResultsPlyDamageToTheLastFrameAndToDamageElementsCsv) {
  const Deck deck = parse_deck(test::example_text("damage-progressive.toml") + "[output]\nvtk_every = 100\n",
                               "damage-progressive.toml");
  const ImpactCase impact(impact_case_description(deck));
  const ImpactRunOptions options = into_scratch("plyimpact-impact-run-progressive");
  const fs::path dir = *options.output_dir;
  const ImpactRunOutcome out = run_impact(deck, impact, options);
  ASSERT_TRUE(out.result.progressive.has_value());
  const std::vector<ElementPlyDamage>& list = out.result.progressive->element_ply_damage;
  const int elements = 144, plies = 4; // 12 × 12 mesh, [0/90]s
  // (element, ply) → damage of the run; the projected value per element.
  std::map<std::pair<int, int>, PerDamageMode> listed;
  std::vector<double> projected(elements, 0.0);
  double largest = 0.0;
  for (const ElementPlyDamage& d : list) {
    listed[{d.element, d.ply}] = d.damage;
    for (const double v : d.damage.values) {
      projected[std::size_t(d.element)] = std::max(projected[std::size_t(d.element)], v);
      largest = std::max(largest, v);
    }
  }
  ASSERT_GT(largest, 0.5); // the example cracks ply 4 (projected damage area 12.6 mm²)

  const auto frames = pvd_files(dir / "plate.pvd");
  ASSERT_GE(frames.size(), 3U); // t = 0, every 100 steps, the last step
  const auto last = read_vtu(dir / frames.back());
  vtkCellData& cells = *last->GetCellData();
  const std::array<const char*, 4> names{"d_ft", "d_fc", "d_mt", "d_mc"};
  int nonzero = 0;
  for (int k = 0; k < plies; ++k)
    for (std::size_t m = 0; m < 4; ++m) {
      vtkDataArray* a = cells.GetArray(fmt::format("ply{}_{}", k + 1, names[m]).c_str());
      ASSERT_NE(a, nullptr) << k << names[m];
      for (int e = 0; e < elements; ++e) {
        const auto it = listed.find({e, k});
        const double expected = it == listed.end() ? 0.0 : it->second.values[m];
        EXPECT_EQ(a->GetTuple1(e), expected) << "ply " << k + 1 << " " << names[m] << " element " << e;
        nonzero += expected > 0.0 ? 1 : 0;
      }
    }
  EXPECT_GT(nonzero, 0);
  vtkDataArray* damage_max = cells.GetArray("damage_max");
  ASSERT_NE(damage_max, nullptr);
  for (int e = 0; e < elements; ++e)
    EXPECT_EQ(damage_max->GetTuple1(e), projected[std::size_t(e)]) << "element " << e;
  // The first frame (t = 0, before any step) has the arrays, all zero.
  const auto first_frame = read_vtu(dir / frames.front());
  vtkDataArray* first = first_frame->GetCellData()->GetArray("damage_max");
  ASSERT_NE(first, nullptr);
  for (int e = 0; e < elements; ++e)
    EXPECT_EQ(first->GetTuple1(e), 0.0);

  // damage_elements.csv: one row per element and ply, the run's values (shortest text reads back exactly).
  const auto rows = read_damage_elements_csv(dir / damage_elements_file);
  ASSERT_EQ(rows.size(), std::size_t(elements * plies));
  for (const DamageElementRow& r : rows) {
    const auto it = listed.find({r.element - 1, r.ply - 1});
    for (std::size_t m = 0; m < 4; ++m)
      EXPECT_EQ(r.damage.values[m], it == listed.end() ? 0.0 : it->second.values[m])
          << "element " << r.element << " ply " << r.ply;
  }
}

// The first load drop (analysis/thresholds/load_drop.hpp) reaches summary.json, without an output folder too:
// none for the §3.6 plate under its 6.14 kg sphere (a smooth half-sine), and for thesis §4.3's 8.4 g ball at
// 12 m/s the fall of the wave-controlled force right after its first peak (an elastic plate: a lab's F_d
// that is no damage, docs/output.md).
TEST(ImpactRun, TheFirstLoadDropReachesTheSummary) {
  const auto summary = [](const std::string& name) {
    const Deck deck = parse_deck(test::example_text(name), name);
    const ImpactCase impact(impact_case_description(deck));
    return run_impact(deck, impact, ImpactRunOptions{}).summary;
  };
  const nlohmann::json heavy = summary("thesis-3.6-v176.toml");
  EXPECT_TRUE(heavy["load_drop"]["force_N"].is_null());
  EXPECT_FALSE(heavy["load_drop"]["rule"].get<std::string>().empty());
  const nlohmann::json light = summary("thesis-4.3.toml");
  ASSERT_FALSE(light["load_drop"]["force_N"].is_null());
  EXPECT_EQ(light["load_drop"]["force_N"].get<double>(), light["peak_force"].get<double>());
  EXPECT_EQ(light["load_drop"]["time_s"].get<double>(), light["time_of_peak_force"].get<double>());
  EXPECT_GT(light["load_drop"]["detected_at_s"].get<double>(), light["time_of_peak_force"].get<double>());
}

} // namespace
} // namespace plyimpact::impact_run_tests
