// `plyimpact sweep`: the same table, byte for byte, with 1 or 2 threads and with 2 MPI ranks; a sweep
// killed part-way and resumed ends with the uninterrupted table; bad specs stop before any case runs;
// a failing case is recorded and the others run.
#include "support/cli.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>

namespace sweep_cli_tests {

namespace {

using namespace plyimpact::test;

CommandResult sweep(const std::string& args) {
  return shell("timeout 300 " + std::string(PLYIMPACT_EXE) + " sweep " + args);
}

/// A 6 x 4 simply supported [0_2/90_4/0_2] plate, 12 cases: 2 layups x 2 velocities x 3 masses.
fs::path twelve_case_deck(const fs::path& dir, const std::string& mesh = "nx = 6\nny = 4\n") {
  const fs::path p = dir / "sweep.toml";
  std::ofstream(p) << R"([materials.T300_976]
E1 = 144.8e9
E2 = 9.65e9
G12 = 7.10e9
G23 = 5.92e9
nu12 = 0.30
rho = 1389.2
[laminate]
material = "T300_976"
layup = "[0_2/90_4/0_2]"
ply_thickness = 0.465e-3
[plate]
a = 0.127
b = 0.0762
[mesh]
)" + mesh + R"([boundary]
x0 = "ss"
xa = "ss"
y0 = "ss"
yb = "ss"
[impactor]
mass = 0.314
radius = 12.7e-3
E = 207e9
velocity = 2.92
[time]
dt = 2e-6
[sweep.values]
"laminate.layup" = ["[0_2/90_4/0_2]", "[0/90]2s"]
"impactor.velocity" = [1.5, 2.92]
"impactor.mass" = "0.2:0.6:3"
)";
  return p;
}

std::vector<std::string> lines(const std::string& text) {
  std::vector<std::string> v;
  std::istringstream in(text);
  for (std::string l; std::getline(in, l);)
    v.push_back(l);
  return v;
}

TEST(SweepCli, OneThreadTwoThreadsAndTwoMpiRanksGiveTheSameTableByteForByte) {
  const fs::path dir = scratch("sweep-same");
  const fs::path deck = twelve_case_deck(dir);
  const CommandResult one = sweep(deck.string() + " -o " + (dir / "j1").string() + " --jobs 1");
  ASSERT_EQ(one.status, 0) << one.out;
  const CommandResult two = sweep(deck.string() + " -o " + (dir / "j2").string() + " --jobs 2");
  ASSERT_EQ(two.status, 0) << two.out;
  const CommandResult mpi =
      // Open MPI keeps its start-up allocations to the end: no leak report from it in sanitizer builds.
      shell("ASAN_OPTIONS=detect_leaks=0 timeout 300 mpirun --allow-run-as-root --oversubscribe -n 2 " +
            std::string(PLYIMPACT_EXE) + " sweep " + deck.string() + " -o " + (dir / "mpi").string() +
            " --jobs 1");
  ASSERT_EQ(mpi.status, 0) << mpi.out;
  EXPECT_NE(mpi.out.find("on 2 ranks x 1 thread"), std::string::npos) << mpi.out;

  const std::string table = read_text(dir / "j1" / "sweep.csv");
  const auto rows = lines(table);
  ASSERT_EQ(rows.size(), 13U) << table;
  EXPECT_TRUE(rows[0].starts_with("case,laminate.layup,impactor.velocity,impactor.mass,status,peak_force_N,"
                                  "time_of_peak_force_s,"))
      << rows[0];
  EXPECT_TRUE(rows[2].starts_with("1,[0_2/90_4/0_2],1.5,0.4,ok,")) << rows[2]; // the last key fastest
  EXPECT_TRUE(rows[12].starts_with("11,[0/90]2s,2.92,0.6,ok,")) << rows[12];
  EXPECT_EQ(read_text(dir / "j2" / "sweep.csv"), table);
  EXPECT_EQ(read_text(dir / "mpi" / "sweep.csv"), table);
  for (const auto* r : {&one, &two, &mpi})
    for (const auto& l : lines(r->out))
      if (l.find("cases run in") != std::string::npos) std::printf("  %s\n", l.c_str());
}

std::size_t records_in(const fs::path& dir) {
  std::size_t n = 0;
  std::error_code ec;
  for (const auto& e : fs::directory_iterator(dir / "cases", ec))
    if (e.path().extension() == ".json") ++n;
  return n;
}

TEST(SweepCli, KilledPartWayAndResumedEndsWithTheUninterruptedTable) {
  const fs::path dir = scratch("sweep-resume");
  const fs::path deck = twelve_case_deck(dir, "nx = 12\nny = 8\n");
  const CommandResult whole = sweep(deck.string() + " -o " + (dir / "whole").string() + " --jobs 1");
  ASSERT_EQ(whole.status, 0) << whole.out;

  const fs::path out = dir / "killed";
  const pid_t pid = ::fork();
  ASSERT_GE(pid, 0);
  if (pid == 0) {
    (void)std::freopen("/dev/null", "w", stdout);
    ::execl(PLYIMPACT_EXE, "plyimpact", "sweep", deck.c_str(), "-o", out.c_str(), "--jobs", "2",
            static_cast<char*>(nullptr));
    ::_exit(127);
  }
  std::size_t at_kill = 0;
  for (int i = 0; i < 60000 && at_kill < 3; ++i) { // at most 60 s
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
    at_kill = records_in(out);
  }
  ::kill(pid, SIGKILL);
  int status = 0;
  ::waitpid(pid, &status, 0);
  ASSERT_TRUE(WIFSIGNALED(status)) << "the sweep ended before it could be killed";
  const std::size_t survived = records_in(out);
  std::printf("  killed with %zu of 12 records\n", survived);
  ASSERT_GE(survived, 3U);
  ASSERT_LT(survived, 12U);
  EXPECT_FALSE(fs::exists(out / "sweep.csv"));

  const CommandResult again = sweep(deck.string() + " -o " + out.string()); // without --resume: refused
  EXPECT_NE(again.status, 0);
  EXPECT_NE(again.out.find("--resume"), std::string::npos) << again.out;
  const CommandResult resumed = sweep(deck.string() + " -o " + out.string() + " --resume --jobs 2");
  ASSERT_EQ(resumed.status, 0) << resumed.out;
  EXPECT_NE(resumed.out.find("sweep: 12 cases (" + std::to_string(12 - survived) + " to run)"),
            std::string::npos)
      << resumed.out;
  const std::string table = read_text(out / "sweep.csv");
  EXPECT_EQ(table, read_text(dir / "whole" / "sweep.csv"));
  std::set<std::string> ids;
  for (const auto& row : lines(table))
    ids.insert(row.substr(0, row.find(',')));
  EXPECT_EQ(ids.size(), 13U); // header + 12 distinct cases, no duplicate rows
  EXPECT_EQ(lines(table).size(), 13U);
}

TEST(SweepCli, ResumeIsRefusedWhenTheSweepChanged) {
  const fs::path dir = scratch("sweep-changed");
  const fs::path deck = twelve_case_deck(dir);
  ASSERT_EQ(sweep(deck.string() + " -o " + (dir / "out").string() + " --set impactor.mass=0.3").status, 0);
  const CommandResult r =
      sweep(deck.string() + " -o " + (dir / "out").string() + " --set impactor.mass=0.4 --resume");
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.out.find("holds another sweep"), std::string::npos) << r.out;
}

