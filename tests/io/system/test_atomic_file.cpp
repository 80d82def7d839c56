// write_file_atomically (io/system/atomic_file.hpp): a failed write names the file, gives the system's reason
// (strerror) and leaves no temporary *.tmp.PID file behind.
#include "plyimpact/io/system/atomic_file.hpp"
#include "support/cli.hpp"

#include <gtest/gtest.h>

#include <stdexcept>
#include <string>
#include <unistd.h>

namespace plyimpact::atomic_file_tests {
namespace {

std::size_t temporary_files_in(const test::fs::path& dir) {
  std::size_t n = 0;
  for (const auto& e : test::fs::directory_iterator(dir))
    n += e.path().filename().string().find(".tmp.") != std::string::npos ? 1 : 0;
  return n;
}

TEST(AtomicFile, WritesTheWholeContent) {
  const test::fs::path dir = test::scratch("atomic-ok");
  write_file_atomically(dir / "a.txt", "one\ntwo\n");
  EXPECT_EQ(test::read_text(dir / "a.txt"), "one\ntwo\n");
  EXPECT_EQ(temporary_files_in(dir), 0U);
}

TEST(AtomicFile, ARenameThatFailsGivesTheSystemsReasonAndRemovesTheTemporaryFile) {
  const test::fs::path dir = test::scratch("atomic-rename");
  test::fs::create_directories(dir / "summary.json" / "inside"); // a non-empty folder in the way
  try {
    write_file_atomically(dir / "summary.json", "{}\n");
    FAIL() << "no exception";
  } catch (const std::runtime_error& e) {
    EXPECT_EQ(std::string(e.what()), (dir / "summary.json").string() + ": cannot rename summary.json.tmp." +
                                         std::to_string(::getpid()) + " into place: Is a directory");
  }
  EXPECT_EQ(temporary_files_in(dir), 0U);
}

TEST(AtomicFile, AWriteThatCannotStartGivesTheSystemsReason) {
  const test::fs::path dir = test::scratch("atomic-open");
  const test::fs::path tmp = dir / ("x.csv.tmp." + std::to_string(::getpid()));
  test::fs::create_directories(tmp); // the temporary name is taken by a folder
  try {
    write_file_atomically(dir / "x.csv", "a\n");
    FAIL() << "no exception";
  } catch (const std::runtime_error& e) {
    EXPECT_EQ(std::string(e.what()), (dir / "x.csv").string() + ": cannot write: Is a directory");
  }
  EXPECT_FALSE(test::fs::exists(dir / "x.csv"));
}

} // namespace
} // namespace plyimpact::atomic_file_tests
