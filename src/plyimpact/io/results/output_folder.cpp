#include "plyimpact/io/results/output_folder.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cerrno>
#include <chrono>
#include <cstring>
#include <ctime>
#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

namespace plyimpact {

namespace fs = std::filesystem;

namespace {

/// Files every kind of run writes (impact, static, modal, buckling, threshold, sweep).
constexpr std::array<std::string_view, 19> result_files{
    "deck.toml",  "provenance.json",     "summary.json",      "history.csv",
    "report.txt", "probes.csv",          "damage_onsets.csv", "damage_area.csv",
    "plate.pvd",  "layers.pvd",          "displacements.csv", "modes.csv",
    "sweep.json", "sweep.csv",           "damage_maps",       "paraview",
    "plots",      "damage_elements.csv", "report.html"};
constexpr std::string_view cases_folder = "cases";
/// Written first by every run (impact, static, modal, buckling, threshold: provenance.json; a sweep:
/// sweep.json, cases/) or last (summary.json): a folder holds results only when one of them is there.
constexpr std::array<std::string_view, 4> run_markers{"provenance.json", "summary.json", "sweep.json",
                                                      "cases"};

bool starts_with(std::string_view s, std::string_view prefix) {
  return s.substr(0, prefix.size()) == prefix;
}

bool ends_with(std::string_view s, std::string_view suffix) {
  return s.size() >= suffix.size() && s.substr(s.size() - suffix.size()) == suffix;
}

/// The name without the suffix of an unfinished atomic write: ".tmp.<pid>" or ".tmp".
std::string_view without_temporary_suffix(std::string_view name) {
  const std::size_t at = name.rfind(".tmp");
  if (at == std::string_view::npos || at == 0) return name;
  const std::string_view rest = name.substr(at + 4);
  if (rest.empty()) return name.substr(0, at);
  if (rest[0] == '.' && rest.size() > 1 &&
      std::all_of(rest.begin() + 1, rest.end(), [](char c) { return c >= '0' && c <= '9'; }))
    return name.substr(0, at);
  return name;
}

std::string errno_text() {
  return std::strerror(errno);
}

/// The lock file's text: who holds the folder.
std::string holder_text(std::string_view command) {
  std::array<char, 256> host{};
  if (::gethostname(host.data(), host.size() - 1) != 0) host[0] = '\0';
  const std::time_t now = std::chrono::system_clock::to_time_t(std::chrono::system_clock::now());
  std::tm utc{};
  ::gmtime_r(&now, &utc);
  std::array<char, 32> stamp{};
  std::strftime(stamp.data(), stamp.size(), "%Y-%m-%dT%H:%M:%SZ", &utc);
  return fmt::format("pid {} on host {}, started {}: {}\n", static_cast<long>(::getpid()), host.data(),
                     stamp.data(), command);
}

std::string read_fd(int fd) {
  std::string text;
  std::array<char, 1024> buf{};
  ::lseek(fd, 0, SEEK_SET);
  for (ssize_t n = 0; (n = ::read(fd, buf.data(), buf.size())) > 0;)
    text.append(buf.data(), static_cast<std::size_t>(n));
  while (!text.empty() && (text.back() == '\n' || text.back() == '\r'))
    text.pop_back();
  return text;
}

} // namespace

fs::path default_output_dir(std::string_view output_dir, std::string_view deck_path) {
  return fs::path(output_dir.empty() ? std::string_view("results") : output_dir) / fs::path(deck_path).stem();
}

bool is_result_name(std::string_view name) {
  const std::string_view n = without_temporary_suffix(name);
  if (n == cases_folder) return true;
  if (std::find(result_files.begin(), result_files.end(), n) != result_files.end()) return true;
  // field_t<time>.csv, and the damage maps of versions that wrote them at the top level
  return (starts_with(n, "field_t") && ends_with(n, ".csv")) || starts_with(n, "damage_map_");
}

std::vector<std::string> results_in(const fs::path& dir) {
  std::vector<std::string> found;
  bool marked = false;
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(dir, ec)) {
    const std::string name = entry.path().filename().string();
    if (!is_result_name(name)) continue;
    found.push_back(name);
    const std::string_view n = without_temporary_suffix(name);
    marked = marked || std::find(run_markers.begin(), run_markers.end(), n) != run_markers.end();
  }
  // A folder that no run has marked (a user's own folder with a deck.toml in it) holds no results:
  // nothing in it is refused or removed.
  if (!marked) return {};
  std::sort(found.begin(), found.end());
  return found;
}

