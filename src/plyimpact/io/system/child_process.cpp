// A fork that runs one piece of work and sends back its bytes (child_process.hpp).
#include "plyimpact/io/system/child_process.hpp"

#include <fcntl.h>
#include <fmt/format.h>
#include <poll.h>
#include <sys/prctl.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>

namespace plyimpact {

namespace {

/// Record kinds the child writes first.
constexpr char returned = 'R';
constexpr char threw = 'E';

/// Writes all of `bytes` to `fd` (the child's end of the pipe); false when the parent went away.
bool write_all(int fd, const std::string& bytes) {
  std::size_t done = 0;
  while (done < bytes.size()) {
    const ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    done += static_cast<std::size_t>(n);
  }
  return true;
}

/// An on_exit handler: the process ends with `status` without running what exit() would run next.
void exit_at_once(int status, void* /*unused*/) {
  _exit(status);
}

/// The child: defaults for the signals the caller handles, no terminal input, the memory limit, the work,
/// its record, and _exit (no atexit handlers or static destructors of the caller's libraries).
[[noreturn]] void run_child(int fd, const std::function<std::string()>& work, const IsolationLimits& limits) {
  // The caller's handlers off: Ctrl-C and SIGTERM end the child, and a crash ends it on its signal even
  // where a sanitizer had caught it to exit with a code of its own.
  for (const int sig : {SIGINT, SIGTERM, SIGPIPE, SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGABRT})
    std::signal(sig, SIG_DFL);
  // and it dies with the caller's thread: a caller ended by its watchdog (Ctrl-C) leaves no gmsh running
  (void)::prctl(PR_SET_PDEATHSIG, SIGKILL); // NOLINT(cppcoreguidelines-pro-type-vararg)
  // and the caller's terminate handler too (the program's exits with 4): an exception that escapes the work
  // (gmsh throws from inside its threads) aborts the child, which the caller reports as the crash it is
  std::set_terminate([] { std::abort(); });
  // A work that calls exit() (gmsh's Exit) ends here, with its code, before the handlers registered before
  // the fork: the caller's static destructors, and LeakSanitizer's check at exit in the sanitizer build,
  // which starts a tracer process that the sandbox refuses (the Exit cases were reported as sandbox stops)
  (void)::on_exit(exit_at_once, nullptr);
  if (const int null = ::open("/dev/null", O_RDWR); null >= 0) { // no prompt, and nothing on the terminal:
    ::dup2(null, STDIN_FILENO);                                  // what the work says comes back in
    ::dup2(null, STDOUT_FILENO);                                 // its record (an abort's message too)
    ::dup2(null, STDERR_FILENO);
  }
  if (limits.memory_bytes) {
    const rlimit limit{*limits.memory_bytes, *limits.memory_bytes};
    (void)::setrlimit(RLIMIT_AS, &limit);
  }
  std::string record;
  try {
    if (limits.sandbox) enter_sandbox(*limits.sandbox);
    record = returned + work();
  } catch (const SandboxError& e) {
    record = threw + fmt::format("cannot enter the sandbox that keeps it from running programs and writing "
                                 "files: {} (docs/robustness.md, \"The sandbox\")",
                                 e.what());
  } catch (const std::exception& e) {
    record = threw + std::string(e.what());
  } catch (...) {
    record = threw + std::string("an exception that is not a std::exception");
  }
  _exit(write_all(fd, record) ? 0 : 1);
}

/// What a child that returned no record did, from its wait status.
std::string how_it_ended(int status, std::uint64_t memory_bytes_or_zero, bool sandboxed) {
  if (WIFSIGNALED(status)) {
    const int sig = WTERMSIG(status);
    if (sig == SIGSYS && sandboxed)
      return "the sandbox stopped it: it tried to start a process or run a program (a shell command: "
             "System, SystemCall, OnelabRun), which plyimpact never lets a deck's files do "
             "(docs/robustness.md, \"The sandbox\")";
    const char* name = sigabbrev_np(sig);
    return fmt::format("it crashed (signal {}, SIG{}: {}){}", sig, name != nullptr ? name : "?",
                       strsignal(sig),
                       sig == SIGKILL && memory_bytes_or_zero > 0 ? " — perhaps out of memory" : "");
  }
  if (WIFEXITED(status))
    return fmt::format("it ended the process itself with exit code {} before it finished (a gmsh script's "
                       "Exit command, or gmsh giving up, does that)",
                       WEXITSTATUS(status));
  return "it stopped for an unknown reason";
}

/// Kills and reaps the child.
void kill_child(pid_t pid) {
  ::kill(pid, SIGKILL);
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
}

} // namespace

std::string run_in_child_process(const std::function<std::string()>& work, const std::string& what,
                                 const IsolationLimits& limits) {
  int fds[2];
  if (::pipe2(fds, O_CLOEXEC) != 0)
    throw IsolatedWorkError(fmt::format("{}: cannot create a pipe ({})", what, std::strerror(errno)), false);
  std::fflush(nullptr); // what the caller has buffered is written once, not again by the child
  const pid_t pid = ::fork();
  if (pid < 0) {
    ::close(fds[0]);
    ::close(fds[1]);
    throw IsolatedWorkError(fmt::format("{}: cannot start a child process ({})", what, std::strerror(errno)),
                            false);
  }
  if (pid == 0) {
    ::close(fds[0]);
    run_child(fds[1], work, limits);
  }
  ::close(fds[1]);
  const auto deadline = std::chrono::steady_clock::now() + limits.time;
  std::string bytes;
  char buffer[65536];
  for (;;) {
    const auto left =
        std::chrono::duration_cast<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now());
    if (left.count() <= 0) {
      ::close(fds[0]);
      kill_child(pid);
      throw IsolatedWorkError(fmt::format("{}: stopped after {:g} s, the time limit: it would not finish",
                                          what, static_cast<double>(limits.time.count()) / 1000.0),
                              IsolatedWorkError::Cause::time_limit);
    }
    pollfd p{fds[0], POLLIN, 0};
    const int ready = ::poll(&p, 1, static_cast<int>(std::min<long long>(left.count(), 200)));
    if (ready < 0 && errno == EINTR) { // a signal for the caller (Ctrl-C, SIGTERM): stop the child
      ::close(fds[0]);
      kill_child(pid);
      throw IsolatedWorkError(fmt::format("{}: interrupted", what), IsolatedWorkError::Cause::interrupted);
    }
    if (ready <= 0) continue;
    const ssize_t n = ::read(fds[0], buffer, sizeof buffer);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break; // end of the record (or the child is gone)
    bytes.append(buffer, static_cast<std::size_t>(n));
  }
  ::close(fds[0]);
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  const bool clean_exit = WIFEXITED(status) && WEXITSTATUS(status) == 0;
  if (clean_exit && !bytes.empty() && bytes.front() == returned) return bytes.substr(1);
  if (clean_exit && !bytes.empty() && bytes.front() == threw) throw IsolatedWorkError(bytes.substr(1), true);
  const bool sandbox_stop = limits.sandbox && WIFSIGNALED(status) && WTERMSIG(status) == SIGSYS;
  throw IsolatedWorkError(
      fmt::format("{}: {}", what,
                  how_it_ended(status, limits.memory_bytes.value_or(0), limits.sandbox.has_value())),
      sandbox_stop ? IsolatedWorkError::Cause::sandbox : IsolatedWorkError::Cause::crashed_or_exited);
}

