// Results folders that cannot mix runs and survive damage (docs/output.md): a folder locked by another
// run is refused naming the holder; a folder with another run's results is refused without --overwrite
// and cleared with it; without -o a run writes results/<deck>/ and says so; a run killed with SIGKILL
// leaves a valid history.csv of the steps done; a mesh too large for the machine is refused before
// assembly with the estimate; a deck path that is a folder, a truncated sweep manifest and a malformed
// sweep record each get a clear message, and the sweep resumes.
#include "support/cli.hpp"

#include <gtest/gtest.h>

#include <csignal>
#include <cstdlib>
#include <fcntl.h>
#include <fstream>
#include <string>
#include <sys/file.h>
#include <sys/wait.h>
#include <unistd.h>
#include <vector>

namespace output_folder_tests {

namespace {

using namespace plyimpact::test;

const std::string impactor = steel_ball_impactor("dt = 2e-6\n");

/// A short 20 m/s impact on the small plate with Choi-Chang damage (T300/976 strengths, Table 4.2).
std::string damage_deck() {
  std::string deck = small_deck("impact", R"(
[impactor]
mass = 0.00844
radius = 6.35e-3
E = 207e9
velocity = 20.0
[time]
dt = 0.5e-6
end = 40e-6
[damage]
criteria = ["choi-chang-matrix", "choi-chang-delamination"]
)");
  const std::string rho = "rho = 1389.2\n";
  deck.insert(deck.find(rho) + rho.size(),
              "Yt = 55.2e6\nYc = 294.0e6\nS12 = 101.1e6\nS23 = 32.94e6\nDa = 1.8\n");
  return deck;
}

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> out;
  std::size_t start = 0;
  for (std::size_t nl = text.find('\n'); nl != std::string::npos; nl = text.find('\n', start)) {
    out.push_back(text.substr(start, nl - start));
    start = nl + 1;
  }
  if (start < text.size()) out.push_back(text.substr(start));
  return out;
}

TEST(OutputFolder, AFolderLockedByAnotherRunIsRefusedNamingTheHolder) {
  const fs::path dir = scratch("lock");
  const fs::path deck = write(dir, small_deck("impact", impactor));
  const fs::path out = dir / "out";
  fs::create_directories(out);
  const int fd = ::open((out / ".plyimpact.lock").c_str(), O_RDWR | O_CREAT, 0644);
  ASSERT_GE(fd, 0);
  ASSERT_EQ(::flock(fd, LOCK_EX | LOCK_NB), 0);
  const std::string holder =
      "pid 4242 on host testhost, started 2026-01-01T00:00:00Z: plyimpact impact a.toml";
  ASSERT_EQ(::write(fd, holder.data(), holder.size()), static_cast<ssize_t>(holder.size()));

  const CommandResult refused = run("impact " + deck.string() + " -o " + out.string());
  EXPECT_EQ(refused.status, 1);
  EXPECT_NE(refused.out.find(out.string() + " is in use by another plyimpact run (" + holder +
                             "): wait until it ends, or give another folder with -o"),
            std::string::npos)
      << refused.out;
  EXPECT_FALSE(fs::exists(out / "summary.json"));
  EXPECT_FALSE(fs::exists(out / "deck.toml"));
  // the other commands honour the same lock
  for (const std::string command :
       {"threshold --criterion choi-chang-matrix", "sweep --set impactor.mass=0.2,0.3"}) {
    const CommandResult r = run(command + " " + deck.string() + " -o " + out.string());
    EXPECT_NE(r.out.find("is in use by another plyimpact run"), std::string::npos) << command << r.out;
  }

  ::close(fd); // released: the run takes the folder, and removes its lock file when done
  const CommandResult taken = run("impact " + deck.string() + " -o " + out.string());
  EXPECT_EQ(taken.status, 0) << taken.out;
  EXPECT_TRUE(fs::exists(out / "summary.json"));
  EXPECT_FALSE(fs::exists(out / ".plyimpact.lock"));
}

TEST(OutputFolder, AStaleLockOfADeadRunIsTakenOver) {
  const fs::path dir = scratch("stale-lock");
  const fs::path deck = write(dir, small_deck("modal", "[modal]\ncount = 2\n"));
  fs::create_directories(dir / "out");
  std::ofstream(dir / "out" / ".plyimpact.lock") << "pid 999999 on host gone: plyimpact modal deck.toml\n";
  const CommandResult r = run("modal " + deck.string() + " -o " + (dir / "out").string());
  EXPECT_EQ(r.status, 0) << r.out;
  EXPECT_TRUE(fs::exists(dir / "out" / "summary.json"));
}

TEST(OutputFolder, AReusedFolderIsRefusedWithoutOverwriteAndClearedWithIt) {
  const fs::path dir = scratch("reuse");
  const fs::path damaged = write(dir, damage_deck());
  const fs::path out = dir / "out";
  const CommandResult first = run("impact " + damaged.string() + " -o " + out.string());
  ASSERT_EQ(first.status, 0) << first.out;
  ASSERT_TRUE(fs::exists(out / "damage_onsets.csv"));
  ASSERT_TRUE(fs::is_directory(out / "damage_maps")); // maps in their subfolder, not at the top level
  std::size_t maps = 0;
  for (const auto& e : fs::directory_iterator(out / "damage_maps"))
    maps += e.path().extension() == ".gp" ? 1 : 0;
  EXPECT_GT(maps, 0U);
  for (const auto& e : fs::directory_iterator(out))
    EXPECT_NE(e.path().filename().string().rfind("damage_map_", 0), 0U) << e.path();
  std::ofstream(out / "notes.txt") << "the user's own file\n";

  std::ofstream(dir / "plain.toml") << small_deck("impact", impactor);
  const std::string second = "impact " + (dir / "plain.toml").string() + " -o " + out.string();
  const CommandResult refused = run(second);
  EXPECT_EQ(refused.status, 1);
  EXPECT_NE(refused.out.find(out.string() +
                             " holds the results of another run (damage_area.csv, damage_maps, "
                             "damage_onsets.csv, deck.toml and 5 more): add --overwrite to "
                             "replace them, or give another folder with -o"),
            std::string::npos)
      << refused.out;
  EXPECT_TRUE(fs::exists(out / "damage_onsets.csv")); // nothing touched

  const CommandResult replaced = run(second + " --overwrite");
  ASSERT_EQ(replaced.status, 0) << replaced.out;
  EXPECT_FALSE(fs::exists(out / "damage_onsets.csv"));
  EXPECT_FALSE(fs::exists(out / "damage_area.csv"));
  EXPECT_FALSE(fs::exists(out / "damage_maps"));
  EXPECT_TRUE(fs::exists(out / "notes.txt")); // not a result: kept
  EXPECT_EQ(read_text(out / "deck.toml"), small_deck("impact", impactor));
  EXPECT_TRUE(fs::exists(out / "summary.json"));
}

TEST(OutputFolder, AFolderNoRunHasMarkedIsNotRefusedNorCleared) {
  const fs::path dir = scratch("own-folder");
  const std::string text = small_deck("modal", "[modal]\ncount = 2\n");
  const fs::path deck = write(dir, text); // the user's own deck.toml, in the folder given to -o
  const CommandResult r = run("modal " + deck.string() + " -o " + dir.string() + " --overwrite");
  ASSERT_EQ(r.status, 0) << r.out;
  EXPECT_TRUE(fs::exists(dir / "summary.json"));
  EXPECT_EQ(read_text(deck), text); // not removed by --overwrite (rewritten with the same text)
}

TEST(OutputFolder, WithoutOutputOptionResultsGoToResultsDeckNameOrOutputDir) {
  const fs::path dir = scratch("default-dir");
  std::ofstream(dir / "plate-a.toml") << small_deck("static", "[load]\npressure = 1e5\n");
  const CommandResult r = shell("cd " + dir.string() + " && " + PLYIMPACT_EXE + " static plate-a.toml");
  ASSERT_EQ(r.status, 0) << r.out;
  EXPECT_NE(r.out.find("results: results/plate-a\n"), std::string::npos) << r.out;
  EXPECT_TRUE(fs::exists(dir / "results" / "plate-a" / "summary.json"));
  EXPECT_TRUE(fs::exists(dir / "results" / "plate-a" / "displacements.csv"));

  std::ofstream(dir / "plate-c.toml")
      << small_deck("impact", impactor) << "[sweep.values]\n\"impactor.velocity\" = [1.0, 2.0]\n";
  const CommandResult c =
      shell("cd " + dir.string() + " && " + PLYIMPACT_EXE + " sweep plate-c.toml --jobs 1");
  ASSERT_EQ(c.status, 0) << c.out;
  EXPECT_NE(c.out.find("results: results/plate-c\n"), std::string::npos) << c.out;
  EXPECT_TRUE(fs::exists(dir / "results" / "plate-c" / "sweep.csv"));

  std::ofstream(dir / "plate-b.toml")
      << small_deck("modal", "[modal]\ncount = 2\n[output]\ndir = \"runs\"\n");
  const CommandResult b = shell("cd " + dir.string() + " && " + PLYIMPACT_EXE + " plate-b.toml");
  ASSERT_EQ(b.status, 0) << b.out;
  EXPECT_NE(b.out.find("results: runs/plate-b\n"), std::string::npos) << b.out;
  EXPECT_TRUE(fs::exists(dir / "runs" / "plate-b" / "modes.csv"));
}

TEST(OutputFolder, ARunKilledWithSigkillLeavesAValidPartialHistory) {
  const fs::path dir = scratch("sigkill");
  const fs::path deck = write(dir, long_impact_deck());
  const fs::path out = dir / "out";
  const pid_t pid = start_impact(deck, out, false);
  ASSERT_GE(pid, 0);
  const std::size_t rows_at_kill = lines_of(wait_for_text(out / "history.csv", [](const std::string& t) {
                                     return lines_of(t).size() >= 1000;
                                   })).size();
  ::kill(pid, SIGKILL);
  int status = 0;
  ::waitpid(pid, &status, 0);
  ASSERT_TRUE(WIFSIGNALED(status)) << "the run ended before it could be killed";

  std::string text = read_text(out / "history.csv");
  ASSERT_FALSE(text.empty());
  // A SIGKILL that lands while a block is being written (the kernel copies it page by page and stops
  // between pages for a fatal signal) cuts that block: every line before the last is complete, the
  // last may be cut short (docs/output.md). The bytes seen before the kill stay in the file.
  const bool cut = text.back() != '\n';
  if (cut) text.erase(text.rfind('\n') + 1);
  const std::vector<std::string> rows = lines_of(text);
  ASSERT_GE(rows.size(), rows_at_kill - 1);
  ASSERT_GE(rows.size(), 999U);
  EXPECT_EQ(rows[0], "t_s,force_N,impactor_w_m,impactor_v_m_per_s,plate_w_m,indentation_m,plate_kinetic_J,"
                     "plate_strain_J,impactor_energy_J,contact_work_J");
  for (std::size_t i = 1; i < rows.size(); ++i) {
    ASSERT_EQ(std::count(rows[i].begin(), rows[i].end(), ','), 9) << i << ": " << rows[i];
    // one row per step of 1 us from t = 0
    EXPECT_NEAR(std::stod(rows[i].substr(0, rows[i].find(','))), static_cast<double>(i - 1) * 1e-6, 1e-12)
        << i;
  }
  EXPECT_FALSE(fs::exists(out / "summary.json")); // visibly not a complete run
  std::printf("  killed with %zu complete rows in history.csv%s\n", rows.size() - 1,
              cut ? " and the last one cut short" : "");
}

TEST(OutputFolder, AThousandByThousandMeshIsRefusedBeforeAssemblyWithTheEstimate) {
  const fs::path dir = scratch("huge-mesh");
  std::string text = small_deck("impact", impactor + "[load]\npressure = 1e5\n[modal]\ncount = 2\n");
  text.replace(text.find("nx = 6\nny = 4"), 13, "nx = 1000\nny = 1000");
  const fs::path deck = write(dir, text);
  const CommandResult r = shell("PLYIMPACT_MEMORY_LIMIT_BYTES=16e9 " + std::string(PLYIMPACT_EXE) +
                                " impact " + deck.string() + " -o " + (dir / "out").string());
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.out.find("deck.toml: a 1000 x 1000 mesh (2e+07 equations) needs about "), std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("but this machine has 16 GB available: use a coarser mesh ([mesh] nx, ny)"),
            std::string::npos)
      << r.out;
  EXPECT_EQ(r.out.find("bad_alloc"), std::string::npos);
  EXPECT_FALSE(fs::exists(dir / "out")); // refused before anything was written
  for (const std::string command : {"static", "modal"}) {
    const CommandResult s = shell("PLYIMPACT_MEMORY_LIMIT_BYTES=16e9 " + std::string(PLYIMPACT_EXE) + " " +
                                  command + " " + deck.string() + " -o " + (dir / "out").string());
    EXPECT_NE(s.out.find("a 1000 x 1000 mesh"), std::string::npos) << command << s.out;
  }
}

