#pragma once
// A results folder that cannot mix runs (docs/output.md): while a run writes into it, the folder is
// locked (`.plyimpact.lock`, an flock held by the running process and naming it); a folder that holds
// another run's results is refused unless the user asks to overwrite them, and then those files are
// removed first. The lock dies with its process, so a killed run leaves no stale lock behind.
#include <filesystem>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace plyimpact {

/// The lock file's name inside a results folder.
inline constexpr std::string_view lock_file_name = ".plyimpact.lock";

/// Another process holds the folder's lock; what() names it (pid, host, command, start time).
class FolderInUse : public std::runtime_error {
public:
  using std::runtime_error::runtime_error;
};

/// The folder holds another run's results and overwriting was not asked for; what() lists them.
class FolderHoldsResults : public std::runtime_error {
public:
  using std::runtime_error::runtime_error;
};

/// The folder a command writes when no -o is given: `<[output] dir>/<deck file name without .toml>`
/// (`results/<deck>/` by default), relative to the current folder.
[[nodiscard]] std::filesystem::path default_output_dir(std::string_view output_dir,
                                                       std::string_view deck_path);

/// True for a name that plyimpact writes into a results folder (summary.json, history.csv, cases/, the
/// temporary files of an interrupted write, ...), false for anything else (the lock file included).
[[nodiscard]] bool is_result_name(std::string_view name);

/// The entries of `dir` that are results of a run (is_result_name), in name order; none unless a run
/// marked the folder (provenance.json, summary.json, sweep.json or cases/ is there), so a user's own
/// folder holding, say, deck.toml is never refused nor cleared.
[[nodiscard]] std::vector<std::string> results_in(const std::filesystem::path& dir);

/// Removes every result entry of `dir` (results_in); other files stay. Throws naming a file it cannot
/// remove.
void clear_results(const std::filesystem::path& dir);

/// Exclusive use of a results folder for the life of this object: created (with its parents) and locked
/// on construction, unlocked and the lock file removed on destruction.
class OutputLock {
public:
  /// Throws FolderInUse when another process holds the lock. `command` is recorded for its message.
  OutputLock(std::filesystem::path dir, std::string_view command);
  ~OutputLock();
  OutputLock(OutputLock&& other) noexcept;
  OutputLock& operator=(OutputLock&&) = delete;
  OutputLock(const OutputLock&) = delete;
  OutputLock& operator=(const OutputLock&) = delete;

  [[nodiscard]] const std::filesystem::path& dir() const { return dir_; }

private:
  std::filesystem::path dir_;
  int fd_ = -1;
};

struct ClaimOptions {
  bool overwrite = false; ///< remove another run's results instead of refusing the folder
  /// Result names this command may find and keep (a sweep resumed: sweep.json, cases/).
  std::vector<std::string> keep;
};

/// Locks `dir` for one run and makes sure no other run's results stay in it: refuses (FolderHoldsResults)
/// a folder holding results not in `options.keep` unless `options.overwrite`, which removes them all.
[[nodiscard]] OutputLock claim_output_folder(const std::filesystem::path& dir, std::string_view command,
                                             const ClaimOptions& options = {});

/// The command line of this process as one string, for the lock file ("plyimpact impact deck.toml").
[[nodiscard]] std::string command_line(int argc, const char* const* argv);

} // namespace plyimpact