TEST(SweepCli, BadSpecsStopBeforeAnyCaseRuns) {
  const fs::path dir = scratch("sweep-bad");
  const fs::path deck = twelve_case_deck(dir);
  struct Bad {
    std::string option, message;
  };
  for (const Bad& b :
       {Bad{"--set impactor.velocty=1,2", "--set 'impactor.velocty=1,2': error: sweep key "
                                          "'impactor.velocty': unknown key 'velocty' in [impactor] "
                                          "(did you mean 'velocity'?)"},
        Bad{"--set impactor.velocity=", "--set 'impactor.velocity=': error: empty list of values"},
        Bad{"--set impactor.velocity=0.5:3.0:x", "--set 'impactor.velocity=0.5:3.0:x': error: malformed "
                                                 "range \"0.5:3.0:x\""},
        Bad{"--set plate.a=0.1,0.2 --mode zip", "zip sweep: impactor.mass has 3 values but "
                                                "laminate.layup has 2"}}) {
    const fs::path out = dir / "out";
    fs::remove_all(out);
    const CommandResult r = sweep(deck.string() + " -o " + out.string() + " " + b.option);
    EXPECT_EQ(r.status, 2) << b.option << ": " << r.out;
    EXPECT_NE(r.out.find(b.message), std::string::npos) << r.out;
    EXPECT_FALSE(fs::exists(out / "cases")) << b.option;
    EXPECT_FALSE(fs::exists(out / "sweep.json")) << b.option;
  }
}

