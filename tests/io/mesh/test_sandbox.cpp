// The sandbox of untrusted work (io/mesh/sandbox.hpp; docs/robustness.md, "The sandbox"): in a child process
// that entered it, starting a program ends the child (SIGSYS), writing outside the private folder and reading
// outside the readable folders are refused by the kernel, and what gmsh needs — threads, its libraries, the
// private folder — still works.
#include "plyimpact/io/mesh/sandbox.hpp"
#include "plyimpact/io/system/child_process.hpp"
#include "support/cli.hpp"

#include <gtest/gtest.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>
#include <thread>

namespace plyimpact::sandbox_tests {
namespace {

namespace fs = std::filesystem;

/// Limits that put the child in the sandbox: reads below `readable` and the system's, writes in `folder`.
IsolationLimits sandboxed(const fs::path& readable, const fs::path& folder) {
  IsolationLimits limits;
  limits.time = std::chrono::seconds(20);
  SandboxPolicy policy{system_read_paths(), folder};
  policy.readable.push_back(readable);
  limits.sandbox = policy;
  return limits;
}

TEST(Sandbox, AProgramStartedInTheSandboxEndsTheChildAndRunsNothing) {
  const fs::path dir = test::scratch("sandbox-program");
  const PrivateFolder scratch;
  const fs::path marker = scratch.path() / "ran"; // writable for the child: only the sandbox can stop it
  try {
    (void)run_in_child_process(
        [&] {
          const int status = std::system(("touch " + marker.string()).c_str()); // NOLINT(cert-env33-c)
          return std::to_string(status);
        },
        "the work", sandboxed(dir, scratch.path()));
    FAIL() << "the child returned: the program was not stopped";
  } catch (const IsolatedWorkError& e) {
    EXPECT_EQ(e.cause(), IsolatedWorkError::Cause::sandbox) << e.what();
    EXPECT_NE(std::string(e.what()).find("the sandbox stopped it"), std::string::npos) << e.what();
  }
  EXPECT_FALSE(fs::exists(marker));
}

TEST(Sandbox, WritesOutsideThePrivateFolderAreRefusedAndInsideItAllowed) {
  const fs::path dir = test::scratch("sandbox-writes");
  const PrivateFolder scratch;
  const std::string result = run_in_child_process(
      [&] {
        const bool outside = static_cast<bool>(std::ofstream(dir / "pwned") << "x");
        const bool inside = static_cast<bool>(std::ofstream(scratch.path() / "mesh.msh") << "x");
        return std::string(outside ? "outside" : "-") + (inside ? "inside" : "-");
      },
      "the work", sandboxed(dir, scratch.path()));
  EXPECT_EQ(result, "-inside");
  EXPECT_FALSE(fs::exists(dir / "pwned"));
}

TEST(Sandbox, ReadsOutsideTheReadableFoldersAreRefused) {
  if (landlock_abi() == 0) GTEST_SKIP() << "the kernel has no Landlock: reads are not confined";
  const fs::path dir = test::scratch("sandbox-reads");
  std::ofstream(dir / "plate.geo") << "lc = 1;\n";
  const PrivateFolder scratch;
  const std::string result = run_in_child_process(
      [&] {
        const bool own = static_cast<bool>(std::ifstream(dir / "plate.geo"));
        const bool passwd = static_cast<bool>(std::ifstream("/etc/passwd"));
        return std::string(own ? "own" : "-") + (passwd ? "passwd" : "-");
      },
      "the work", sandboxed(dir, scratch.path()));
  EXPECT_EQ(result, "own-");
}

TEST(Sandbox, WithoutLandlockSeccompRefusesEveryWrite) {
  const fs::path dir = test::scratch("sandbox-no-landlock");
  const PrivateFolder scratch;
  IsolationLimits limits = sandboxed(dir, scratch.path());
  limits.sandbox->landlock = false; // as on a kernel without Landlock
  const std::string result = run_in_child_process(
      [&] {
        const bool outside = static_cast<bool>(std::ofstream(dir / "pwned") << "x");
        const bool inside = static_cast<bool>(std::ofstream(scratch.path() / "mesh.msh") << "x");
        std::error_code ec;
        const bool folder = fs::create_directory(dir / "pwned-folder", ec);
        const bool reads = static_cast<bool>(std::ifstream("/etc/hostname"));
        return std::string(outside ? "outside" : "-") + (inside ? "inside" : "-") +
               (folder ? "folder" : "-") + (reads ? "reads" : "-");
      },
      "the work", limits);
  EXPECT_EQ(result, "---reads"); // reads are not confined without Landlock
  EXPECT_FALSE(fs::exists(dir / "pwned"));
  EXPECT_FALSE(fs::exists(dir / "pwned-folder"));
}

TEST(Sandbox, ThreadsStillRunInTheSandbox) {
  const PrivateFolder scratch;
  const std::string result = run_in_child_process(
      [] {
        int sum = 0;
        std::thread t([&] { sum = 42; });
        t.join();
        return std::to_string(sum);
      },
      "the work", sandboxed(scratch.path(), scratch.path()));
  EXPECT_EQ(result, "42");
}

TEST(Sandbox, ThePrivateFolderIsRemovedWithWhatIsInIt) {
  fs::path kept;
  {
    const PrivateFolder scratch;
    kept = scratch.path();
    std::ofstream(kept / "left.txt") << "x";
    EXPECT_TRUE(fs::is_directory(kept));
    EXPECT_EQ(fs::status(kept).permissions() & fs::perms::all, fs::perms::owner_all);
  }
  EXPECT_FALSE(fs::exists(kept));
}

} // namespace
} // namespace plyimpact::sandbox_tests
