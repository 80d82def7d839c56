#pragma once
// In-memory observers: the time history (every k-th step, the first and last always) and the plate's
// displacement field at requested times.
#include "plyimpact/analysis/impact_observer.hpp"

#include <vector>

namespace plyimpact {

class HistoryRecorder final : public ImpactObserver {
public:
  explicit HistoryRecorder(int every = 1) : every_(every < 1 ? 1 : every) {}
  void on_start(const StepView& initial) override { record(initial); }
  void on_step(const StepView& view) override {
    if (view.step % every_ == 0) record(view);
  }
  void on_finish(const StepView& last, const ImpactResult& /*result*/) override {
    if (last_step_ != last.step) record(last);
  }
  [[nodiscard]] std::vector<ImpactSample>& samples() { return samples_; }

private:
  void record(const StepView& v) {
    samples_.push_back(history_sample(v));
    last_step_ = v.step;
  }
  int every_;
  long last_step_ = -1;
  std::vector<ImpactSample> samples_;
};

class FieldRecorder final : public ImpactObserver {
public:
  /// Snapshots at the first step with t ≥ each requested time.
  explicit FieldRecorder(std::vector<double> times);
  void on_step(const StepView& view) override;
  [[nodiscard]] std::vector<FieldSnapshot>& fields() { return fields_; }

private:
  std::vector<double> times_;
  std::size_t next_ = 0;
  std::vector<FieldSnapshot> fields_;
};

} // namespace plyimpact
