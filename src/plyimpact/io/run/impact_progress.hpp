#pragma once
// The progress of one impact run, as an observer of its time loop: the simulated time against the
// deck's `end` or, for end = "auto", against an estimate of the event that improves as it goes. The
// SPEC §4 rule ends the run max(t_c, 2 T1) after the impactor leaves at the contact time t_c (T1 the
// plate's fundamental period), so the estimate is that rule applied to the best t_c known: before
// contact the rigid-target Hertz time, in contact the half-sine estimate from the impactor's velocity
// (a flexible plate lengthens the contact), after separation the measured one. The ETA is the recent
// rate of the run (Progress::eta_s), so steps that grow dearer as damage spreads lengthen it at once.
// The display never claims 100 % before the run ends.
#include "plyimpact/analysis/impact/impact_case.hpp"
#include "plyimpact/analysis/impact/impact_observer.hpp"
#include "plyimpact/io/run/progress.hpp"

namespace plyimpact {

/// Simulated time the run is expected to last, seen at `view` [s]. `separation` is the time the
/// impactor first left the plate (negative while it has not); `fundamental_period` T1 of the plate [s]
/// (0 where unknown). Half-sine estimate in contact: the impactor's velocity v = v0 cos(π t / t_c), so
/// t_c = π t / acos(v / v0).
[[nodiscard]] double expected_run_time(const ImpactSettings& settings, const StepView& view,
                                       double separation, double fundamental_period);

class ImpactProgress final : public ImpactObserver {
public:
  /// `fundamental_period`: ImpactCase::fundamental_period, for the end-of-event rule.
  ImpactProgress(const ImpactSettings& settings, double fundamental_period, ProgressStyle style,
                 double line_interval_s);
  void on_step(const StepView& view) override;
  void on_finish(const StepView& last, const ImpactResult& result) override;

private:
  ImpactSettings settings_;
  double fundamental_period_;
  Progress progress_;
  bool touched_ = false;
  double separation_ = -1.0;
};

} // namespace plyimpact
