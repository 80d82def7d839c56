#pragma once
// In-memory observers: the time history (every k-th step, the first and last always) and the plate's
// displacement field at requested times.
#include "plyimpact/analysis/impact/impact_observer.hpp"

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

/// At most `capacity` samples spread evenly over a run of any length: every step until the buffer is
/// full, then every other sample is dropped and the stride doubles (the curves of report.html).
class ThinnedHistory final : public ImpactObserver {
public:
  explicit ThinnedHistory(std::size_t capacity = 4096) : capacity_(capacity < 4 ? 4 : capacity) {}
  void on_start(const StepView& initial) override { record(initial); }
  void on_step(const StepView& view) override {
    if (view.step % stride_ == 0) record(view);
  }
  void on_finish(const StepView& last, const ImpactResult& /*result*/) override {
    if (last_step_ != last.step) samples_.push_back(history_sample(last));
  }
  [[nodiscard]] const std::vector<ImpactSample>& samples() const { return samples_; }

private:
  void record(const StepView& v) {
    samples_.push_back(history_sample(v));
    last_step_ = v.step;
    if (samples_.size() < capacity_) return;
    std::size_t kept = 0; // the samples at multiples of twice the stride: indices 0, 2, 4, ...
    for (std::size_t i = 0; i < samples_.size(); i += 2)
      samples_[kept++] = std::move(samples_[i]);
    samples_.resize(kept);
    stride_ *= 2;
  }
  std::size_t capacity_;
  long stride_ = 1;
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
