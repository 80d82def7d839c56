#pragma once
// Work that may take the process down — a library that aborts, segfaults, calls exit(), waits on a
// prompt or loops for ever (gmsh reading and meshing a script: docs/robustness.md) — run in a child
// process. The child is a fork of the caller: it runs `work` on the caller's memory and sends back the
// bytes it returns; the caller waits with a time limit and stays responsive to its signals. Whatever
// happens in the child, the caller gets those bytes or an IsolatedWorkError that says what happened.
#include "plyimpact/io/mesh/sandbox.hpp"

#include <chrono>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace plyimpact {

/// The child did not return its bytes: it threw (the exception's message), crashed (the signal), ended
/// the process itself (the exit code), ran out of time or memory, or the caller was interrupted.
class IsolatedWorkError : public std::runtime_error {
public:
  /// What ended the work.
  enum class Cause {
    work_threw,        ///< the work's own exception (the message is its)
    crashed_or_exited, ///< a signal, an exit of its own, or no child at all
    sandbox,           ///< the sandbox killed it: it tried to start a program (SIGSYS)
    interrupted,       ///< the caller got Ctrl-C or SIGTERM while it waited
    time_limit,        ///< it ran past IsolationLimits::time
  };
  IsolatedWorkError(const std::string& message, Cause cause) : std::runtime_error(message), cause_(cause) {}
  IsolatedWorkError(const std::string& message, bool thrown_by_work)
      : IsolatedWorkError(message, thrown_by_work ? Cause::work_threw : Cause::crashed_or_exited) {}
  [[nodiscard]] Cause cause() const { return cause_; }
  /// True when `work` itself threw (the message is its exception's), false when the child failed.
  [[nodiscard]] bool thrown_by_work() const { return cause_ == Cause::work_threw; }

private:
  Cause cause_;
};

struct IsolationLimits {
  std::chrono::milliseconds time{120000};    ///< the child is killed after this
  std::optional<std::uint64_t> memory_bytes; ///< address-space limit of the child (RLIMIT_AS)
  std::optional<SandboxPolicy> sandbox;      ///< the child enters it before the work (sandbox.hpp)
};

/// Runs `work` in a child process (stdin, stdout and stderr on /dev/null, SIGINT and SIGTERM at their
/// defaults, in `limits.sandbox` where given) and returns what it returned. Throws IsolatedWorkError naming
/// `what` ("gmsh meshing plate.geo") where the child threw (with its message), died on a signal, exited
/// before returning, exceeded `limits`, or the caller received a signal while it waited (the child is then
/// killed).
[[nodiscard]] std::string run_in_child_process(const std::function<std::string()>& work,
                                               const std::string& what, const IsolationLimits& limits = {});

/// What a program run by run_program did.
struct ProgramResult {
  int exit_code = -1; ///< its exit code; -1 where it died on a signal or could not start
  std::string output; ///< its stdout and stderr together
};

/// True where `name` is an executable file in one of PATH's folders (what `command -v` tells, without a
/// shell).
[[nodiscard]] bool program_on_path(const std::string& name);

/// Runs `argv` (argv[0] looked up in PATH) in `folder`, standard input /dev/null, its standard output and
/// error captured, SIGINT and SIGTERM at their defaults; no shell reads the arguments. The program dies
/// with the calling thread (PR_SET_PDEATHSIG): a plyimpact stopped by Ctrl-C or SIGTERM never leaves a
/// gnuplot running (issue 77). Waits for it to end.
[[nodiscard]] ProgramResult run_program(const std::vector<std::string>& argv,
                                        const std::filesystem::path& folder);

} // namespace plyimpact