void clear_results(const fs::path& dir) {
  for (const std::string& name : results_in(dir)) {
    std::error_code ec;
    fs::remove_all(dir / name, ec);
    if (ec)
      throw std::runtime_error(fmt::format("{}: cannot remove it to overwrite the folder: {}",
                                           (dir / name).string(), ec.message()));
  }
}

OutputLock::OutputLock(fs::path dir, std::string_view command) : dir_(std::move(dir)) {
  std::error_code ec;
  fs::create_directories(dir_, ec);
  if (ec)
    throw std::runtime_error(
        fmt::format("{}: cannot create the results folder: {}", dir_.string(), ec.message()));
  const fs::path file = dir_ / lock_file_name;
  // A lock file unlinked by its previous holder between our open and our flock is not the folder's
  // lock any more: lock again until the file locked is the one at the path.
  for (int attempt = 0; attempt < 100; ++attempt) {
    const int fd = ::open(file.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
    if (fd < 0)
      throw std::runtime_error(
          fmt::format("{}: cannot create the lock file: {}", file.string(), errno_text()));
    if (::flock(fd, LOCK_EX | LOCK_NB) != 0) {
      const int error = errno;
      const std::string holder = read_fd(fd);
      ::close(fd);
      if (error != EWOULDBLOCK)
        throw std::runtime_error(fmt::format("{}: cannot lock: {}", file.string(), std::strerror(error)));
      throw FolderInUse(fmt::format(
          "{} is in use by another plyimpact run ({}): wait until it ends, or give another folder with -o",
          dir_.string(), holder.empty() ? "it has not written its name yet" : holder));
    }
    struct stat at_path {};
    struct stat locked {};
    if (::fstat(fd, &locked) == 0 && ::stat(file.c_str(), &at_path) == 0 && at_path.st_ino == locked.st_ino &&
        at_path.st_dev == locked.st_dev) {
      const std::string text = holder_text(command);
      if (::ftruncate(fd, 0) != 0 || ::pwrite(fd, text.data(), text.size(), 0) < 0) {
        const std::string why = errno_text();
        ::close(fd);
        throw std::runtime_error(fmt::format("{}: cannot write the lock file: {}", file.string(), why));
      }
      fd_ = fd;
      return;
    }
    ::close(fd);
  }
  throw FolderInUse(
      fmt::format("{}: the lock file keeps changing: another run is starting there", dir_.string()));
}

OutputLock::OutputLock(OutputLock&& other) noexcept : dir_(std::move(other.dir_)), fd_(other.fd_) {
  other.fd_ = -1;
}

OutputLock::~OutputLock() {
  if (fd_ < 0) return;
  std::error_code ec;
  fs::remove(dir_ / lock_file_name, ec); // while still locked: nobody can take a lock on it meanwhile
  ::close(fd_);
}

OutputLock claim_output_folder(const fs::path& dir, std::string_view command, const ClaimOptions& options) {
  OutputLock lock(dir, command);
  std::vector<std::string> others;
  for (const std::string& name : results_in(dir))
    if (std::find(options.keep.begin(), options.keep.end(), std::string(without_temporary_suffix(name))) ==
        options.keep.end())
      others.push_back(name);
  if (others.empty()) return lock;
  if (options.overwrite) {
    clear_results(dir);
    return lock;
  }
  std::string listed;
  for (std::size_t i = 0; i < others.size() && i < 4; ++i)
    listed += (i > 0 ? ", " : "") + others[i];
  if (others.size() > 4) listed += fmt::format(" and {} more", others.size() - 4);
  throw FolderHoldsResults(fmt::format("{} holds the results of another run ({}): add --overwrite to replace "
                                       "them, or give another folder with -o",
                                       dir.string(), listed));
}

std::string command_line(int argc, const char* const* argv) {
  std::string s;
  for (int i = 0; i < argc; ++i) {
    if (i > 0) s += ' ';
    s += argv[i];
  }
  return s;
}

} // namespace plyimpact