TEST(SweepCli, AFailingCaseIsRecordedAndTheOthersRun) {
  const fs::path dir = scratch("sweep-failing");
  const fs::path deck = twelve_case_deck(dir);
  const CommandResult r = sweep(deck.string() + " -o " + (dir / "out").string() +
                                " --set impactor.velocity=1.5,-1.0,2.92 --set impactor.mass=0.3");
  ASSERT_EQ(r.status, 0) << r.out;
  EXPECT_NE(r.out.find("2 of 6 cases did not complete"), std::string::npos) << r.out;
  const auto rows = lines(read_text(dir / "out" / "sweep.csv"));
  ASSERT_EQ(rows.size(), 7U);
  int failed = 0;
  for (std::size_t i = 1; i < rows.size(); ++i) {
    if (rows[i].find(",failed,") != std::string::npos) {
      ++failed;
      EXPECT_NE(rows[i].find("impactor.velocity must be positive"), std::string::npos) << rows[i];
      EXPECT_NE(rows[i].find(",-1,"), std::string::npos) << rows[i];
    } else {
      EXPECT_NE(rows[i].find(",ok,"), std::string::npos) << rows[i];
    }
  }
  EXPECT_EQ(failed, 2); // v = -1 with each of the two layups
}

TEST(SweepCli, ASweepInWhichEveryCaseFailedExitsNonZero) {
  // A script must tell it from a good run: exit 1, the count and the first case's error; the table is
  // still written, with each case's error.
  const fs::path dir = scratch("sweep-all-failed");
  const fs::path deck = twelve_case_deck(dir);
  const CommandResult r = sweep(deck.string() + " -o " + (dir / "out").string() +
                                " --set impactor.velocity=-1.0,-2.0 --set impactor.mass=0.3 --jobs 1");
  EXPECT_EQ(r.status, 1) << r.out;
  EXPECT_NE(r.out.find("plyimpact: error: none of the 4 cases completed (status and error columns of "),
            std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("case 0: "), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("impactor.velocity must be positive"), std::string::npos) << r.out;
  const auto rows = lines(read_text(dir / "out" / "sweep.csv"));
  ASSERT_EQ(rows.size(), 5U);
  for (std::size_t i = 1; i < rows.size(); ++i)
    EXPECT_NE(rows[i].find(",failed,"), std::string::npos) << rows[i];
}

/// The field of `column` in data row `row` (1-based) of a CSV without quoted commas.
std::string field(const std::string& table, std::size_t row, const std::string& column) {
  const auto rows = lines(table);
  const auto split = [](const std::string& line) {
    std::vector<std::string> f;
    std::istringstream in(line);
    for (std::string x; std::getline(in, x, ',');)
      f.push_back(x);
    if (!line.empty() && line.back() == ',') f.emplace_back();
    return f;
  };
  const auto header = split(rows.at(0));
  const auto values = split(rows.at(row));
  const auto at = std::find(header.begin(), header.end(), column);
  return at == header.end() ? "(no column " + column + ")"
                            : values.at(static_cast<std::size_t>(at - header.begin()));
}

TEST(SweepCli, ThresholdSweepGivesTheThresholdCommandsVelocityBitForBit) {
  const fs::path dir = scratch("sweep-threshold");
  const std::string examples = std::string(PLYIMPACT_SOURCE_DIR) + "/examples/";
  const CommandResult alone = shell("timeout 300 " + std::string(PLYIMPACT_EXE) + " threshold " + examples +
                                    "thesis-4.3-threshold-0_3-90_4-0_3.toml -o " + (dir / "alone").string());
  ASSERT_EQ(alone.status, 0) << alone.out;
  const CommandResult s = sweep(examples + "sweep-4.3-threshold.toml -o " + (dir / "sweep").string() +
                                " --set laminate.layup=[0_2/90_2/0_2],[0_3/90_4/0_3]");
  ASSERT_EQ(s.status, 0) << s.out;
  const double v_alone =
      nlohmann::json::parse(read_text(dir / "alone" / "summary.json"))["threshold_velocity"].get<double>();
  const std::string table = read_text(dir / "sweep" / "sweep.csv");
  EXPECT_EQ(std::stod(field(table, 2, "threshold_velocity_m_per_s")), v_alone);
  EXPECT_EQ(field(table, 2, "first_failure_ply"), "10"); // docs/validation.md §13, Table 4.4
  EXPECT_EQ(field(table, 1, "first_failure_ply"), "6");
  std::printf("  [0_3/90_4/0_3]: threshold %s m/s (threshold command %.17g); [0_2/90_2/0_2]: %s m/s\n",
              field(table, 2, "threshold_velocity_m_per_s").c_str(), v_alone,
              field(table, 1, "threshold_velocity_m_per_s").c_str());
  EXPECT_NEAR(v_alone, 6.628, 0.0005); // docs/validation.md §13, "ours, deck"
}

