#pragma once
// history.csv written while the run goes (docs/output.md): the header at once, then complete rows in
// buffered blocks, flushed every block and at least every second, so a run killed at any moment leaves
// a CSV of the steps done (a kill -9 during a block's write may cut its last line short), and memory
// does not grow with the number of steps.
#include "plyimpact/analysis/impact/impact_observer.hpp"

#include <chrono>
#include <filesystem>
#include <string>
#include <vector>

namespace plyimpact {

/// Which columns a run's history.csv has after the ten of every run.
struct HistoryLayout {
  /// > 0 (progressive damage): damage_dissipation_J, damage_area_m2 (projected) and plyK_damage_area_m2
  /// for K = 1 … damaged_plies follow.
  int damaged_plies = 0;
  /// not empty (stacked plate): delamination_dissipation_J, delamination_area_m2 (projected) and
  /// delamination_area_after_plyP_m2 for each interface, named by the ply P above it, follow.
  std::vector<int> interfaces_after_ply;
};

/// The layout of the rows a run's samples carry (the first sample's vectors give the counts).
[[nodiscard]] HistoryLayout history_layout(const ImpactResult& result);

/// The column names of history.csv, in order; every name carries its unit.
[[nodiscard]] std::vector<std::string> history_columns(const HistoryLayout& layout = {});
/// The header line of history.csv (with its newline).
[[nodiscard]] std::string history_csv_header(const HistoryLayout& layout = {});
/// The values of a sample's row, in the order of history_columns (the sample's vectors give the optional
/// columns' counts).
template <class Consumer>
void for_each_history_value(const ImpactSample& h, Consumer&& take) {
  for (const double v : {h.t, h.force, h.impactor_w, h.impactor_v, h.plate_w, h.indentation, h.plate_kinetic,
                         h.plate_strain, h.impactor_energy, h.contact_work})
    take(v);
  if (!h.ply_damage_area.empty()) {
    take(h.damage_dissipation);
    take(h.damage_area);
    for (const double a : h.ply_damage_area)
      take(a);
  }
  if (!h.interface_delaminated_area.empty()) {
    take(h.delamination_dissipation);
    take(h.delaminated_area);
    for (const double a : h.interface_delaminated_area)
      take(a);
  }
}
/// One row of history.csv (with its newline): the shortest round-trip text of every number.
[[nodiscard]] std::string history_csv_row(const ImpactSample& sample);
/// The same row appended to `out`.
void append_history_csv_row(std::string& out, const ImpactSample& sample);

/// Observer that writes history.csv: the initial state, every `every`-th step and the last step (the
/// rows of HistoryRecorder, analysis/impact/recorders.hpp).
class HistoryCsvWriter final : public ImpactObserver {
public:
  /// Creates (truncates) `path` and writes the header. Throws std::runtime_error naming the file.
  HistoryCsvWriter(std::filesystem::path path, int every, const HistoryLayout& layout = {});
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
  std::size_t whole_bytes_ = 0; ///< the file's size after the last complete flush: whole rows only
  long last_step_ = -1;
  std::string buffer_;
  ImpactSample sample_; ///< the row being formatted, its vectors reused from step to step
  std::chrono::steady_clock::time_point last_flush_;
};

} // namespace plyimpact
