#pragma once
// The bookkeeping every impact time loop shares (linear ImpactSolver, NonlinearImpactSolver): the
// step limit and interrupt, contact episodes and peaks, the SPEC §4 end-of-event rule and the final
// summary values of ImpactResult.
#include "plyimpact/analysis/hertz_contact.hpp"
#include "plyimpact/analysis/impact_analysis.hpp"
#include "plyimpact/analysis/newmark.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>

namespace plyimpact {

class ImpactEvent {
public:
  ImpactEvent(ImpactResult& result, const ImpactSettings& settings, double fundamental_period)
      : r_(result), s_(settings), period_(fundamental_period) {}

  /// Before step+1: true (with ImpactResult::stop_reason set) at the step limit or on an interrupt.
  bool must_stop(long step, double t) {
    if (step >= s_.max_steps) {
      r_.stop_reason =
          fmt::format("stopped at the step limit ({} steps, t = {:.6g} s) before the end of the event; "
                      "raise time.max_steps or set time.end",
                      s_.max_steps, t);
      return true;
    }
    if (s_.cancel != nullptr && s_.cancel->load()) {
      r_.stop_reason = fmt::format("interrupted at step {} (t = {:.6g} s)", step, t);
      return true;
    }
    return false;
  }

  /// A converged step: contact episodes, peak force, peak deflection ws and indentation α.
  void record(double t, double force, double alpha, double ws) {
    if (force > 0.0) {
      if (!in_contact_) r_.episodes.push_back({t - s_.dt, t, 0.0});
      in_contact_ = true;
      auto& ep = r_.episodes.back();
      ep.end = t;
      ep.peak_force = std::max(ep.peak_force, force);
      if (force > r_.peak_force) r_.peak_force = force, r_.time_of_peak_force = t;
    } else if (in_contact_) {
      in_contact_ = false;
      last_separation_ = t;
      if (r_.episodes.size() == 1) r_.contact_duration = r_.episodes.front().end - r_.episodes.front().start;
    }
    r_.peak_contact_deflection = std::max(r_.peak_contact_deflection, ws);
    r_.max_indentation = std::max(r_.max_indentation, alpha);
  }

  /// End of the event at t: time.end reached, or (SPEC §4) out of contact for the longer of the first
  /// contact and two fundamental periods.
  bool over(double t) {
    if (s_.end) return t >= *s_.end - 1e-9 * s_.dt;
    if (in_contact_ || last_separation_ < 0.0) return false;
    r_.fundamental_period = period_;
    return t - last_separation_ >= std::max(r_.contact_duration, 2.0 * r_.fundamental_period);
  }

  /// The summary values after the last step.
  void finish(long steps, const HertzContact& law, const NewmarkStepper& impactor, double e0,
              double contact_work, std::chrono::steady_clock::time_point wall0) {
    if (in_contact_ && r_.episodes.size() == 1)
      r_.contact_duration = r_.episodes.front().end - r_.episodes.front().start;
    r_.steps = steps;
    r_.permanent_indentation = law.permanent_indentation();
    r_.rebound_velocity = -impactor.velocity();
    r_.absorbed_energy = e0 - impactor.kinetic_energy();
    r_.contact_dissipation = contact_work;
    r_.wall_time = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();
  }

private:
  ImpactResult& r_;
  const ImpactSettings& s_;
  double period_;
  bool in_contact_ = false;
  double last_separation_ = -1.0;
};

} // namespace plyimpact
