#include "plyimpact/analysis/thresholds/threshold_search.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <functional>
#include <limits>
#include <stdexcept>

namespace plyimpact {

namespace {

/// The peak index of a run without failure grows with velocity about like a power law,
/// index ∝ v^p; fit p to the two highest non-failing runs (p = 1 with one) and predict v(index = 1).
std::optional<double> predicted_threshold(const std::vector<ThresholdTrial>& trials) {
  std::vector<ThresholdTrial> safe;
  for (const auto& t : trials)
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
}

/// Bracketing and narrowing, the same for every criterion. `trial(v)` runs the case at v, appends its
/// ThresholdTrial to result.trials and returns whether it failed; `keep_failure()` is called when the
/// last trial failed and became the upper end of the bracket.
struct Bracketing {
  const ThresholdOptions& options;
  std::function<bool(double)> trial;
  std::function<void()> keep_failure;
  bool interpolate = true; ///< aim with predicted_threshold(); false: plain bisection

  void run(double start, ThresholdResult& result) const {
    // Bracket [lower, upper]: no failure at `lower` (0 is safe), failure at `upper`.
    double lower = 0.0, upper = start;
    if (!(upper > 0.0)) upper = 1.0;
    while (!trial(upper)) {
      lower = upper;
      upper *= 2.0;
      if (upper > options.max_velocity) return; // not found below max_velocity
    }
    keep_failure();
    // Safeguarded interpolation: aim just below the predicted v(index = 1), then just above it.
    // Bisection whenever the prediction leaves the bracket, so the bracket always shrinks and holds
    // [no failure, failure].
    const double tol = options.tolerance;
    while (upper - lower > tol) {
      double v = 0.5 * (lower + upper);
      const auto est = interpolate ? predicted_threshold(result.trials) : std::nullopt;
      if (est && *est > lower && *est < upper) {
        v = *est - 0.45 * tol;                               // expect no failure just below
        if (*est - lower < 0.9 * tol) v = lower + 0.9 * tol; // expect failure: closes the bracket
        v = std::clamp(v, lower + 0.05 * tol, upper - 0.05 * tol);
      }
      if (trial(v)) {
        upper = v;
        keep_failure();
      } else {
        lower = v;
      }
    }
    result.found = true;
    result.velocity = upper;
    result.lower = lower;
  }
};

/// Tracks one criterion and ends the run at its first failure.
class FirstFailure final : public ImpactObserver {
public:
  FirstFailure(const DiscretePlate& model, Criterion criterion, const DamageOptions& options)
      : tracker(model, {criterion}, options) {}
  void on_step(const StepView& v) override { tracker.on_step(v); }
  [[nodiscard]] bool wants_stop() const override { return tracker.any_failure(); }
  DamageTracker tracker;
};

/// Watches the damage field of a progressive run and ends it when the criterion is met. Damage never
/// heals, so a criterion met once stays met: the end state of a run says whether it failed.
class DamageWatch final : public ImpactObserver {
public:
  explicit DamageWatch(const DamageCriterion& criterion) : criterion_(criterion) {}

  void on_step(const StepView& v) override {
    const PlyDamageView* field = v.damage();
    if (reached || field == nullptr) return;
    area_ = field->projected_damage_area();
    if (criterion_.kind == DamageCriterion::Kind::damage_area) {
      if (area_ > criterion_.area) reached = where(*field, v);
      return;
    }
    if (!field->first_damage()) return; // nothing damaged yet: no need to look
    reached = where(*field, v);
  }
  [[nodiscard]] bool wants_stop() const override { return reached.has_value(); }
  /// damage-area: the largest area seen over the limit; first damage: 0 (no index before damage).
  [[nodiscard]] double peak_index() const {
    return criterion_.kind == DamageCriterion::Kind::damage_area ? area_ / criterion_.area : 0.0;
  }

