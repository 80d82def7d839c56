// Ctrl-C at random moments (src/cli/interruption.hpp; docs/robustness.md, "Within a second, whatever the
// program is doing"; issue 77): a coupon run on the ASTM rig (meshing, factoring, stepping), gmsh meshing a
// script that never ends, and plyimpact plot drawing a long history, each interrupted at ten moments drawn
// from a seeded generator. Each must end within a second of the signal with exit 130, leave no child
// running, and keep whole what it had written (a summary that parses, history rows with every cell).
#include "support/cli.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/wait.h>

#include <algorithm>
#include <chrono>
#include <fstream>
#include <random>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

namespace plyimpact::test::interruption_tests {
namespace {

/// How an interrupted command ended: its wait status and the seconds from the signal to its end.
struct Stopped {
  int status = 0;
  double seconds = 0.0;
};

/// Starts `plyimpact ARGS…` in `dir` (output to dir/out.txt), sends SIGINT after `delay`, and waits.
Stopped interrupt_after(const fs::path& dir, const std::vector<std::string>& args,
                        std::chrono::milliseconds delay) {
  const pid_t pid = ::fork();
  if (pid == 0) {
    if (::chdir(dir.c_str()) != 0) ::_exit(127);
    (void)std::freopen("out.txt", "w", stdout);
    (void)std::freopen("err.txt", "w", stderr);
    std::vector<char*> argv{const_cast<char*>("plyimpact")}; // NOLINT(cppcoreguidelines-pro-type-const-cast)
    for (const std::string& a : args)
      argv.push_back(const_cast<char*>(a.c_str())); // NOLINT(cppcoreguidelines-pro-type-const-cast)
    argv.push_back(nullptr);
    ::execv(PLYIMPACT_EXE, argv.data());
    ::_exit(127);
  }
  std::this_thread::sleep_for(delay);
  ::kill(pid, SIGINT);
  const auto t0 = std::chrono::steady_clock::now();
  Stopped s;
  ::waitpid(pid, &s.status, 0);
  s.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return s;
}

/// The test process adopts every orphan of the commands it starts (PR_SET_CHILD_SUBREAPER), so a child left
/// behind by plyimpact (gmsh's, gnuplot) becomes its child rather than init's, and the processes of other
/// tests running beside this one (ctest -j) are never counted.
void adopt_orphans() {
  ASSERT_EQ(::prctl(PR_SET_CHILD_SUBREAPER, 1UL, 0UL, 0UL, 0UL), 0);
}

/// No process left running among this test's children: each command started was waited for, so a live
/// child here is an adopted orphan (the kernel's SIGKILL of a child whose parent died leaves a zombie, which
/// is reaped and not counted).
bool no_child_left_running() {
  while (::waitpid(-1, nullptr, WNOHANG) > 0) {
  }
  for (const auto& entry : fs::directory_iterator("/proc")) {
    std::ifstream stat(entry.path() / "stat");
    std::string line;
    if (!std::getline(stat, line)) continue;
    const auto close = line.rfind(')'); // the command name may hold spaces and parentheses
    if (close == std::string::npos) continue;
    std::istringstream rest(line.substr(close + 1));
    char state = 0;
    pid_t parent = 0;
    rest >> state >> parent;
    if (parent == ::getpid() && state != 'Z') {
      ADD_FAILURE() << "left running: " << line;
      return false;
    }
  }
  return true;
}

/// Every line of a CSV has as many commas as its header.
void expect_whole_rows(const fs::path& csv) {
  std::ifstream in(csv);
  std::string header, line;
  if (!std::getline(in, header)) return;
  const auto commas = std::count(header.begin(), header.end(), ',');
  while (std::getline(in, line))
    EXPECT_EQ(std::count(line.begin(), line.end(), ','), commas) << csv << ": " << line;
}

/// The program's start-up before main() installs its handlers (about 80 ms in the Release build): a signal
/// then ends it as it ends any program (a shell reports 130 all the same), so the moments start after it.
constexpr int start_up_ms = 150;

/// Ten moments from start_up_ms to start_up_ms + `span`, the same on every run.
std::vector<std::chrono::milliseconds> moments(unsigned seed, int span_ms) {
  std::mt19937 random(seed);
  std::vector<std::chrono::milliseconds> m;
  for (int i = 0; i < 10; ++i)
    m.emplace_back(start_up_ms + static_cast<int>(random() % static_cast<unsigned>(span_ms)));
  return m;
}

void expect_stopped_within_a_second(const Stopped& s, const fs::path& dir) {
  ASSERT_TRUE(WIFEXITED(s.status)) << "ended by a signal, not by plyimpact\n" << read_text(dir / "err.txt");
  EXPECT_EQ(WEXITSTATUS(s.status), 130) << read_text(dir / "err.txt");
  EXPECT_LE(s.seconds, 1.0) << read_text(dir / "err.txt");
}

/// The coupon on the ASTM D7136 rig struck by the standard's 5.5 kg striker to the end of the event.
std::string coupon_deck() {
  return coupon_laminate() + "[rig]\npreset = \"astm-d7136\"\n[impactor]\nmass = 5.5\nE = 210e9\nnu = 0.3\n"
                             "[time]\nend = \"auto\"\n";
}

TEST(Interruption, ACouponRunStopsWithinASecondAtTenRandomMoments) {
  const fs::path dir = scratch("interrupt-coupon");
  std::ofstream(dir / "coupon.toml") << coupon_deck();
  for (const auto delay : moments(77, 3000)) {
    fs::remove_all(dir / "out");
    const Stopped s = interrupt_after(dir, {"impact", "coupon.toml", "-o", "out"}, delay);
    expect_stopped_within_a_second(s, dir);
    if (fs::exists(dir / "out" / "summary.json")) { // stopped while stepping: consistent, incomplete
      const auto j = read_json(dir / "out" / "summary.json");
      EXPECT_FALSE(j["complete"].get<bool>()) << delay.count() << " ms";
    }
    if (fs::exists(dir / "out" / "history.csv")) expect_whole_rows(dir / "out" / "history.csv");
  }
}

TEST(Interruption, GmshMeshingAScriptThatNeverEndsStopsWithinASecond) {
  adopt_orphans();
  const fs::path dir = scratch("interrupt-gmsh");
  std::string deck = coupon_deck();
  deck = deck.substr(0, deck.find("[rig]")) +
         "[mesh]\ngeo = \"endless.geo\"\n[boundary]\nedges = \"clamped\"\n[impactor]\nmass = 2.0\n"
         "radius = 0.008\nE = 210e9\nnu = 0.3\nenergy = 1.0\n[time]\ndt = 1e-6\nend = 4e-6\n";
  std::ofstream(dir / "deck.toml") << deck;
  std::ofstream(dir / "endless.geo") << "For i In {1:1e12}\nEndFor\n";
  for (const auto delay : moments(78, 2000)) {
    const Stopped s = interrupt_after(dir, {"impact", "deck.toml", "-o", "out", "--overwrite"}, delay);
    expect_stopped_within_a_second(s, dir);
  }
  std::this_thread::sleep_for(std::chrono::milliseconds(200)); // the kernel's SIGKILL of an orphan
  EXPECT_TRUE(no_child_left_running());
}

TEST(Interruption, APlotStopsWithinASecondAndLeavesNoGnuplotRunning) {
  adopt_orphans();
  const fs::path dir = scratch("interrupt-plot");
  fs::create_directories(dir / "res");
  {
    std::ofstream h(dir / "res" / "history.csv");
    h << "t_s,force_N,impactor_w_m,impactor_v_m_per_s,plate_w_m,indentation_m,plate_kinetic_J,plate_strain_J,"
         "impactor_energy_J,contact_work_J\n";
    for (int i = 0; i < 19000; ++i) { // below the thinning: gnuplot draws every row
      const double f = 1000.0 * std::sin(1e-3 * i), w = 1e-3 * std::sin(1e-3 * i);
      h << fmt::format("{:.9g},{:.6g},{:.6g},1,{:.6g},{:.6g},0,0,1,0\n", 1e-6 * i, f, w, w, 0.1 * w);
    }
  }
  for (const auto delay : moments(79, 1500)) {
    const Stopped s = interrupt_after(dir, {"plot", "res", "-o", "pics"}, delay);
    if (WIFEXITED(s.status) && WEXITSTATUS(s.status) == 0) continue; // the plot was done before the signal
    expect_stopped_within_a_second(s, dir);
  }
  std::this_thread::sleep_for(std::chrono::milliseconds(200));
  EXPECT_TRUE(no_child_left_running());
  // every picture there is whole: the ones drawn are renamed from their temporary names once complete
  for (const auto& entry : fs::directory_iterator(dir / "pics"))
    if (entry.path().extension() == ".png") {
      EXPECT_GT(fs::file_size(entry.path()), 1000U) << entry.path();
    }
}

// A sweep interrupted while its cases mesh (issue 77): the cases were stored as failed and --resume never
// ran them again. Interrupted, they are not run; resumed with a script that meshes, they run.
TEST(Interruption, ASweepCaseInterruptedWhileItMeshesRunsAgainOnResume) {
  const fs::path dir = scratch("interrupt-sweep");
  std::string deck = coupon_deck();
  deck = deck.substr(0, deck.find("[rig]")) +
         "[mesh]\ngeo = \"plate.geo\"\n[boundary]\nedges = \"clamped\"\n[impactor]\nmass = 2.0\n"
         "radius = 0.008\nE = 210e9\nnu = 0.3\nvelocity = 1.0\n[time]\ndt = 1e-6\nend = 4e-6\n"
         "[sweep]\n[sweep.values]\n\"impactor.velocity\" = [1.0, 2.0]\n";
  std::ofstream(dir / "deck.toml") << deck;
  std::ofstream(dir / "plate.geo") << "For i In {1:1e12}\nEndFor\n";
  const Stopped s = interrupt_after(dir, {"sweep", "deck.toml", "-o", "out", "--jobs", "1"},
                                    std::chrono::milliseconds(1500));
  expect_stopped_within_a_second(s, dir);
  std::ofstream(dir / "plate.geo") << R"(lc = 0.02;
Point(1) = {0, 0, 0, lc}; Point(2) = {0.1, 0, 0, lc}; Point(3) = {0.1, 0.08, 0, lc}; Point(4) = {0, 0.08, 0, lc};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Physical Curve("edges") = {1, 2, 3, 4};
Physical Surface("plate") = {1};
)";
  const CommandResult resumed = shell(
      fmt::format("cd '{}' && {} sweep deck.toml -o out --resume --jobs 1", dir.string(), PLYIMPACT_EXE));
  EXPECT_NE(resumed.out.find("2 to run"), std::string::npos) << resumed.out;
  const std::string table = read_text(dir / "out" / "sweep.csv");
  EXPECT_EQ(std::count(table.begin(), table.end(), '\n'), 3) << table; // the header and both cases
  EXPECT_EQ(table.find("failed"), std::string::npos) << table;
}

} // namespace
} // namespace plyimpact::test::interruption_tests
