// A history.csv read back for plotting (io/results/history_check.hpp): refused where it is not a regular file
// or its rows are cut or not numbers (with the line), passed as it is up to max_plot_rows rows, thinned
// beyond with the force's peak kept.
#include "plyimpact/io/results/history_check.hpp"
#include "support/cli.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <cmath>
#include <fstream>
#include <sstream>
#include <string>

namespace plyimpact::history_check_tests {
namespace {

namespace fs = std::filesystem;

std::string refusal(const fs::path& history) {
  try {
    (void)check_history_for_plot(history, history.parent_path() / "thinned.csv");
  } catch (const HistoryFileError& e) {
    return e.what();
  }
  return "";
}

TEST(HistoryCheck, AFifoADeviceAndAFolderAreRefusedWithoutBlocking) {
  const fs::path dir = test::scratch("history-not-files");
  ASSERT_EQ(::mkfifo((dir / "fifo.csv").c_str(), 0600), 0);
  fs::create_symlink("/dev/zero", dir / "zero.csv");
  fs::create_directories(dir / "folder.csv");
  for (const char* name : {"fifo.csv", "zero.csv", "folder.csv"})
    EXPECT_NE(refusal(dir / name).find("not a regular file"), std::string::npos) << name;
}

TEST(HistoryCheck, RowsCutOrNotNumbersAreNamedWithTheirLine) {
  const fs::path dir = test::scratch("history-rows");
  const std::string header = "t_s,force_N,w_m\n";
  const auto with = [&](const std::string& name, const std::string& text) {
    std::ofstream(dir / name) << text;
    return refusal(dir / name);
  };
  EXPECT_NE(with("cut.csv", header + "0,0,0\n1e-6,5").find("cut.csv:3: error: the last row has no end"),
            std::string::npos);
  EXPECT_NE(with("nan.csv", header + "0,0,0\n1e-6,nan,0\n").find("nan.csv:3: error: column 2 (\"force_N\")"),
            std::string::npos);
  EXPECT_NE(with("short.csv", header + "0,0\n").find("short.csv:2: error: 2 cells where the header has 3"),
            std::string::npos);
  EXPECT_NE(with("empty.csv", "").find("no header line"), std::string::npos);
  EXPECT_EQ(with("good.csv", header + "0,0,0\n1e-6,5.5,-1e-9\n"), "");
}

TEST(HistoryCheck, ALongHistoryIsThinnedToTheLimitWithItsPeakKept) {
  const fs::path dir = test::scratch("history-long");
  const std::size_t rows = 5 * max_plot_rows + 7;
  const std::size_t peak = 31'337; // an odd row: every k-th row would miss it
  std::ostringstream text;
  text << "t_s,force_N\n";
  for (std::size_t i = 0; i < rows; ++i)
    text << fmt::format("{:.9g},{:.9g}\n", 1e-7 * static_cast<double>(i),
                        i == peak ? 9999.0 : std::sin(1e-4 * static_cast<double>(i)));
  std::ofstream(dir / "history.csv") << text.str();
  const CheckedHistory c = check_history_for_plot(dir / "history.csv", dir / "thinned.csv");
  EXPECT_EQ(c.rows, rows);
  EXPECT_EQ(c.file, dir / "thinned.csv");
  EXPECT_LE(c.plotted, max_plot_rows);
  EXPECT_GE(c.plotted, max_plot_rows / 4); // a row of each group at least
  std::ifstream thinned(c.file);
  std::string line, last_time = "-1";
  std::size_t count = 0;
  bool has_peak = false;
  std::getline(thinned, line);
  while (std::getline(thinned, line)) {
    ++count;
    has_peak = has_peak || line.ends_with(",9999");
    const double t = std::stod(line.substr(0, line.find(',')));
    EXPECT_GT(t, std::stod(last_time)) << "rows out of order at " << line;
    last_time = line.substr(0, line.find(','));
  }
  EXPECT_EQ(count, c.plotted);
  EXPECT_TRUE(has_peak) << "the peak of the force was thinned away";
  // a short history is plotted as it is
  std::ofstream(dir / "short.csv") << "t_s,force_N\n0,0\n1e-6,1\n";
  const CheckedHistory s = check_history_for_plot(dir / "short.csv", dir / "unused.csv");
  EXPECT_EQ(s.file, dir / "short.csv");
  EXPECT_EQ(s.plotted, 2U);
  EXPECT_FALSE(fs::exists(dir / "unused.csv"));
}

} // namespace
} // namespace plyimpact::history_check_tests
