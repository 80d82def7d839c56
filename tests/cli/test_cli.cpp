// The command line: every analysis writes DIR/summary.json with the SPEC §10 keys; bad decks exit
// non-zero with the file:line:column message.
#include "plyimpact/analysis/impact/capabilities.hpp"
#include "support/cli.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>
#include <sys/wait.h>
#include <unistd.h>

namespace cli_tests {

namespace {

using namespace plyimpact::test;

TEST(Cli, ImpactWritesHistoryAndSummaryWithTheSpecKeys) {
  const fs::path dir = scratch("impact");
  const fs::path deck = write(dir, small_deck("impact", steel_ball_impactor("dt = 1e-6\n")));
  const CommandResult r = run("impact " + deck.string() + " -o " + (dir / "out").string());
  ASSERT_EQ(r.status, 0) << r.out;
  EXPECT_NE(r.out.find("peak force"), std::string::npos);
  const auto j = read_json(dir / "out" / "summary.json");
  for (const char* key :
       {"peak_force", "time_of_peak_force", "contact_duration", "episodes", "peak_contact_deflection",
        "max_indentation", "permanent_indentation", "rebound_velocity", "absorbed_energy", "contacts",
        "steps", "complete", "wall_time"})
    EXPECT_TRUE(j.contains(key)) << key;
  EXPECT_TRUE(j["complete"].get<bool>());
  EXPECT_GT(j["peak_force"].get<double>(), 0.0);
  std::ifstream csv(dir / "out" / "history.csv");
  std::string header;
  std::getline(csv, header);
  EXPECT_EQ(header, "t_s,force_N,impactor_w_m,impactor_v_m_per_s,plate_w_m,indentation_m,plate_kinetic_J,"
                    "plate_strain_J,impactor_energy_J,contact_work_J");
  EXPECT_TRUE(fs::exists(dir / "out" / "deck.toml"));
  EXPECT_TRUE(fs::exists(dir / "out" / "provenance.json"));
}

// provenance.json and report.html name the commit the program was built from, as --version prints it
// (issue 82): a result can be traced to its sources.
TEST(Cli, TheResultsNameTheCommitThatVersionPrints) {
  const CommandResult version = run("--version");
  ASSERT_EQ(version.status, 0) << version.out;
  const std::size_t open = version.out.find("(commit "), close = version.out.find(')', open);
  ASSERT_NE(open, std::string::npos) << version.out;
  const std::string commit = version.out.substr(open + 8, close - open - 8);
  ASSERT_FALSE(commit.empty());
  const fs::path dir = scratch("commit");
  const fs::path deck = write(dir, small_deck("impact", steel_ball_impactor("dt = 1e-6\n")));
  const CommandResult r = run("impact " + deck.string() + " -o " + (dir / "out").string());
  ASSERT_EQ(r.status, 0) << r.out;
  EXPECT_EQ(read_json(dir / "out" / "provenance.json").at("commit").get<std::string>(), commit);
  EXPECT_NE(read_text(dir / "out" / "report.html").find("(commit " + commit + ")"), std::string::npos);
}

TEST(Cli, ADeckAloneRunsItsOwnAnalysis) {
  const fs::path dir = scratch("default");
  const fs::path deck = write(dir, small_deck("modal", "[modal]\ncount = 3\n"));
  const CommandResult r = run(deck.string() + " -o " + (dir / "out").string());
  ASSERT_EQ(r.status, 0) << r.out;
  EXPECT_EQ(read_json(dir / "out" / "summary.json")["analysis"], "modal");
}

// `plyimpact capabilities` prints the one table of what runs and its restrictions, as the code has them
// (issue 78): what docs/deck.md holds too.
TEST(Cli, CapabilitiesPrintsTheTableOfWhatRunsAndItsRestrictions) {
  const CommandResult r = run("capabilities");
  ASSERT_EQ(r.status, 0) << r.out;
  EXPECT_NE(r.out.find(plyimpact::capability_table_markdown()), std::string::npos) << r.out;
  EXPECT_NE(r.out.find(plyimpact::restrictions_markdown()), std::string::npos) << r.out;
}

TEST(Cli, StaticModalBucklingSummariesCarryTheirKeys) {
  const fs::path dir = scratch("fem");
  const fs::path deck = write(dir, small_deck("static", R"(
[load]
pressure = 1e5
point = { x = 0.0635, y = 0.0381, force = 100.0 }
[modal]
count = 4
[buckling]
Nx = -1e5
count = 2
)"));
  for (const std::string analysis : {"static", "modal", "buckling"}) {
    const CommandResult r = run(analysis + " " + deck.string() + " -o " + (dir / analysis).string());
    ASSERT_EQ(r.status, 0) << analysis << ": " << r.out;
  }
  const auto s = read_json(dir / "static" / "summary.json");
  EXPECT_GT(s["center_deflection"].get<double>(), 0.0); // load along +z deflects along +z
  EXPECT_TRUE(s.contains("load_point_deflection"));
  EXPECT_TRUE(s.contains("max_abs_deflection"));
  const auto m = read_json(dir / "modal" / "summary.json");
  const auto f = m["frequencies_hz"].get<std::vector<double>>();
  ASSERT_EQ(f.size(), 4U);
  EXPECT_TRUE(std::is_sorted(f.begin(), f.end()));
  const auto b = read_json(dir / "buckling" / "summary.json");
  EXPECT_EQ(b["load_factors"].size(), 2U);
  EXPECT_TRUE(fs::exists(dir / "static" / "displacements.csv"));
}

TEST(Cli, LaminateJsonHasTheScriptKeys) {
  const CommandResult r =
      run("laminate --json " + std::string(PLYIMPACT_SOURCE_DIR) + "/examples/annex2.toml");
  ASSERT_EQ(r.status, 0) << r.out;
  const auto j = nlohmann::json::parse(r.out);
  for (const char* key : {"thickness", "plies", "A", "B", "D", "F", "inertia", "hertz_k"})
    EXPECT_TRUE(j.contains(key)) << key;
  EXPECT_NEAR(j["A"][0][0].get<double>(), 2.8901e8, 0.0001e8);
  EXPECT_EQ(j["plies"].size(), 8U);
  EXPECT_NEAR(j["hertz_k"].get<double>(), 0.98218e9, 0.00001e9);
}

TEST(Cli, BadDeckExitsNonZeroWithTheLocation) {
  const fs::path dir = scratch("bad");
  const fs::path deck = write(dir, "analysis = \"impact\"\n[plate]\na = -1\nb = 1\n");
  const CommandResult r = run("impact " + deck.string());
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.out.find("deck.toml:3:5: error: plate.a must be positive"), std::string::npos) << r.out;
  EXPECT_NE(run("impact /nonexistent.toml").status, 0);
}

TEST(Cli, SigintFinishesTheStepAndWritesConsistentPartialResults) {
  const fs::path dir = scratch("sigint");
  // 2 000 000 steps of 1 us on a 6 x 4 mesh: far longer than the test waits. The signal is sent once
  // history.csv holds 100 rows, so the time loop is running whatever the build (a fixed delay raced
  // with start-up under the sanitizers and with the end of the run in the release build).
  const fs::path deck = write(dir, long_impact_deck());
  const fs::path out = dir / "out";
  const pid_t pid = start_impact(deck, out, true);
  ASSERT_GE(pid, 0);
  const auto newlines = [](const std::string& text) {
    return static_cast<std::size_t>(std::count(text.begin(), text.end(), '\n'));
  };
  const std::size_t rows_seen =
      newlines(wait_for_text(out / "history.csv", [&](const std::string& t) { return newlines(t) >= 100; }));
  ::kill(pid, SIGINT);
  int status = 0;
  ::waitpid(pid, &status, 0);
  ASSERT_TRUE(WIFEXITED(status)) << "the interrupted run was killed by the signal instead of ending its step";
  EXPECT_EQ(WEXITSTATUS(status), 130);
  const auto j = read_json(out / "summary.json");
  EXPECT_FALSE(j["complete"].get<bool>());
  std::ifstream csv(out / "history.csv");
  std::string line;
  std::size_t rows = 0;
  while (std::getline(csv, line)) {
    EXPECT_EQ(std::count(line.begin(), line.end(), ','), 9) << line; // every row complete
    ++rows;
  }
  EXPECT_GE(rows, rows_seen);
  EXPECT_EQ(rows, j["steps"].get<std::size_t>() + 2); // header + t = 0 + one row per step
}

TEST(Cli, ImpactAndThresholdShowProgressWithAnEtaInLogsAndNothingWhenQuiet) {
  const fs::path dir = scratch("progress");
  const std::string deck = std::string(PLYIMPACT_SOURCE_DIR) + "/examples/thesis-3.6-v268.toml";
  // stderr is a pipe here, as in a CI or cluster log: plain lines, every update with --progress-every 0.
  const CommandResult r = run("impact " + deck + " -o " + (dir / "lines").string() + " --progress-every 0");
  ASSERT_EQ(r.status, 0) << r.out;
  EXPECT_NE(r.out.find("impact:  50 % (t = "), std::string::npos) << r.out;
  EXPECT_NE(r.out.find(" ms, step "), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("elapsed, ETA "), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("impact: 8626 steps to t = 8.626 ms, "), std::string::npos) << r.out;
  const CommandResult quiet =
      run("impact " + deck + " -o " + (dir / "quiet").string() + " --progress-every 0 -q");
  ASSERT_EQ(quiet.status, 0) << quiet.out;
  EXPECT_EQ(quiet.out.find("ETA"), std::string::npos) << quiet.out;
  const std::string threshold =
      std::string(PLYIMPACT_SOURCE_DIR) + "/examples/thesis-4.3-threshold-0_2-90_2-0_2.toml";
  const CommandResult t =
      run("threshold " + threshold + " -o " + (dir / "threshold").string() + " --progress-every 0");
  ASSERT_EQ(t.status, 0) << t.out;
  EXPECT_NE(t.out.find("threshold:   0 % (trial 1: v = "), std::string::npos) << t.out;
  EXPECT_NE(t.out.find("threshold: 100 % (trial "), std::string::npos) << t.out;
}

TEST(Cli, AMisspeltCriterionOnTheCommandLineGetsADidYouMean) {
  const CommandResult r =
      run("threshold " + std::string(PLYIMPACT_SOURCE_DIR) +
          "/examples/thesis-4.3-threshold-0_2-90_2-0_2.toml --criterion choi-chang-matrx");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(
      r.out.find("--criterion: unknown criterion \"choi-chang-matrx\" (did you mean \"choi-chang-matrix\"?)"),
      std::string::npos)
      << r.out;
}

TEST(Cli, ADamageCriterionOnAnOnsetDeckSaysToSetTheProgressiveModel) {
  const CommandResult r = run("threshold " + std::string(PLYIMPACT_SOURCE_DIR) +
                              "/examples/thesis-4.3-threshold-0_2-90_2-0_2.toml --criterion matrix-damage");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.out.find("criterion \"matrix-damage\" looks for ply damage, which only the progressive damage "
                       "model computes: set [damage] model = \"progressive\""),
            std::string::npos)
      << r.out;
  const CommandResult area = run("threshold " + std::string(PLYIMPACT_SOURCE_DIR) +
                                 "/examples/threshold-matrix-damage.toml --criterion damage-area");
  EXPECT_EQ(area.status, 2);
  EXPECT_NE(area.out.find("criterion \"damage-area\" needs [threshold] damage_area"), std::string::npos)
      << area.out;
}

TEST(Cli, UnrestrainedStaticPlateIsAClearErrorNotNaN) {
  const fs::path dir = scratch("free");
  std::string text = small_deck("static", "[load]\npressure = 1e5\n");
  for (const char* e : {"x0", "xa", "y0", "yb"}) {
    const std::string from = std::string(e) + " = \"ss\"";
    text.replace(text.find(from), from.size(), std::string(e) + " = \"free\"");
  }
  const CommandResult r = run("static " + write(dir, text).string() + " -o " + (dir / "out").string());
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.out.find("insufficient restraint"), std::string::npos) << r.out;
  EXPECT_EQ(r.out.find("nan"), std::string::npos);
}

