// Work run in a child process (io/system/child_process.hpp): whatever the child does — return, throw, abort,
// segfault, exit, loop for ever — the caller gets the bytes or an IsolatedWorkError saying what happened,
// and a signal to the waiting caller stops the child instead of being ignored until it finishes.
#include "plyimpact/io/system/child_process.hpp"

#include <gtest/gtest.h>

#include <pthread.h>

#include <atomic>
#include <chrono>
#include <csignal>
#include <cstdlib>
#include <stdexcept>
#include <string>
#include <thread>

namespace plyimpact::child_process_tests {
namespace {

/// The message of the IsolatedWorkError `work` ends in, and whether the work itself threw it.
std::pair<std::string, bool> failure_of(const std::function<std::string()>& work,
                                        IsolationLimits limits = {}) {
  try {
    (void)run_in_child_process(work, "the work", limits);
  } catch (const IsolatedWorkError& e) {
    return {e.what(), e.thrown_by_work()};
  }
  return {"", false};
}

TEST(ChildProcess, ReturnsTheBytesTheWorkReturned) {
  std::string big(3'000'000, 'x'); // more than a pipe holds: the caller reads while the child writes
  big[12345] = '\0';
  EXPECT_EQ(run_in_child_process([&] { return big; }, "the work"), big);
  EXPECT_EQ(run_in_child_process([] { return std::string(); }, "the work"), "");
}

TEST(ChildProcess, AnExceptionOfTheWorkComesBackWithItsMessage) {
  const auto [what, thrown] =
      failure_of([]() -> std::string { throw std::invalid_argument("no such plate"); });
  EXPECT_EQ(what, "no such plate");
  EXPECT_TRUE(thrown);
}

TEST(ChildProcess, AnAbortOrACrashEndsTheChildNotTheCaller) {
  const auto [aborted, thrown] = failure_of([]() -> std::string { std::abort(); });
  EXPECT_NE(aborted.find("the work: it crashed (signal 6, SIGABRT"), std::string::npos) << aborted;
  EXPECT_FALSE(thrown);
  const auto [segfault, _] = failure_of([]() -> std::string {
    std::raise(SIGSEGV);
    return "";
  });
  EXPECT_NE(segfault.find("SIGSEGV"), std::string::npos) << segfault;
  // gmsh 4.8 throws std::string from inside an OpenMP region, which terminates (the rig abort).
  const auto [terminated, __] = failure_of([]() -> std::string { std::terminate(); });
  EXPECT_NE(terminated.find("SIGABRT"), std::string::npos) << terminated;
}

TEST(ChildProcess, AChildThatExitsBeforeReturningIsNamedSo) {
  const auto [what, thrown] = failure_of([]() -> std::string { std::exit(0); }); // a .geo's Exit
  // exit code 0, unless the leak sanitizer's check at exit sets its own
  EXPECT_NE(what.find("ended the process itself with exit code"), std::string::npos) << what;
  EXPECT_FALSE(thrown);
}

TEST(ChildProcess, WorkPastTheTimeLimitIsKilled) {
  IsolationLimits limits;
  limits.time = std::chrono::seconds(1);
  const auto t0 = std::chrono::steady_clock::now();
  const auto [what, thrown] = failure_of(
      []() -> std::string {
        for (;;)
          std::this_thread::sleep_for(std::chrono::seconds(1));
      },
      limits);
  const double waited = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  EXPECT_NE(what.find("stopped after 1 s, the time limit"), std::string::npos) << what;
  EXPECT_LT(waited, 5.0);
}

extern "C" void ignore_signal(int /*sig*/) {}

TEST(ChildProcess, ASignalToTheWaitingCallerStopsTheChild) {
  // As Ctrl-C reaches the command line's handler: a handler without SA_RESTART, the signal sent to the
  // waiting thread into a child that would take a minute. It is sent every 0.2 s until the call returns:
  // one that arrives before the caller waits (a fork of a sanitized process can take longer than that)
  // interrupts nothing, and the next one must stop the child.
  struct sigaction action {};
  action.sa_handler = ignore_signal;
  struct sigaction previous {};
  ASSERT_EQ(sigaction(SIGUSR1, &action, &previous), 0);
  const pthread_t waiter = pthread_self();
  std::atomic<bool> returned = false;
  std::thread sender([waiter, &returned] {
    while (!returned) {
      std::this_thread::sleep_for(std::chrono::milliseconds(200));
      if (!returned) pthread_kill(waiter, SIGUSR1);
    }
  });
  const auto t0 = std::chrono::steady_clock::now();
  const auto [what, thrown] = failure_of([]() -> std::string {
    std::this_thread::sleep_for(std::chrono::seconds(60));
    return "";
  });
  const double waited = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  returned = true;
  sender.join();
  sigaction(SIGUSR1, &previous, nullptr);
  EXPECT_NE(what.find("the work: interrupted"), std::string::npos) << what;
  EXPECT_LT(waited, 10.0);
}

} // namespace
} // namespace plyimpact::child_process_tests
