#pragma once
// The progress of one impact run, as an observer of its time loop: the simulated time against the
// deck's `end` or, for end = "auto", against an estimate of the event that improves as it goes (the
// SPEC §4 rule ends the run one contact duration after separation, so the estimate is twice the
// contact duration: before contact the rigid-target Hertz time, in contact the half-sine estimate
// from the impactor's velocity, after separation the measured one). The display never claims 100 %
// before the run ends.
#include "plyimpact/analysis/impact_case.hpp"
#include "plyimpact/analysis/impact_observer.hpp"
#include "plyimpact/io/progress.hpp"

namespace plyimpact {

/// Simulated time the run is expected to last, seen at `view` [s]. `separation` is the time the
/// impactor first left the plate (negative while it has not). Half-sine estimate in contact: the
/// impactor's velocity v = v0 cos(π t / t_c), so t_c = π t / acos(v / v0).
[[nodiscard]] double expected_run_time(const ImpactSettings& settings, const StepView& view,
                                       double separation);

class ImpactProgress final : public ImpactObserver {
public:
  ImpactProgress(const ImpactSettings& settings, ProgressStyle style, double line_interval_s);
  void on_step(const StepView& view) override;
  void on_finish(const StepView& last, const ImpactResult& result) override;

private:
  ImpactSettings settings_;
  Progress progress_;
  bool touched_ = false;
  double separation_ = -1.0;
};

} // namespace plyimpact