TEST(Cli, GuardsWarnInTheSummaryAndRefuseWhatCannotBeComputed) {
  // docs/robustness.md. The centre of the 6 x 4 mesh is an element corner, and Δt = 20 µs gives 25
  // steps over the Hertz contact time (0.50 ms): two warnings, on stderr and in summary.json.
  const fs::path dir = scratch("guards");
  const std::string impact = R"([impactor]
mass = 0.314
radius = 6.35e-3
E = 207e9
velocity = 2.92
[contact]
k = 0.6e9
load = "point"
[time]
dt = 2e-5
end = 1e-4
)";
  const fs::path deck = write(dir, small_deck("impact", impact));
  const CommandResult ok = run("impact " + deck.string() + " -o " + (dir / "out").string());
  EXPECT_EQ(ok.status, 0) << ok.out;
  EXPECT_NE(ok.out.find("plyimpact: warning: time.dt = 2e-05 s gives only 25."), std::string::npos) << ok.out;
  EXPECT_NE(ok.out.find("plyimpact: warning: the impact point (0.0635, 0.0381) m lies on an element corner"),
            std::string::npos)
      << ok.out;
  const auto warnings = read_json(dir / "out" / "summary.json")["warnings"];
  ASSERT_EQ(warnings.size(), 4U);
  EXPECT_NE(warnings[0].get<std::string>().find("(t_c/50)"), std::string::npos);
  EXPECT_NE(warnings[2].get<std::string>().find("the contact is not resolved"), std::string::npos);
  // end = 0.1 ms comes before the end of the 0.5 ms contact (test_honest_summary.cpp).
  EXPECT_NE(warnings[3].get<std::string>().find("is still in contact"), std::string::npos);

  // The memory limit (overridden by the environment) refuses the factorization with the estimate.
  // (the mesh's estimate, io/system/memory_estimate.hpp, refuses it before assembly)
  const std::string limited = "PLYIMPACT_MEMORY_LIMIT_BYTES=1000 " + std::string(PLYIMPACT_EXE) + " impact " +
                              deck.string() + " -o " + (dir / "mem").string() + " > " +
                              (dir / "mem.txt").string() + " 2>&1";
  const int status = std::system(limited.c_str());
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 1);
  std::ifstream mem_txt(dir / "mem.txt");
  const std::string mem_out((std::istreambuf_iterator<char>(mem_txt)), std::istreambuf_iterator<char>());
  EXPECT_NE(
      mem_out.find("a 6 x 4 mesh (585 equations) needs about 0.00228 GB for the stiffness, mass and factor "
                   "(4.94e+04 non-zeros in the factor) but this machine has 1e-06 GB available"),
      std::string::npos)
      << mem_out;

  // An impact velocity of 1e300 m/s overflows the contact force in the first step: stopped, named.
  std::string absurd = impact;
  absurd.replace(absurd.find("velocity = 2.92"), 15, "velocity = 1e300");
  const CommandResult nan =
      run("impact " + write(dir, small_deck("impact", absurd)).string() + " -o " + (dir / "nan").string());
  EXPECT_EQ(nan.status, 1);
  EXPECT_NE(nan.out.find("non-finite contact force Fc [N] at step 1 (t = 2e-05 s)"), std::string::npos)
      << nan.out;
}

