#include "plyimpact/analysis/threshold_search.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace plyimpact {

namespace {

/// Tracks one criterion and ends the run at its first failure.
class FirstFailure final : public ImpactObserver {
public:
  FirstFailure(const PlateModel& model, Criterion criterion, const DamageOptions& options)
      : tracker(model, {criterion}, options) {}
  void on_step(const StepView& v) override { tracker.on_step(v); }
  [[nodiscard]] bool wants_stop() const override { return tracker.any_failure(); }
  DamageTracker tracker;
};

} // namespace

ThresholdResult find_threshold_velocity(const ImpactCase& impact, Criterion criterion,
                                        const ThresholdOptions& options, const std::atomic<bool>* cancel) {
  if (!(options.tolerance > 0.0)) throw std::invalid_argument("threshold: tolerance must be positive");
  const ImpactSettings& s = impact.settings();
  ThresholdResult result;
  std::optional<DamageOnset> onset_at_upper;
  const auto trial = [&](double v) {
    FirstFailure watch(impact.model(), criterion, options.damage);
    RunRequest run;
    run.impactor = s.impactor;
    run.impactor->velocity = v;
    run.observers = {&watch};
    run.history_every = 0; // the search needs no history
    run.cancel = cancel;
    (void)impact.run(run);
    if (cancel != nullptr && cancel->load()) throw std::runtime_error("threshold: interrupted");
    const DamageTracker& tracker = watch.tracker;
    const bool failed = tracker.any_failure();
    result.trials.push_back({v, failed, tracker.peak_index(criterion)});
    if (options.on_trial) options.on_trial(result.trials);
    if (failed) onset_at_upper = tracker.first_onsets().front();
    return failed;
  };

  // Bracket [lower, upper]: no failure at `lower` (0 is safe), failure at `upper`.
  double lower = 0.0, upper = s.impactor.velocity;
  if (!(upper > 0.0)) upper = 1.0;
  while (!trial(upper)) {
    lower = upper;
    upper *= 2.0;
    if (upper > options.max_velocity) return result; // not found below max_velocity
  }
  std::optional<DamageOnset> best = onset_at_upper;
  // Safeguarded interpolation: the peak index of a run without failure grows with velocity about
  // like a power law, index ∝ v^p; fit p to the two highest non-failing runs (p = 1 with one) and aim
  // just below the predicted v(index = 1), then just above it. Bisection whenever the prediction
  // leaves the bracket, so the bracket always shrinks and holds [no failure, failure].
  const double tol = options.tolerance;
  const auto predicted = [&]() -> std::optional<double> {
    std::vector<ThresholdTrial> safe;
    for (const auto& t : result.trials)
      if (!t.failed && t.peak_index > 0.0) safe.push_back(t);
    if (safe.empty()) return std::nullopt;
    std::sort(safe.begin(), safe.end(), [](const auto& a, const auto& b) { return a.velocity < b.velocity; });
    const ThresholdTrial& hi = safe.back();
    double p = 1.0;
    if (safe.size() >= 2) {
      const ThresholdTrial& lo = safe[safe.size() - 2];
      if (hi.velocity > lo.velocity && hi.peak_index > lo.peak_index)
        p = std::log(hi.peak_index / lo.peak_index) / std::log(hi.velocity / lo.velocity);
    }
    if (!(p > 0.0) || !std::isfinite(p)) return std::nullopt;
    return hi.velocity * std::pow(1.0 / hi.peak_index, 1.0 / p);
  };
  while (upper - lower > tol) {
    double v = 0.5 * (lower + upper);
    if (const auto est = predicted(); est && *est > lower && *est < upper) {
      v = *est - 0.45 * tol;                               // expect no failure just below
      if (*est - lower < 0.9 * tol) v = lower + 0.9 * tol; // expect failure: closes the bracket
      v = std::clamp(v, lower + 0.05 * tol, upper - 0.05 * tol);
    }
    if (trial(v)) {
      upper = v;
      best = onset_at_upper;
    } else {
      lower = v;
    }
  }
  result.found = true;
  result.velocity = upper;
  result.lower = lower;
  result.first_failure = best;
  return result;
}

double bracket_progress(const std::vector<ThresholdTrial>& trials, double tolerance) {
  double lower = 0.0, upper = std::numeric_limits<double>::infinity(), first_width = -1.0;
  for (const ThresholdTrial& t : trials) {
    if (t.failed)
      upper = std::min(upper, t.velocity);
    else
      lower = std::max(lower, t.velocity);
    if (first_width < 0.0 && std::isfinite(upper)) first_width = upper - lower;
  }
  if (!std::isfinite(upper)) return 0.0;
  if (first_width <= tolerance) return 1.0;
  return std::clamp(std::log(first_width / (upper - lower)) / std::log(first_width / tolerance), 0.0, 1.0);
}

} // namespace plyimpact
