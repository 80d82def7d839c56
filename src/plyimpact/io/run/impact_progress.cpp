#include "plyimpact/io/run/impact_progress.hpp"

#include "plyimpact/analysis/contact/contact_rules.hpp"
#include "plyimpact/analysis/impact/guards.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

namespace plyimpact {

double expected_run_time(const ImpactSettings& settings, const StepView& view, double separation,
                         double fundamental_period) {
  if (settings.end) return *settings.end;
  // SPEC §4: the run ends max(t_c, 2 T1) after the impactor leaves at t_c; by separation, soon after it
  // leaves (a guess: a tenth of the contact).
  const bool by_separation = settings.end_rule == EventEnd::separation;
  const auto event = [&](double t_c) {
    return t_c + (by_separation ? 0.1 * t_c : std::max(t_c, 2.0 * fundamental_period));
  };
  if (separation > 0.0) return event(separation);
  const Impactor& i = settings.impactor;
  const double rigid = hertz_contact_time(i.mass, i.velocity, settings.k, contact_exponent(i.nose));
  const double phase = std::acos(std::clamp(view.impactor_v / i.velocity, -1.0, 1.0));
  const double half_sine = phase > 0.1 ? std::numbers::pi * view.t / phase : 0.0;
  return event(std::max({rigid, half_sine, view.t}));
}

ImpactProgress::ImpactProgress(const ImpactSettings& settings, double fundamental_period, ProgressStyle style,
                               double line_interval_s)
    : settings_(settings), fundamental_period_(fundamental_period),
      progress_("impact", 1.0, style, line_interval_s) {}

namespace {

/// ", energy error 3.2 %" once the running balance error has passed the tolerance (guards.hpp), else "".
std::string energy_error_text(const StepView& view) {
  if (!view.energy_balance_error || !(*view.energy_balance_error > energy_balance_tolerance)) return "";
  return fmt::format(", energy error {:.3g} %", 100.0 * *view.energy_balance_error);
}

} // namespace

void ImpactProgress::on_step(const StepView& view) {
  if (view.force > 0.0) touched_ = true;
  if (touched_ && separation_ < 0.0 && view.force == 0.0) separation_ = view.t;
  if (view.step % 16 != 0 || !progress_.due()) return; // nothing built on most steps
  const double expected = expected_run_time(settings_, view, separation_, fundamental_period_);
  const bool known = settings_.end.has_value();
  progress_.update(std::min(view.t / expected, known ? 1.0 : 0.99),
                   fmt::format("t = {:.4g} of {}{:.4g} ms, step {}{}", view.t * 1e3, known ? "" : "about ",
                               expected * 1e3, view.step, energy_error_text(view)));
}

void ImpactProgress::on_finish(const StepView& last, const ImpactResult& result) {
  progress_.finish(fmt::format("{} steps to t = {:.4g} ms{}", result.steps, last.t * 1e3,
                               result.complete ? "" : " (incomplete)"));
}

} // namespace plyimpact
