#pragma once
// The sandbox of a child process that runs untrusted work: gmsh reading a deck's .geo or .msh (issue 77;
// docs/robustness.md, "The sandbox"). A gmsh script is a program, and a second parser of its language
// (io/mesh/geo_script.hpp) can never be proven to agree with gmsh's own: so the policy is also enforced by
// the operating system, in the child, before gmsh reads anything.
//
//   - seccomp (libseccomp): starting a process or a program (fork, vfork, clone without CLONE_THREAD,
//     execve, execveat), opening or using a socket, and tracing another process end the child at once
//     with SIGSYS; threads are allowed (clone3 answers ENOSYS, so that the C library falls back to clone,
//     whose flags seccomp can read).
//   - Landlock (Linux 5.13 and later, where the kernel enables it): files may be read only below the
//     folders named by the policy (the script's folder, the system's libraries) and written only below
//     the child's private temporary folder. Where the kernel has no Landlock, seccomp refuses every
//     open for writing, every creation, removal and renaming of a file instead.
//
// Both are irreversible for the process that enters them, and the kernel passes them on to any child it
// might start: nothing the work does can lift them.
#include <filesystem>
#include <stdexcept>
#include <vector>

namespace plyimpact {

/// The sandbox could not be entered (the kernel refused the filter); the message says which part.
class SandboxError : public std::runtime_error {
public:
  using std::runtime_error::runtime_error;
};

/// What sandboxed work may touch.
struct SandboxPolicy {
  std::vector<std::filesystem::path> readable; ///< folders (or files) it may read below
  std::filesystem::path writable;              ///< the one folder it may write in (empty: none)
  /// Landlock where the kernel has it; false (the tests) takes the path of a kernel without it: seccomp
  /// refuses every write, the private folder's too, and reads are not confined.
  bool landlock = true;
};

/// A private temporary folder (mode 0700, a fresh name below the system's temporary folder) for the
/// sandboxed work to write in, removed with everything in it when this goes out of scope.
class PrivateFolder {
public:
  PrivateFolder(); ///< throws SandboxError when it cannot be made
  ~PrivateFolder();
  PrivateFolder(const PrivateFolder&) = delete;
  PrivateFolder& operator=(const PrivateFolder&) = delete;
  [[nodiscard]] const std::filesystem::path& path() const { return path_; }

private:
  std::filesystem::path path_;
};

/// The folders every sandboxed gmsh needs to read: the system's libraries and data (/usr, /lib*), the
/// dynamic loader's cache, its own /proc entry, the processor list and /dev/null, /dev/urandom.
[[nodiscard]] std::vector<std::filesystem::path> system_read_paths();

/// The highest Landlock ABI the kernel offers, 0 where it has none.
[[nodiscard]] int landlock_abi();

/// Puts the calling process in the sandbox of `policy` (see above). Throws SandboxError where the kernel
/// refuses the seccomp filter; a kernel without Landlock is covered by seccomp's write rules.
void enter_sandbox(const SandboxPolicy& policy);

} // namespace plyimpact