TEST(OutputFolder, AGradedMeshTooFineIsRefusedBeforeAssembly) {
  const fs::path dir = scratch("huge-graded");
  std::string text = small_deck("impact", impactor);
  // 20 um elements at the impact point, growing by 1 % up to 0.1 mm: a mesh of millions of nodes
  text.replace(text.find("nx = 6\nny = 4"), 13, "size_at_impact = 20e-6\ngrowth = 1.01\nmax_size = 1e-4");
  const fs::path deck = write(dir, text);
  const CommandResult r = shell("PLYIMPACT_MEMORY_LIMIT_BYTES=16e9 " + std::string(PLYIMPACT_EXE) +
                                " impact " + deck.string() + " -o " + (dir / "out").string());
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(
      r.out.find("plyimpact: error: a mesh graded toward the impact point of 1431 x 923 elements (2.64e+07 "
                 "equations) needs about 269 GB"),
      std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("but this machine has 16 GB available: give a larger mesh.size_at_impact or "
                       "mesh.max_size"),
            std::string::npos)
      << r.out;
  EXPECT_FALSE(fs::exists(dir / "out"));
}

TEST(OutputFolder, ADeckPathThatIsAFolderIsAClearError) {
  const fs::path dir = scratch("deck-folder");
  const CommandResult r = run("impact " + dir.string() + " -o " + (dir / "out").string());
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.out.find(dir.string() + ": error: this is a folder, not a deck file: give the .toml file"),
            std::string::npos)
      << r.out;
  const CommandResult alone = run(dir.string()); // the deck's own analysis
  EXPECT_EQ(alone.status, 2);
  EXPECT_NE(alone.out.find("this is a folder, not a deck file"), std::string::npos) << alone.out;
}

