#pragma once
// Running a sweep (docs/sweep.md): cases on worker threads, each finished case recorded atomically in
// DIR/cases/NNNNNN.json, and DIR/sweep.csv rebuilt from the records, one row per case in case order
// (with DIR/report.html, io/sweeps/sweep_report.hpp).
// Each case is computed from its own deck alone, so the table does not depend on how many threads or
// MPI ranks ran it, nor in which order; the numbers are written with the shortest text that reads back
// to the same double, so equal runs give byte-identical tables.
#include "plyimpact/io/sweeps/sweep_spec.hpp"

#include <nlohmann/json.hpp>

#include <atomic>
#include <cstddef>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace plyimpact {

class SharedImpactCases;

struct SweepOptions {
  bool case_folders = false;                 ///< also write DIR/cases/NNNNNN/ (summary.json, history.csv…)
  bool share_factorization = true;           ///< reuse the plate and its K̄ factor across cases
  const std::atomic<bool>* cancel = nullptr; ///< stop taking cases; a case cut short is not recorded
  std::function<void()> on_case_recorded;    ///< after each record is on disk (any thread: thread-safe)
};

/// Thread-safe source of positions in the list of pending cases; nullopt when none is left.
using NextCase = std::function<std::optional<std::size_t>()>;

/// The output folder of a sweep: sweep.json (fingerprint, keys, size), cases/, sweep.csv.
class SweepFolder {
public:
  SweepFolder(std::filesystem::path dir, const Sweep& sweep);

  /// Throws std::runtime_error when DIR holds another sweep (different fingerprint), or holds records
  /// and `resume` is false. A truncated or corrupt sweep.json is said to be so: with `resume` (or when
  /// there is no record) the records' own fingerprints are checked and the returned warning says that
  /// sweep.json is rewritten; without, the message says to add --resume.
  [[nodiscard]] std::optional<std::string> check(bool resume) const;
  /// Writes sweep.json (atomically).
  void write_manifest() const;

  struct Pending {
    std::vector<std::size_t> cases;   ///< indices without a valid record, ascending
    std::vector<std::string> damaged; ///< one message per record file that could not be read (run again)
  };
  /// Case indices without a valid record, and the damaged record files among them.
  [[nodiscard]] Pending scan() const;
  /// Case indices without a valid record, ascending.
  [[nodiscard]] std::vector<std::size_t> pending() const { return scan().cases; }
  [[nodiscard]] std::filesystem::path record_path(std::size_t index) const;
  /// The record of case `index` when it exists and belongs to this sweep (a malformed record is none;
  /// `problem`, when given, then says what is wrong with the file).
  [[nodiscard]] std::optional<nlohmann::json> read_record(std::size_t index,
                                                          std::string* problem = nullptr) const;

  struct TableStatus {
    std::size_t missing = 0; ///< cases without a record (the table is not written)
    std::size_t failed = 0;  ///< cases recorded with an error
  };
  /// Writes sweep.csv and report.html (each atomically) when every case has a record.
  TableStatus write_table() const;
  /// What a resumed sweep finds in its folder and keeps: sweep.json, cases/ and the last table and report.
  [[nodiscard]] static std::vector<std::string> resumable_results() {
    return {"sweep.json", "sweep.csv", "report.html", "cases"};
  }

  [[nodiscard]] const std::filesystem::path& path() const { return dir_; }

private:
  /// The first record in cases/ written by another sweep (its file name and fingerprint), if any.
  [[nodiscard]] std::optional<std::pair<std::string, std::string>> foreign_record() const;

  std::filesystem::path dir_;
  const Sweep& sweep_;
};

/// Computes one case: its record (status "ok", "incomplete" or "failed" with the error message), or
/// nullopt when the run was cancelled part-way. Keeps the last plate and factorization for the next
/// case of the same plate and time step (same_plate, analysis/impact/impact_case.hpp).
class SweepWorker {
public:
  /// `cases`: the plates this worker shares with the other workers of its process (with
  /// options.share_factorization).
  SweepWorker(const Sweep& sweep, const SweepFolder& folder, SweepOptions options, SharedImpactCases& cases);
  ~SweepWorker();
  SweepWorker(const SweepWorker&) = delete;
  SweepWorker& operator=(const SweepWorker&) = delete;

  [[nodiscard]] std::optional<nlohmann::json> run(std::size_t index);
  /// How many times this worker built a plate and factored its K̄ (for tests and benchmarks).
  [[nodiscard]] int factorizations() const { return factorizations_; }

private:
  struct Cache;
  const Sweep& sweep_;
  const SweepFolder& folder_;
  SweepOptions options_;
  SharedImpactCases& cases_;
  std::unique_ptr<Cache> cache_;
  int factorizations_ = 0;
};

/// The most threads a sweep process starts: far beyond any machine's cores, well below what makes thread
/// creation fail (--jobs 100000 aborted the program).
inline constexpr int max_sweep_jobs = 1024;

/// Runs `pending` cases on `jobs` threads (1 to max_sweep_jobs, else std::invalid_argument); each thread
/// takes the next position from `next` and writes the case's record as soon as it is done. With
/// `options.share_factorization`, the threads share each plate (and its factor and contact-point response):
/// the first to need it builds it, the others wait for it and run their impactors on it. Returns the number
/// of factorizations of K̄.
int run_sweep_cases(const Sweep& sweep, const SweepFolder& folder, const std::vector<std::size_t>& pending,
                    int jobs, const NextCase& next, const SweepOptions& options);

/// sweep.csv from the records of every case, in case order.
[[nodiscard]] std::string sweep_table_csv(const Sweep& sweep, const std::vector<nlohmann::json>& records);

} // namespace plyimpact
