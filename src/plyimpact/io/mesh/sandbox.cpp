// seccomp and Landlock around untrusted work (sandbox.hpp).
#include "plyimpact/io/mesh/sandbox.hpp"

#include <fcntl.h>
#include <fmt/format.h>
#include <linux/landlock.h>
#include <sched.h>
#include <seccomp.h>
#include <sys/prctl.h>
#include <sys/stat.h>
#include <sys/syscall.h>
#include <unistd.h>

#include <cerrno>
#include <cstdint>
#include <cstring>
#include <initializer_list>
#include <memory>

namespace plyimpact {

namespace {

// Landlock's access rights (linux/landlock.h; the values are the kernel's ABI and never change). The
// newer ones are spelt out here because Debian 12's kernel headers stop at ABI 2.
constexpr std::uint64_t fs_execute = 1ULL << 0U;
constexpr std::uint64_t fs_write_file = 1ULL << 1U;
constexpr std::uint64_t fs_read_file = 1ULL << 2U;
constexpr std::uint64_t fs_read_dir = 1ULL << 3U;
constexpr std::uint64_t fs_abi1 = (1ULL << 13U) - 1; ///< execute … make_sym (ABI 1)
constexpr std::uint64_t fs_refer = 1ULL << 13U;      ///< linking or renaming across folders (ABI 2)
constexpr std::uint64_t fs_truncate = 1ULL << 14U;   ///< truncate (ABI 3)
constexpr std::uint64_t fs_ioctl_dev = 1ULL << 15U;  ///< ioctl on devices (ABI 5)
/// The rights that apply to a file (not a folder): a rule on a file may grant only these.
constexpr std::uint64_t fs_file_rights =
    fs_execute | fs_write_file | fs_read_file | fs_truncate | fs_ioctl_dev;

/// Every right the kernel's ABI knows: all of them are refused unless a rule grants them.
std::uint64_t handled_rights(int abi) {
  std::uint64_t rights = fs_abi1;
  if (abi >= 2) rights |= fs_refer;
  if (abi >= 3) rights |= fs_truncate;
  if (abi >= 5) rights |= fs_ioctl_dev;
  return rights;
}

/// A file descriptor closed when it goes out of scope.
struct Descriptor {
  int fd = -1;
  Descriptor() = default;
  explicit Descriptor(int f) : fd(f) {}
  Descriptor(const Descriptor&) = delete;
  Descriptor& operator=(const Descriptor&) = delete;
  ~Descriptor() {
    if (fd >= 0) ::close(fd);
  }
};

/// Grants `rights` below `path` (or on it, for a file). A path that does not exist is left out.
void allow_beneath(int ruleset, const std::filesystem::path& path, std::uint64_t rights) {
  const Descriptor p(::open(path.c_str(), O_PATH | O_CLOEXEC)); // NOLINT(cppcoreguidelines-pro-type-vararg)
  if (p.fd < 0) return;
  struct stat st {};
  if (::fstat(p.fd, &st) != 0) return;
  landlock_path_beneath_attr rule{};
  rule.allowed_access = S_ISDIR(st.st_mode) ? rights : (rights & fs_file_rights);
  rule.parent_fd = p.fd;
  if (::syscall(SYS_landlock_add_rule, ruleset, LANDLOCK_RULE_PATH_BENEATH, &rule, 0) != 0)
    throw SandboxError(
        fmt::format("Landlock refused a rule for {} ({})", path.string(), std::strerror(errno)));
}

/// Landlock: reads below policy.readable, everything below policy.writable, nothing else.
void restrict_files(const SandboxPolicy& policy, int abi) {
  const std::uint64_t handled = handled_rights(abi);
  landlock_ruleset_attr attr{};
  attr.handled_access_fs = handled;
  const Descriptor ruleset(static_cast<int>(::syscall(SYS_landlock_create_ruleset, &attr, sizeof attr, 0)));
  if (ruleset.fd < 0)
    throw SandboxError(fmt::format("Landlock is there but refused a ruleset ({})", std::strerror(errno)));
  for (const std::filesystem::path& p : policy.readable)
    allow_beneath(ruleset.fd, p, fs_read_file | fs_read_dir);
  allow_beneath(ruleset.fd, "/dev/null", fs_read_file | fs_write_file);
  if (!policy.writable.empty()) allow_beneath(ruleset.fd, policy.writable, handled);
  if (::syscall(SYS_landlock_restrict_self, ruleset.fd, 0) != 0)
    throw SandboxError(fmt::format("Landlock refused to restrict the process ({})", std::strerror(errno)));
}

/// The condition "argument `arg` & mask == value" (what SCMP_A0 … SCMP_A5 make with a compound literal, a
/// C99 feature that C++ does not have).
scmp_arg_cmp masked_equal(unsigned arg, scmp_datum_t mask, scmp_datum_t value) {
  scmp_arg_cmp c{};
  c.arg = arg;
  c.op = SCMP_CMP_MASKED_EQ;
  c.datum_a = mask;
  c.datum_b = value;
  return c;
}

/// A libseccomp filter released when it goes out of scope.
struct Filter {
  scmp_filter_ctx ctx = seccomp_init(SCMP_ACT_ALLOW);
  Filter() = default;
  Filter(const Filter&) = delete;
  Filter& operator=(const Filter&) = delete;
  ~Filter() { seccomp_release(ctx); }

