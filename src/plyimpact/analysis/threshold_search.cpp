#include "plyimpact/analysis/threshold_search.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <stdexcept>

namespace plyimpact {

ThresholdResult find_threshold_velocity(const PlateModel& model, const ImpactSettings& settings,
                                        Criterion criterion, const ThresholdOptions& options) {
  if (!(options.tolerance > 0.0)) throw std::invalid_argument("threshold: tolerance must be positive");
  std::atomic<bool> stop{false};
  ImpactSettings s = settings;
  s.cancel = &stop; // a run ends as soon as the criterion fires
  s.field_times.clear();
  s.history_every = 1 << 30; // no history needed
  const ImpactSolver solver(model, s);

  ThresholdResult result;
  std::optional<DamageOnset> onset_at_upper;
  const auto trial = [&](double v) {
    DamageTracker tracker(model, {criterion}, options.damage);
    stop.store(false);
    Impactor imp = s.impactor;
    imp.velocity = v;
    (void)solver.run(imp, [&](long step, double t, double force, const Eigen::VectorXd& u) {
      tracker.observe(step, t, force, u);
      if (tracker.any_failure()) stop.store(true);
    });
    const bool failed = tracker.any_failure();
    result.trials.push_back({v, failed, tracker.peak_index(criterion)});
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

} // namespace plyimpact