TEST(SweepCli, ADamageThresholdSweepGivesTheThresholdCommandsVelocityAndTheDamageFound) {
  // The matrix-damage threshold of examples/threshold-matrix-damage.toml at 0.05 m/s, for 30 g and
  // 60 g: the 30 g case is the threshold command's search bit for bit, and the first_failure_* columns
  // say what was found there (matrix tension in the bottom ply 4, as the command's damage_reached).
  // Twice the mass at the same velocity loads the plate more: its threshold velocity is lower.
  const fs::path dir = scratch("sweep-damage-threshold");
  const std::string deck = std::string(PLYIMPACT_SOURCE_DIR) + "/examples/threshold-matrix-damage.toml";
  const CommandResult alone = shell("timeout 300 " + std::string(PLYIMPACT_EXE) + " threshold " + deck +
                                    " --tolerance 0.05 -o " + (dir / "alone").string());
  ASSERT_EQ(alone.status, 0) << alone.out;
  const CommandResult s = sweep(deck + " -o " + (dir / "sweep").string() +
                                " --set threshold.tolerance=0.05 --set impactor.mass=0.03,0.06");
  ASSERT_EQ(s.status, 0) << s.out;
  const nlohmann::json j = nlohmann::json::parse(read_text(dir / "alone" / "summary.json"));
  const std::string table = read_text(dir / "sweep" / "sweep.csv");
  std::printf("  matrix-damage threshold: 30 g %s m/s (threshold command %.17g), 60 g %s m/s\n",
              field(table, 1, "threshold_velocity_m_per_s").c_str(), j["threshold_velocity"].get<double>(),
              field(table, 2, "threshold_velocity_m_per_s").c_str());
  EXPECT_EQ(std::stod(field(table, 1, "threshold_velocity_m_per_s")), j["threshold_velocity"].get<double>());
  EXPECT_EQ(field(table, 1, "first_failure_criterion"), "matrix-damage");
  EXPECT_EQ(field(table, 1, "first_failure_mode"), j["damage_reached"]["mode"].get<std::string>());
  EXPECT_EQ(field(table, 1, "first_failure_mode"), "matrix-tension");
  EXPECT_EQ(std::stoi(field(table, 1, "first_failure_ply")), j["damage_reached"]["ply"].get<int>());
  EXPECT_EQ(std::stod(field(table, 1, "first_failure_time_s")), j["damage_reached"]["time"].get<double>());
  EXPECT_EQ(field(table, 1, "first_failure_interface"), "");
  EXPECT_EQ(field(table, 1, "damage_dissipation_J"), ""); // a threshold computes no dissipation
  EXPECT_LT(std::stod(field(table, 2, "threshold_velocity_m_per_s")),
            std::stod(field(table, 1, "threshold_velocity_m_per_s")));
}

TEST(SweepCli, CaseFoldersHoldEachCasesOwnResults) {
  const fs::path dir = scratch("sweep-folders");
  const fs::path deck = twelve_case_deck(dir);
  const CommandResult r = sweep(deck.string() + " -o " + (dir / "out").string() +
                                " --set impactor.mass=0.3 --case-folders --jobs 2");
  ASSERT_EQ(r.status, 0) << r.out;
  const std::string table = read_text(dir / "out" / "sweep.csv");
  for (std::size_t c = 0; c < 4; ++c) {
    const fs::path folder = dir / "out" / "cases" / ("00000" + std::to_string(c));
    ASSERT_TRUE(fs::exists(folder / "summary.json")) << folder;
    EXPECT_TRUE(fs::exists(folder / "history.csv"));
    // The case's deck.toml is a runnable deck: running it alone gives the table's peak force.
    const CommandResult alone =
        shell("timeout 300 " + std::string(PLYIMPACT_EXE) + " impact " + (folder / "deck.toml").string() +
              " -o " + (dir / ("alone" + std::to_string(c))).string());
    ASSERT_EQ(alone.status, 0) << alone.out;
    const auto summary =
        nlohmann::json::parse(read_text(dir / ("alone" + std::to_string(c)) / "summary.json"));
    EXPECT_EQ(summary["peak_force"].get<double>(), std::stod(field(table, c + 1, "peak_force_N"))) << c;
  }
}