  void add(std::uint32_t action, int syscall) const {
    if (seccomp_rule_add(ctx, action, syscall, 0) != 0) refused(syscall);
  }
  void add(std::uint32_t action, int syscall, scmp_arg_cmp condition) const {
    if (seccomp_rule_add(ctx, action, syscall, 1, condition) != 0) refused(syscall);
  }
  [[noreturn]] static void refused(int syscall) {
    char* name = seccomp_syscall_resolve_num_arch(SCMP_ARCH_NATIVE, syscall);
    const std::string what = name != nullptr ? name : std::to_string(syscall);
    std::free(name); // NOLINT(cppcoreguidelines-no-malloc,cppcoreguidelines-owning-memory): libseccomp's
    throw SandboxError(fmt::format("seccomp refused a rule for {}", what));
  }
};

/// Where the kernel has no Landlock: no file opened for writing, created, removed, renamed or linked.
void refuse_every_write(const Filter& f) {
  const std::uint32_t refuse = SCMP_ACT_ERRNO(EACCES);
  for (const unsigned flag : {unsigned{O_WRONLY}, unsigned{O_RDWR}, unsigned{O_CREAT}, unsigned{O_TRUNC}}) {
    f.add(refuse, SCMP_SYS(open), masked_equal(1, flag, flag));
    f.add(refuse, SCMP_SYS(openat), masked_equal(2, flag, flag));
  }
  // openat2's flags are in a structure: ENOSYS makes the C library fall back to openat
  f.add(SCMP_ACT_ERRNO(ENOSYS), SCMP_SYS(openat2));
  for (const int nr : {SCMP_SYS(creat), SCMP_SYS(unlink), SCMP_SYS(unlinkat), SCMP_SYS(rename),
                       SCMP_SYS(renameat), SCMP_SYS(renameat2), SCMP_SYS(mkdir), SCMP_SYS(mkdirat),
                       SCMP_SYS(rmdir), SCMP_SYS(link), SCMP_SYS(linkat), SCMP_SYS(symlink),
                       SCMP_SYS(symlinkat), SCMP_SYS(truncate), SCMP_SYS(mknod), SCMP_SYS(mknodat)})
    f.add(refuse, nr);
}

/// seccomp: no process, no program, no socket, no tracing; threads allowed.
void restrict_system_calls(bool without_landlock) {
  const Filter f;
  if (f.ctx == nullptr) throw SandboxError("seccomp could not be initialised");
  const std::uint32_t kill = SCMP_ACT_KILL_PROCESS;
  for (const int nr : {SCMP_SYS(execve), SCMP_SYS(execveat), SCMP_SYS(fork), SCMP_SYS(vfork),
                       SCMP_SYS(ptrace), SCMP_SYS(process_vm_readv), SCMP_SYS(process_vm_writev)})
    f.add(kill, nr);
  // clone3 passes its flags in a structure seccomp cannot read: ENOSYS makes the C library use clone
  f.add(SCMP_ACT_ERRNO(ENOSYS), SCMP_SYS(clone3));
  f.add(kill, SCMP_SYS(clone), masked_equal(0, CLONE_THREAD, 0)); // a process, not a thread
  // sockets are refused, not fatal: the C library may try one (a name service) and go on without it
  for (const int nr : {SCMP_SYS(socket), SCMP_SYS(socketpair), SCMP_SYS(connect), SCMP_SYS(bind),
                       SCMP_SYS(listen), SCMP_SYS(accept), SCMP_SYS(accept4)})
    f.add(SCMP_ACT_ERRNO(EACCES), nr);
  if (without_landlock) refuse_every_write(f);
  if (const int rc = seccomp_load(f.ctx); rc != 0)
    throw SandboxError(fmt::format("the kernel refused the seccomp filter ({})", std::strerror(-rc)));
}

} // namespace

PrivateFolder::PrivateFolder() {
  std::error_code ec;
  std::string name = (std::filesystem::temp_directory_path(ec) / "plyimpact-sandbox-XXXXXX").string();
  if (ec || ::mkdtemp(name.data()) == nullptr)
    throw SandboxError(
        fmt::format("cannot make a private temporary folder ({})", ec ? ec.message() : std::strerror(errno)));
  path_ = name;
}

PrivateFolder::~PrivateFolder() {
  std::error_code ec;
  std::filesystem::remove_all(path_, ec); // what the work left there; nothing to report on failure
}

std::vector<std::filesystem::path> system_read_paths() {
  return {"/usr",        "/lib", "/lib64", "/etc/ld.so.cache", "/proc/self", "/sys/devices/system/cpu",
          "/dev/urandom"};
}

int landlock_abi() {
  const long abi = ::syscall(SYS_landlock_create_ruleset, nullptr, 0, LANDLOCK_CREATE_RULESET_VERSION);
  return abi < 0 ? 0 : static_cast<int>(abi);
}

void enter_sandbox(const SandboxPolicy& policy) {
  // both need it: no program started later could gain privileges the process does not have
  if (::prctl(PR_SET_NO_NEW_PRIVS, 1, 0, 0, 0) != 0) // NOLINT(cppcoreguidelines-pro-type-vararg)
    throw SandboxError(fmt::format("no_new_privs refused ({})", std::strerror(errno)));
  const int abi = policy.landlock ? landlock_abi() : 0;
  if (abi > 0) restrict_files(policy, abi);
  restrict_system_calls(abi == 0);
}

} // namespace plyimpact