/// A sweep of 3 velocities on the small plate.
fs::path three_case_sweep(const fs::path& dir) {
  const fs::path p = dir / "sweep.toml";
  std::ofstream(p) << small_deck("impact", impactor)
                   << "[sweep.values]\n\"impactor.velocity\" = [1.0, 2.0, 3.0]\n";
  return p;
}

CommandResult sweep(const std::string& args) {
  return run("sweep " + args + " --jobs 1");
}

TEST(OutputFolder, ATruncatedSweepManifestIsNamedAndTheSweepResumes) {
  const fs::path dir = scratch("sweep-manifest");
  const fs::path deck = three_case_sweep(dir);
  const fs::path out = dir / "out";
  ASSERT_EQ(sweep(deck.string() + " -o " + out.string()).status, 0);
  const std::string table = read_text(out / "sweep.csv");
  const std::string manifest = read_text(out / "sweep.json");
  std::ofstream(out / "sweep.json", std::ios::trunc) << manifest.substr(0, manifest.size() / 2);
  fs::remove(out / "cases" / "000002.json");

  const CommandResult again = sweep(deck.string() + " -o " + out.string());
  EXPECT_NE(again.status, 0);
  EXPECT_NE(again.out.find((out / "sweep.json").string() +
                           " is truncated or corrupt (not the JSON object plyimpact writes)"),
            std::string::npos)
      << again.out;
  EXPECT_NE(again.out.find("run the same command with --resume"), std::string::npos) << again.out;
  EXPECT_EQ(again.out.find("holds another sweep"), std::string::npos) << again.out;

  const CommandResult resumed = sweep(deck.string() + " -o " + out.string() + " --resume");
  ASSERT_EQ(resumed.status, 0) << resumed.out;
  EXPECT_NE(resumed.out.find("was truncated or corrupt: rewritten for this sweep"), std::string::npos)
      << resumed.out;
  EXPECT_NE(resumed.out.find("sweep: 3 cases (1 to run)"), std::string::npos) << resumed.out;
  EXPECT_EQ(read_text(out / "sweep.csv"), table);
  EXPECT_EQ(read_text(out / "sweep.json"), manifest);
}