TEST(Cli, AnUnknownCommandIsNamedWithTheValidOnesAndExits2) {
  // Not a command, not a file, not a .toml: named, with a near command when there is one (exit 2 as
  // for other usage errors; before: CLI11's exit 109 "The following argument was not expected").
  const CommandResult slip = run("impactt examples/annex2.toml");
  EXPECT_EQ(slip.status, 2) << slip.out;
  EXPECT_EQ(slip.out,
            "plyimpact: error: unknown command 'impactt' (did you mean 'impact'?); the commands are "
            "laminate, static, modal, buckling, impact, threshold, plot, sweep, capabilities, materials, "
            "init, preview, schema "
            "(plyimpact --help), "
            "or give a deck file: plyimpact DECK.toml\n");
  const CommandResult other = run("frobnicate");
  EXPECT_EQ(other.status, 2) << other.out;
  EXPECT_NE(other.out.find("plyimpact: error: unknown command 'frobnicate'; the commands are laminate,"),
            std::string::npos)
      << other.out;
  // A missing deck is still a deck error, named as such.
  const CommandResult missing = run("no-such-deck.toml");
  EXPECT_EQ(missing.status, 2) << missing.out;
  EXPECT_NE(missing.out.find("no-such-deck.toml: error: cannot open the deck file"), std::string::npos)
      << missing.out;
}

} // namespace

