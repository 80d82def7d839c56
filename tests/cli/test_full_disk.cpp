// A run whose disk fills (issue 77; docs/robustness.md, "Interruption without loss"): it fails with the
// system's reason and leaves no file cut short under its final name — history.csv keeps whole rows, every
// atomically written file is whole or absent. The disk is a 1 MiB tmpfs mounted for the test (root only:
// skipped elsewhere).
#include "support/cli.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <sys/mount.h>

#include <algorithm>
#include <fstream>
#include <string>
#include <utility>

namespace plyimpact::test::full_disk_tests {
namespace {

/// Unmounts a folder when it goes out of scope, whatever the test asserted before.
class Unmounted {
public:
  explicit Unmounted(fs::path at) : at_(std::move(at)) {}
  Unmounted(const Unmounted&) = delete;
  Unmounted& operator=(const Unmounted&) = delete;
  ~Unmounted() { ::umount(at_.c_str()); }

private:
  fs::path at_;
};

TEST(FullDisk, ARunThatFillsItsDiskFailsAndLeavesOnlyWholeFiles) {
  // a mount left by an earlier run that was killed would keep scratch() from emptying the folder
  ::umount((fs::temp_directory_path() / "plyimpact-cli-full-disk" / "disk").c_str());
  const fs::path dir = scratch("full-disk");
  const fs::path disk = dir / "disk";
  fs::create_directories(disk);
  if (::mount("tmpfs", disk.c_str(), "tmpfs", 0, "size=1m") != 0)
    GTEST_SKIP() << "cannot mount a small tmpfs here (not root)";
  const Unmounted unmount(disk);
  std::ofstream(dir / "deck.toml") << long_impact_deck();
  const CommandResult r =
      run(fmt::format("impact {} -o {} -q", (dir / "deck.toml").string(), (disk / "out").string()));
  EXPECT_EQ(r.status, 1) << r.out;
  EXPECT_NE(r.out.find("No space left on device"), std::string::npos) << r.out;
  std::ifstream csv(disk / "out" / "history.csv");
  std::string header, line;
  ASSERT_TRUE(std::getline(csv, header)) << r.out;
  const auto commas = std::count(header.begin(), header.end(), ',');
  std::size_t rows = 0;
  while (std::getline(csv, line)) {
    EXPECT_EQ(std::count(line.begin(), line.end(), ','), commas) << "row " << rows << ": " << line;
    ++rows;
  }
  EXPECT_GT(rows, 100U);
  for (const auto& entry : fs::directory_iterator(disk / "out")) // no temporary file left behind
    EXPECT_EQ(entry.path().string().find(".tmp"), std::string::npos) << entry.path();
  if (fs::exists(disk / "out" / "summary.json")) {
    EXPECT_NO_THROW((void)read_json(disk / "out" / "summary.json"));
  }
}

} // namespace
} // namespace plyimpact::test::full_disk_tests
