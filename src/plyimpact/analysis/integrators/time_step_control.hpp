#pragma once
// Error-controlled time steps (issue 22). The impact loop advances with steps Δt_k = Δt_max/2^k, k = 0 …
// levels − 1, so that every time is a whole number of the smallest step and each level's effective
// stiffness K̄ = K + M/(βΔt_k²) is factored once, when first used (linear_step.cpp).
//
// The quantity controlled is the indentation α = wi − ws, which alone sets the contact force, with
// α̈ = ẅi − ẅs (ẅi = −Fc/m the impactor's acceleration, ẅs = swᵀü the plate's at the contact point).
// Each step has two errors, both measured in metres of indentation:
//
//   integration    Newmark's local error in a displacement over one step, to leading order
//                  (Zienkiewicz & Xie 1991)  e_i = |β − 1/6| Δt² |Δα̈|  ∝ Δt³;                      (TS1)
//   sampling       the history is known at the steps only, and a peak between two of them is missed by up
//                  to the error of linear interpolation, e_s = Δt² |α̈_{n+1}| / 8  ∝ Δt²: where α̈ changes
//                  little (at the peak force) (TS1) is small but the peak still has to be caught.  (TS2)
//
// A step is redone at a finer level when either exceeds tolerance · α_m (α_m the rigid-target Hertz
// indentation, contact_rules.hpp), going down at once the levels that the larger of ∛(e_i/bound) and
// √(e_s/bound) asks. The next step is twice as long when both would stay below half the bound after the
// doubling (8 e_i and 4 e_s), except right after a redone step. A step out of contact at both its ends has
// no error of the force to control (the impactor flies freely): the next one is Δt_max at once (no level
// between is factored for nothing); a step that ends in a new contact is measured like any other and
// redone finer when it must (a contact that starts and ends within one Δt_max is missed).
#include "plyimpact/analysis/impact/impact_result.hpp"
#include "plyimpact/analysis/impact/parameters.hpp"
#include "plyimpact/analysis/integrators/newmark.hpp"

#include <vector>

namespace plyimpact {

class TimeStepControl {
public:
  /// `largest`: the coefficients of Δt_max; `indentation_scale`: α_m [m].
  TimeStepControl(const NewmarkCoefficients& largest, const AdaptiveTimeStep& settings,
                  double indentation_scale);

  [[nodiscard]] int level() const { return level_; }
  /// The Newmark coefficients of the current level.
  [[nodiscard]] const NewmarkCoefficients& coefficients() const {
    return coefficients_[static_cast<std::size_t>(level_)];
  }
  /// The time at the end of the step about to be solved [s].
  [[nodiscard]] double step_end_time() const;
  /// The errors (TS1), (TS2) of the indentation over the step just solved [m].
  struct StepErrors {
    double integration = 0.0;
    double sampling = 0.0;
  };
  /// The errors of the step just solved, from the accelerations of the impactor and of the plate's
  /// contact point at its start and end.
  [[nodiscard]] StepErrors indentation_errors(double impactor_a0, double impactor_a1, double plate_a0,
                                              double plate_a1) const;
  /// The step just solved had errors `e`: true to accept it (the time advances; the next step may be
  /// longer), false to solve it again at the finer level() now set. At the finest level every step is
  /// accepted, and one above the bound is counted.
  bool accept(const StepErrors& e);
  /// The step just solved was out of contact at both ends: it is accepted and the next one is Δt_max.
  void accept_free_flight();
  /// Makes the next step shorter (finer levels; not counted as redone) until it ends at `end` or before,
  /// or is the smallest: a run with time.end stops there, not up to Δt_max after it.
  void end_by(double end);
  /// What the run's summary reports (ImpactResult::time_steps).
  [[nodiscard]] AdaptiveStepResult result(int factorizations) const;

private:
  AdaptiveTimeStep settings_;
  std::vector<NewmarkCoefficients> coefficients_; ///< per level
  double bound_;                                  ///< tolerance · α_m [m]
  double smallest_dt_;
  long ticks_ = 0; ///< time elapsed, in smallest steps
  int level_ = 0;
  int finest_used_ = 0;
  bool just_rejected_ = false;
  long rejected_ = 0, above_bound_ = 0;
  double largest_ratio_ = 0.0; ///< of an accepted step's error to the bound
};

} // namespace plyimpact
