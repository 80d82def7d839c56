#pragma once
// Work that may take the process down — a library that aborts, segfaults, calls exit(), waits on a
// prompt or loops for ever (gmsh reading and meshing a script: docs/robustness.md) — run in a child
// process. The child is a fork of the caller: it runs `work` on the caller's memory and sends back the
// bytes it returns; the caller waits with a time limit and stays responsive to its signals. Whatever
// happens in the child, the caller gets those bytes or an IsolatedWorkError that says what happened.
#include <chrono>
#include <cstdint>
#include <functional>
#include <optional>
#include <stdexcept>
#include <string>

namespace plyimpact {

/// The child did not return its bytes: it threw (the exception's message), crashed (the signal), ended
/// the process itself (the exit code), ran out of time or memory, or the caller was interrupted.
class IsolatedWorkError : public std::runtime_error {
public:
  IsolatedWorkError(const std::string& message, bool thrown_by_work)
      : std::runtime_error(message), thrown_by_work_(thrown_by_work) {}
  /// True when `work` itself threw (the message is its exception's), false when the child failed.
  [[nodiscard]] bool thrown_by_work() const { return thrown_by_work_; }

private:
  bool thrown_by_work_;
};

struct IsolationLimits {
  std::chrono::milliseconds time{120000};    ///< the child is killed after this
  std::optional<std::uint64_t> memory_bytes; ///< address-space limit of the child (RLIMIT_AS)
};

/// Runs `work` in a child process (stdin, stdout and stderr on /dev/null, SIGINT and SIGTERM at their
/// defaults) and
/// returns what it returned. Throws IsolatedWorkError naming `what` ("gmsh meshing plate.geo") where the
/// child threw (with its message), died on a signal, exited before returning, exceeded `limits`, or the
/// caller received a signal while it waited (the child is then killed).
[[nodiscard]] std::string run_in_child_process(const std::function<std::string()>& work,
                                               const std::string& what, const IsolationLimits& limits = {});

} // namespace plyimpact
