#pragma once
// history.csv written while the run goes (docs/output.md): the header at once, then complete rows in
// buffered blocks, flushed every block and at least every second, so a run killed at any moment leaves
// a CSV of the steps done (a kill -9 during a block's write may cut its last line short), and memory
// does not grow with the number of steps.
#include "plyimpact/analysis/impact_observer.hpp"

#include <chrono>
#include <filesystem>
#include <string>

namespace plyimpact {

/// The header line of history.csv (with its newline); every column name carries its unit.
/// `damaged_plies` > 0 (progressive damage): the damage dissipation, the projected damaged area and the
/// damaged area of each ply follow.
[[nodiscard]] std::string history_csv_header(int damaged_plies = 0);
/// One row of history.csv (with its newline): the shortest round-trip text of every number.
[[nodiscard]] std::string history_csv_row(const ImpactSample& sample);
/// The same row appended to `out`.
void append_history_csv_row(std::string& out, const ImpactSample& sample);

/// Observer that writes history.csv: the initial state, every `every`-th step and the last step (the
/// rows of HistoryRecorder, analysis/recorders.hpp).
class HistoryCsvWriter final : public ImpactObserver {
public:
  /// Creates (truncates) `path` and writes the header. Throws std::runtime_error naming the file.
  HistoryCsvWriter(std::filesystem::path path, int every, int damaged_plies = 0);
  ~HistoryCsvWriter() override;
  HistoryCsvWriter(const HistoryCsvWriter&) = delete;
  HistoryCsvWriter& operator=(const HistoryCsvWriter&) = delete;

  void on_start(const StepView& initial) override { record(initial); }
  void on_step(const StepView& view) override {
    if (view.step % every_ == 0) record(view);
  }
  void on_finish(const StepView& last, const ImpactResult& result) override;

  /// Writes the buffered rows to the file. Throws std::runtime_error with the system's reason.
  void flush();

private:
  void record(const StepView& v);

  std::filesystem::path path_;
  int every_;
  int fd_ = -1;
  long last_step_ = -1;
  std::string buffer_;
  std::chrono::steady_clock::time_point last_flush_;
};

} // namespace plyimpact