namespace {

// Command-line values are checked like deck values: a message naming the option and exit 2, never a
// silent replacement (threshold --tolerance -1 became 0.01) or an abort (--jobs 100000).

TEST(CliOptions, AThresholdToleranceThatIsNotAPositiveNumberIsRefused) {
  for (const char* bad : {"-1", "0", "nan", "inf", "1e-3x"}) {
    const plyimpact::test::CommandResult r = plyimpact::test::run(
        std::string("threshold ") + PLYIMPACT_SOURCE_DIR + "/examples/thesis-4.3.toml --tolerance " + bad);
    EXPECT_EQ(r.status, 2) << bad << "\n" << r.out;
    EXPECT_NE(r.out.find("--tolerance: must be a positive number (the bracket width in m/s), got"),
              std::string::npos)
        << r.out;
  }
}

TEST(CliOptions, ASweepThreadCountOutsideItsRangeIsRefused) {
  for (const char* bad : {"0", "-3", "100000"}) {
    const plyimpact::test::CommandResult r = plyimpact::test::run(
        std::string("sweep ") + PLYIMPACT_SOURCE_DIR + "/examples/sweep-4.2-velocity.toml --jobs " + bad);
    EXPECT_EQ(r.status, 2) << bad << "\n" << r.out;
    EXPECT_NE(r.out.find("--jobs"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("not in range 1 to 1024"), std::string::npos) << r.out;
  }
}

} // namespace

namespace {

TEST(CliVersion, SaysTheVersionAndTheCommitItWasBuiltFrom) {
  // A bug report needs the commit, not just 0.1.0 (cmake/commit.cmake; "unknown" outside git).
  const plyimpact::test::CommandResult r = plyimpact::test::run("--version");
  EXPECT_EQ(r.status, 0);
  EXPECT_EQ(r.out.rfind(std::string("plyimpact ") + PLYIMPACT_VERSION + " (commit ", 0), 0U) << r.out;
  const std::string commit =
      r.out.substr(r.out.find("(commit ") + 8, r.out.find(')') - r.out.find("(commit ") - 8);
  const bool hex = commit.size() >= 12 && commit.find_first_not_of("0123456789abcdef") >= 12;
  EXPECT_TRUE(hex || commit == "unknown") << commit;
}

} // namespace

} // namespace cli_tests
