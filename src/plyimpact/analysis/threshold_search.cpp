#include "plyimpact/analysis/threshold_search.hpp"

#include <atomic>
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
  while (upper - lower > options.tolerance) {
    const double mid = 0.5 * (lower + upper);
    if (trial(mid)) {
      upper = mid;
      best = onset_at_upper;
    } else {
      lower = mid;
    }
  }
  result.found = true;
  result.velocity = upper;
  result.lower = lower;
  result.first_failure = best;
  return result;
}

} // namespace plyimpact
