#pragma once
// Running the plyimpact executable from tests: command, scratch folders, small decks.
#include "test_paths.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <array>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>

namespace plyimpact::test {

namespace fs = std::filesystem;

struct CommandResult {
  int status = -1;
  std::string out;
};

/// Runs a shell command (stdout and stderr together) and returns its exit status and output.
inline CommandResult shell(const std::string& command) {
  CommandResult r;
  FILE* pipe = ::popen((command + " 2>&1").c_str(), "r");
  if (pipe == nullptr) return r;
  std::array<char, 4096> buf{};
  while (std::fgets(buf.data(), buf.size(), pipe) != nullptr)
    r.out += buf.data();
  const int status = ::pclose(pipe);
  r.status = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return r;
}

/// How many times `what` occurs in `text`, without overlaps (elements of a report or a picture).
inline std::size_t occurrences(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + what.size()))
    ++n;
  return n;
}

/// Runs `plyimpact ARGS`. Every summary.json a test's run writes is checked by the program against the
/// table of summary keys (io/results/summary_keys.hpp); a key outside it fails the test that ran it.
inline CommandResult run(const std::string& args) {
  CommandResult r = shell(std::string(PLYIMPACT_EXE) + " " + args);
  EXPECT_EQ(r.out.find("plyimpact: warning: summary.json:"), std::string::npos)
      << "plyimpact " << args << " wrote a summary key outside summary_keys.cpp:\n"
      << r.out;
  return r;
}

/// An empty folder under the system temporary folder.
inline fs::path scratch(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("plyimpact-cli-" + name);
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

/// A 4 mm quasi-isotropic T300/976 coupon, [45/0/-45/90]2s of 0.25 mm plies: an impact deck's material and
/// laminate, no plate, supports or impactor.
inline std::string coupon_laminate() {
  return R"(analysis = "impact"
[materials.T300_976]
E1 = 144.8e9
E2 = 9.65e9
G12 = 7.10e9
G13 = 7.10e9
G23 = 5.92e9
nu12 = 0.30
rho = 1389.2
[laminate]
material = "T300_976"
layup = "[45/0/-45/90]2s"
ply_thickness = 0.25e-3
)";
}

/// The [0_2/90_4/0_2] T300/976 plate of Annex 2 on a 6 × 4 mesh, simply supported, plus `extra`.
inline std::string small_deck(const std::string& analysis, const std::string& extra) {
  return "analysis = \"" + analysis + R"("
[materials.T300_976]
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
nx = 6
ny = 4
[boundary]
x0 = "ss"
xa = "ss"
y0 = "ss"
yb = "ss"
)" + extra;
}

/// Writes DIR/deck.toml.
inline fs::path write(const fs::path& dir, const std::string& text) {
  const fs::path p = dir / "deck.toml";
  std::ofstream(p) << text;
  return p;
}

/// The tests' usual impactor, the 314 g steel ball of R = 12.7 mm at 2.92 m/s (thesis §4.2), and a
/// [time] table with `time_keys` (one "key = value" per line).
inline std::string steel_ball_impactor(const std::string& time_keys) {
  return R"(
[impactor]
mass = 0.314
radius = 12.7e-3
E = 207e9
velocity = 2.92
[time]
)" + time_keys;
}

/// small_deck's plate struck for 2 000 000 steps of 1 µs: far longer than a test waits before it
/// interrupts or kills the run.
inline std::string long_impact_deck() {
  return small_deck("impact", steel_ball_impactor("dt = 1e-6\nend = 2.0\n"));
}

/// Starts `plyimpact impact DECK -o OUT` in a child process, its stdout (and its stderr with
/// `quiet_stderr`) sent to /dev/null; returns the child's pid (negative when fork failed).
inline pid_t start_impact(const fs::path& deck, const fs::path& out, bool quiet_stderr) {
  const pid_t pid = ::fork();
  if (pid != 0) return pid;
  (void)std::freopen("/dev/null", "w", stdout);
  if (quiet_stderr) (void)std::freopen("/dev/null", "w", stderr);
  ::execl(PLYIMPACT_EXE, "plyimpact", "impact", deck.c_str(), "-o", out.c_str(), static_cast<char*>(nullptr));
  ::_exit(127);
}

/// The whole file as text (bytes as they are).
inline std::string read_text(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

inline nlohmann::json read_json(const fs::path& p) {
  std::ifstream in(p);
  return nlohmann::json::parse(in);
}

/// Reads `file` every millisecond, for at most 60 s, until `enough(text)`; returns the last text read.
template <class Enough>
std::string wait_for_text(const fs::path& file, Enough enough) {
  std::string text;
  for (int i = 0; i < 60000; ++i) {
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
    text = read_text(file);
    if (enough(text)) break;
  }
  return text;
}

/// `text` with the first line (after the first) that starts with `from` replaced by `to`; a failed
/// expectation, and `text` unchanged, when there is no such line.
inline std::string with_line(std::string text, const std::string& from, const std::string& to) {
  const auto pos = text.find("\n" + from);
  EXPECT_NE(pos, std::string::npos) << from;
  if (pos == std::string::npos) return text;
  const auto end = text.find('\n', pos + 1);
  text.replace(pos + 1, end - pos - 1, to);
  return text;
}

} // namespace plyimpact::test