  std::optional<DamageReached> reached;

private:
  /// damage-area: the run's first damage; first damage: the first element and ply (in the field's
  /// order) with d > 0 in a mode of the criterion, nullopt when there is none.
  [[nodiscard]] std::optional<DamageReached> where(const PlyDamageView& field, const StepView& v) const {
    if (criterion_.kind == DamageCriterion::Kind::damage_area && field.first_damage()) {
      const PlyDamageView::FirstDamage& f = *field.first_damage();
      return DamageReached{f.mode, f.ply + 1, f.element + 1, v.t, v.force, area_};
    }
    for (const ElementPlyDamage& e : field.element_ply_damage())
      for (const DamageMode m : all_damage_modes)
        if (counts_for(criterion_.kind, m) && e.damage[m] > 0.0)
          return DamageReached{m, e.ply + 1, e.element + 1, v.t, v.force, area_};
    return std::nullopt;
  }

  DamageCriterion criterion_;
  double area_ = 0.0;
};

void check_tolerance(const ThresholdOptions& options) {
  if (!(options.tolerance > 0.0)) throw std::invalid_argument("threshold: tolerance must be positive");
}

} // namespace

std::string_view to_string(DamageCriterion::Kind kind) {
  switch (kind) {
  case DamageCriterion::Kind::fibre_damage:
    return "fibre-damage";
  case DamageCriterion::Kind::matrix_damage:
    return "matrix-damage";
  case DamageCriterion::Kind::damage_area:
    return "damage-area";
  }
  return "unknown";
}

std::optional<DamageCriterion::Kind> parse_damage_criterion(std::string_view name) {
  for (const auto k : {DamageCriterion::Kind::fibre_damage, DamageCriterion::Kind::matrix_damage,
                       DamageCriterion::Kind::damage_area})
    if (to_string(k) == name) return k;
  return std::nullopt;
}

bool counts_for(DamageCriterion::Kind kind, DamageMode mode) {
  const bool fibre = mode == DamageMode::fibre_tension || mode == DamageMode::fibre_compression;
  switch (kind) {
  case DamageCriterion::Kind::fibre_damage:
    return fibre;
  case DamageCriterion::Kind::matrix_damage:
    return !fibre;
  case DamageCriterion::Kind::damage_area:
    return true;
  }
  return false;
}

ThresholdResult find_threshold_velocity(const ImpactCase& impact, Criterion criterion,
                                        const ThresholdOptions& options, const std::atomic<bool>* cancel) {
  check_tolerance(options);
  const ImpactSettings& s = impact.settings();
  ThresholdResult result;
  std::optional<DamageOnset> onset_at_last;
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
    if (failed) onset_at_last = tracker.first_onsets().front();
    return failed;
  };
  const Bracketing search{options, trial, [&] { result.first_failure = onset_at_last; }};
  search.run(s.impactor.velocity, result);
  return result;
}

ThresholdResult find_threshold_velocity(const ImpactCase& impact, const DamageCriterion& criterion,
                                        const ThresholdOptions& options, const std::atomic<bool>* cancel) {
  check_tolerance(options);
  const ImpactSettings& s = impact.settings();
  if (!s.progressive_damage)
    throw std::invalid_argument(
        fmt::format("threshold: criterion {} needs the progressive damage model", to_string(criterion.kind)));
  if (criterion.kind == DamageCriterion::Kind::damage_area && !(criterion.area > 0.0))
    throw std::invalid_argument("threshold: the damage-area limit must be positive");
  ThresholdResult result;
  std::optional<DamageReached> reached_at_last;
  const auto trial = [&](double v) {
    DamageWatch watch(criterion);
    RunRequest run;
    run.impactor = s.impactor;
    run.impactor->velocity = v;
    run.observers = {&watch};
    run.history_every = 0;
    run.cancel = cancel;
    (void)impact.run(run); // a whole progressive run from the virgin plate (newton_newmark_step.cpp)
    if (cancel != nullptr && cancel->load()) throw std::runtime_error("threshold: interrupted");
    const bool failed = watch.reached.has_value();
    result.trials.push_back({v, failed, watch.peak_index()});
    if (options.on_trial) options.on_trial(result.trials);
    reached_at_last = watch.reached;
    return failed;
  };
  const Bracketing search{options, trial, [&] { result.damage = reached_at_last; }, false};
  search.run(s.impactor.velocity, result);
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