bool program_on_path(const std::string& name) {
  const char* path = std::getenv("PATH"); // NOLINT(concurrency-mt-unsafe): read, never set
  const std::string folders = path != nullptr ? path : "/usr/bin:/bin";
  std::size_t at = 0;
  for (;;) {
    const std::size_t colon = std::min(folders.find(':', at), folders.size());
    const std::filesystem::path candidate =
        std::filesystem::path(colon > at ? folders.substr(at, colon - at) : ".") / name;
    if (::access(candidate.c_str(), X_OK) == 0 && std::filesystem::is_regular_file(candidate)) return true;
    if (colon == folders.size()) return false;
    at = colon + 1;
  }
}

namespace {

/// The child of run_program: dies with its parent, runs in `folder`, writes into `out`, becomes the program.
[[noreturn]] void become_program(const std::vector<std::string>& argv, const std::filesystem::path& folder,
                                 int out, pid_t parent) {
  (void)::prctl(PR_SET_PDEATHSIG, SIGKILL); // NOLINT(cppcoreguidelines-pro-type-vararg)
  if (::getppid() != parent) _exit(127);    // the parent died before the line above
  for (const int sig : {SIGINT, SIGTERM, SIGPIPE})
    std::signal(sig, SIG_DFL);
  if (const int null = ::open("/dev/null", O_RDONLY); null >= 0) ::dup2(null, STDIN_FILENO); // NOLINT
  ::dup2(out, STDOUT_FILENO);
  ::dup2(out, STDERR_FILENO);
  if (::chdir(folder.c_str()) != 0) _exit(127);
  std::vector<char*> args;
  args.reserve(argv.size() + 1);
  for (const std::string& a : argv)
    args.push_back(
        const_cast<char*>(a.c_str())); // NOLINT(cppcoreguidelines-pro-type-const-cast): execvp's type
  args.push_back(nullptr);
  ::execvp(args.front(), args.data());
  _exit(127);
}

} // namespace

ProgramResult run_program(const std::vector<std::string>& argv, const std::filesystem::path& folder) {
  ProgramResult result;
  int fds[2];
  if (argv.empty() || ::pipe2(fds, O_CLOEXEC) != 0) return result;
  std::fflush(nullptr);
  const pid_t parent = ::getpid();
  const pid_t pid = ::fork();
  if (pid < 0) {
    ::close(fds[0]);
    ::close(fds[1]);
    return result;
  }
  if (pid == 0) {
    ::close(fds[0]);
    become_program(argv, folder, fds[1], parent);
  }
  ::close(fds[1]);
  char buffer[4096];
  for (;;) {
    const ssize_t n = ::read(fds[0], buffer, sizeof buffer);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break;
    result.output.append(buffer, static_cast<std::size_t>(n));
  }
  ::close(fds[0]);
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return result;
}

} // namespace plyimpact