TEST(OutputFolder, AMalformedSweepRecordIsNamedAndRunsAgain) {
  const fs::path dir = scratch("sweep-record");
  const fs::path deck = three_case_sweep(dir);
  const fs::path out = dir / "out";
  ASSERT_EQ(sweep(deck.string() + " -o " + out.string()).status, 0);
  const std::string table = read_text(out / "sweep.csv");
  std::string record = read_text(out / "cases" / "000001.json");
  record.replace(record.find("\"case\": 1"), 9, "\"case\": \"one\"");
  std::ofstream(out / "cases" / "000001.json", std::ios::trunc) << record;
  std::ofstream(out / "cases" / "000000.json", std::ios::trunc) << "{\"format\": 1, \"ca";

  const CommandResult resumed = sweep(deck.string() + " -o " + out.string() + " --resume");
  ASSERT_EQ(resumed.status, 0) << resumed.out;
  EXPECT_NE(resumed.out.find((out / "cases" / "000000.json").string() +
                             " is damaged (not valid JSON (truncated?)): case 0 runs again"),
            std::string::npos)
      << resumed.out;
  EXPECT_NE(resumed.out.find((out / "cases" / "000001.json").string() + " is damaged ("), std::string::npos)
      << resumed.out;
  EXPECT_NE(resumed.out.find("): case 1 runs again"), std::string::npos) << resumed.out;
  EXPECT_NE(resumed.out.find("sweep: 3 cases (2 to run)"), std::string::npos) << resumed.out;
  EXPECT_EQ(read_text(out / "sweep.csv"), table);
}

TEST(OutputFolder, ASecondDifferentSweepIntoTheFolderIsRefused) {
  const fs::path dir = scratch("sweep-other");
  const fs::path deck = three_case_sweep(dir);
  const fs::path out = dir / "out";
  ASSERT_EQ(sweep(deck.string() + " -o " + out.string()).status, 0);
  const CommandResult other =
      sweep(deck.string() + " -o " + out.string() + " --resume --set impactor.mass=0.2,0.3");
  EXPECT_NE(other.status, 0);
  EXPECT_NE(other.out.find("holds another sweep"), std::string::npos) << other.out;
  const CommandResult impact = run("impact " + deck.string() + " -o " + out.string());
  EXPECT_NE(impact.out.find("holds the results of another run (cases, report.html, sweep.csv, sweep.json)"),
            std::string::npos)
      << impact.out;
  const CommandResult replaced =
      sweep(deck.string() + " -o " + out.string() + " --overwrite --set impactor.mass=0.2,0.3");
  EXPECT_EQ(replaced.status, 0) << replaced.out;
}

} // namespace

} // namespace output_folder_tests
