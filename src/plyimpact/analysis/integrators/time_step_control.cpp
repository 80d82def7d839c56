#include "plyimpact/analysis/integrators/time_step_control.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace plyimpact {

TimeStepControl::TimeStepControl(const NewmarkCoefficients& largest, const AdaptiveTimeStep& settings,
                                 double indentation_scale)
    : settings_(settings), bound_(settings.tolerance * indentation_scale),
      smallest_dt_(largest.halved(settings.levels - 1).dt) {
  if (settings.levels < 1 || settings.levels > 24)
    throw std::invalid_argument(
        fmt::format("adaptive time steps: levels must lie between 1 and 24, got {}", settings.levels));
  if (!(settings.tolerance > 0.0) || !(indentation_scale > 0.0))
    throw std::invalid_argument(
        "adaptive time steps: the tolerance and the indentation scale must be positive");
  if (std::abs(largest.beta - 1.0 / 6.0) < 1e-3)
    throw std::invalid_argument("adaptive time steps: the error estimate (β − 1/6) Δt² Δa vanishes for "
                                "newmark_beta = 1/6; use the default 1/4");
  for (int k = 0; k < settings.levels; ++k)
    coefficients_.push_back(largest.halved(k));
}

double TimeStepControl::step_end_time() const {
  const long step_ticks = 1L << (settings_.levels - 1 - level_);
  return static_cast<double>(ticks_ + step_ticks) * smallest_dt_;
}

TimeStepControl::StepErrors TimeStepControl::indentation_errors(double impactor_a0, double impactor_a1,
                                                                double plate_a0, double plate_a1) const {
  const NewmarkCoefficients& c = coefficients();
  const double a0 = impactor_a0 - plate_a0, a1 = impactor_a1 - plate_a1;  // α̈ at the two ends
  return {std::abs(c.beta - 1.0 / 6.0) * c.dt * c.dt * std::abs(a1 - a0), // (TS1)
          c.dt * c.dt * std::abs(a1) / 8.0};                              // (TS2)
}

bool TimeStepControl::accept(const StepErrors& e) {
  const double integration = e.integration / bound_, sampling = e.sampling / bound_;
  const double ratio = std::max(integration, sampling);
  const int finest = settings_.levels - 1;
  if (ratio > 1.0 && level_ < finest) {
    // e_i ∝ Δt³, e_s ∝ Δt²: the halvings each needs, the more of the two.
    const double shrink = std::max(std::cbrt(integration), std::sqrt(sampling));
    const int down = std::max(1, static_cast<int>(std::ceil(std::log2(shrink))));
    level_ = std::min(finest, level_ + down);
    ++rejected_;
    just_rejected_ = true;
    return false;
  }
  if (ratio > 1.0) ++above_bound_;
  largest_ratio_ = std::max(largest_ratio_, ratio);
  finest_used_ = std::max(finest_used_, level_);
  ticks_ += 1L << (finest - level_);
  if (!just_rejected_ && level_ > 0 && 8.0 * integration < 0.5 && 4.0 * sampling < 0.5) --level_;
  just_rejected_ = false;
  return true;
}

void TimeStepControl::accept_free_flight() {
  finest_used_ = std::max(finest_used_, level_);
  ticks_ += 1L << (settings_.levels - 1 - level_);
  level_ = 0;
  just_rejected_ = false;
}

void TimeStepControl::end_by(double end) {
  while (level_ < settings_.levels - 1 && step_end_time() > end + 1e-9 * smallest_dt_)
    ++level_;
}

AdaptiveStepResult TimeStepControl::result(int factorizations) const {
  AdaptiveStepResult r;
  r.tolerance = settings_.tolerance;
  r.largest_dt = coefficients_.front().dt;
  r.smallest_allowed_dt = coefficients_.back().dt;
  r.smallest_used_dt = coefficients_[static_cast<std::size_t>(finest_used_)].dt;
  r.rejected_steps = rejected_;
  r.steps_above_tolerance = above_bound_;
  r.largest_error_ratio = largest_ratio_;
  r.factorizations = factorizations;
  return r;
}

} // namespace plyimpact