TEST(SweepCli, CtrlCStopsWithStatus130KeepsOnlyWholeRecordsSaysHowManyAndResumes) {
  const fs::path dir = scratch("sweep-sigint");
  const fs::path deck = twelve_case_deck(dir, "nx = 12\nny = 8\n");
  const CommandResult whole = sweep(deck.string() + " -o " + (dir / "whole").string() + " --jobs 2");
  ASSERT_EQ(whole.status, 0) << whole.out;
  const fs::path out = dir / "interrupted";
  const fs::path log = dir / "interrupted.log";
  const pid_t pid = ::fork();
  ASSERT_GE(pid, 0);
  if (pid == 0) {
    (void)std::freopen(log.c_str(), "w", stdout);
    (void)std::freopen("/dev/null", "w", stderr);
    ::execl(PLYIMPACT_EXE, "plyimpact", "sweep", deck.c_str(), "-o", out.c_str(), "--jobs", "2",
            static_cast<char*>(nullptr));
    ::_exit(127);
  }
  for (int i = 0; i < 60000 && records_in(out) < 2; ++i) // at most 60 s
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  ::kill(pid, SIGINT);
  int status = 0;
  ::waitpid(pid, &status, 0);
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 130);
  const std::size_t kept = records_in(out);
  std::printf("  interrupted with %zu of 12 records\n", kept);
  ASSERT_LT(kept, 12U);
  // The summary line counts the cases this run recorded, not the cases it was asked to run.
  EXPECT_NE(read_text(log).find("sweep: " + std::to_string(kept) + " of 12 cases run"), std::string::npos)
      << read_text(log);
  for (const auto& e : fs::directory_iterator(out / "cases")) { // the cases cut short left no record
    if (e.path().extension() == ".json") {
      EXPECT_EQ(nlohmann::json::parse(read_text(e.path()))["status"], "ok") << e.path();
    }
  }
  const CommandResult resumed = sweep(deck.string() + " -o " + out.string() + " --resume");
  ASSERT_EQ(resumed.status, 0) << resumed.out;
  EXPECT_EQ(read_text(out / "sweep.csv"), read_text(dir / "whole" / "sweep.csv"));
}

TEST(SweepCli, ShowsProgressLinesWithAnEtaWhenStderrIsNotATerminalAndNoneWhenQuiet) {
  const fs::path dir = scratch("sweep-progress");
  const fs::path deck = twelve_case_deck(dir);
  // --progress-every 0: a line per recorded case (the default is one line every 10 s).
  const CommandResult r =
      sweep(deck.string() + " -o " + (dir / "lines").string() + " --jobs 1 --progress-every 0");
  ASSERT_EQ(r.status, 0) << r.out;
  for (int k = 1; k <= 12; ++k)
    EXPECT_NE(r.out.find(fmt::format("% ({} of 12 cases), ", k)), std::string::npos) << k << "\n" << r.out;
  EXPECT_NE(r.out.find("sweep: 100 % (12 of 12 cases), "), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("ETA 0:0"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("sweep: 12 cases recorded, "), std::string::npos) << r.out;
  const CommandResult quiet =
      sweep(deck.string() + " -o " + (dir / "quiet").string() + " --jobs 1 --progress-every 0 --quiet");
  ASSERT_EQ(quiet.status, 0) << quiet.out;
  EXPECT_EQ(quiet.out.find("ETA"), std::string::npos) << quiet.out;
}

TEST(SweepCli, StrictRefusesASweepWithAnImplausibleCaseBeforeRunningAny) {
  const fs::path dir = scratch("sweep-strict");
  const fs::path deck = twelve_case_deck(dir);
  // 2920 "m/s": the velocity written in mm/s in one case.
  const CommandResult r =
      sweep(deck.string() + " -o " + (dir / "out").string() + " --set impactor.velocity=2.92,2920 --strict");
  EXPECT_EQ(r.status, 2) << r.out;
  EXPECT_NE(r.out.find("cases have implausible values, refused by --strict"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("impactor.velocity = 2920: this looks like mm/s"), std::string::npos) << r.out;
  EXPECT_FALSE(fs::exists(dir / "out" / "cases"));
}

} // namespace

} // namespace sweep_cli_tests
