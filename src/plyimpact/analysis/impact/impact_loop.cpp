#include "plyimpact/analysis/impact/impact_loop.hpp"

#include "plyimpact/analysis/contact/contact_rules.hpp"
#include "plyimpact/analysis/impact/guards.hpp"
#include "plyimpact/analysis/impact/separation_end.hpp"
#include "plyimpact/analysis/integrators/time_step_control.hpp"
#include "plyimpact/analysis/plate_analyses/nonlinear_static.hpp"
#include "plyimpact/fem/element_loop.hpp"
#include "plyimpact/fem/mechanical_model.hpp"
#include "plyimpact/laminate/ply_damage.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <optional>
#include <string>

namespace plyimpact {

namespace {

/// The whole plate state is checked for NaN/Inf every this many steps (the contact scalars every step).
constexpr long full_state_check_every = 100;

/// The bookkeeping of the event: step limit and interrupt, contact episodes and peaks, the end-of-event
/// rules (SPEC §4's, or separation_end.hpp's) and the summary values of ImpactResult.
class ImpactEvent {
public:
  ImpactEvent(ImpactResult& result, const LoopSettings& settings)
      : r_(result), s_(settings),
        separation_check_every_(std::max(1L, std::lround(separation_check_interval / settings.dt))) {
    if (s_.separation_compliance) separation_.emplace(*s_.separation_compliance);
  }

  /// Before step+1: true (with ImpactResult::stop_reason set) at the step limit, on an interrupt or
  /// when an observer asked to stop.
  bool must_stop(long step, double t, bool observer_stop) {
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
    if (observer_stop) {
      r_.stop_reason = fmt::format("stopped by an observer at step {} (t = {:.6g} s)", step, t);
      return true;
    }
    return false;
  }

  /// A converged step of length dt: contact episodes, peak force, peak deflection ws and indentation α.
  void record(double t, double dt, double force, double alpha, double ws) {
    last_force_ = force;
    if (force > 0.0) {
      if (!in_contact_) r_.episodes.push_back({t - dt, t, 0.0});
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

  /// End of the event after `step` at t: time.end reached; with the separation rule, the impactor out of
  /// the plate's reach (`state()` gives what it looks at, asked once per separation_check_interval);
  /// else (SPEC §4) out of contact for the longer of the first contact and two fundamental periods.
  template <class StateOf>
  bool over(long step, double t, const StateOf& state) {
    if (s_.end) return t >= *s_.end - 1e-9 * s_.dt;
    if (in_contact_ || last_separation_ < 0.0) return false;
    if (separation_ && !separation_->bound_failure() && step % separation_check_every_ == 0) {
      if (separation_->cannot_hit_again(state())) return true;
      if (const auto& why = separation_->bound_failure()) r_.warnings.push_back(*why);
    }
    return t - last_separation_ >= std::max(r_.contact_duration, 2.0 * s_.fundamental_period);
  }

  /// The summary values after the last step; `ended` is true when over() ended the run.
  void finish(bool ended, long steps, double t, const HertzContact& law, const NewmarkStepper& impactor,
              double e0, double contact_work) {
    if (in_contact_ && r_.episodes.size() == 1)
      r_.contact_duration = r_.episodes.front().end - r_.episodes.front().start;
    r_.steps = steps;
    r_.end_time = t;
    r_.permanent_indentation = law.permanent_indentation();
    r_.contact_dissipation = contact_work;
    if (!s_.end && s_.fundamental_period > 0.0) r_.fundamental_period = s_.fundamental_period;
    r_.end_rule = s_.end                              ? EventEndRule::time
                  : separation_ && separation_->end() ? EventEndRule::separation
                                                      : EventEndRule::re_hit;
    if (separation_) r_.separation_end = separation_->end();
    // The end-of-event rule ends a run only after the impactor has left; time.end may come before.
    const bool by_rule = ended && !s_.end;
    const bool left = by_rule || (!in_contact_ && !r_.episodes.empty() && impactor.velocity() < 0.0);
    if (left) {
      r_.rebound_velocity = -impactor.velocity();
      r_.absorbed_energy = e0 - impactor.kinetic_energy();
    }
    r_.complete = ended && left;
    if (r_.complete) return;
    if (!ended) {
      r_.incomplete_reason = r_.stop_reason;
      return;
    }
    r_.incomplete_reason = cut_short_reason(t, impactor);
    r_.warnings.push_back(r_.incomplete_reason);
  }

private:
  /// Why a run that reached time.end is not a whole event, and the deck key to change.
  [[nodiscard]] std::string cut_short_reason(double t, const NewmarkStepper& impactor) const {
    const std::string state =
        in_contact_ ? fmt::format("is still in contact with the plate (contact force {:.4g} N)", last_force_)
        : r_.episodes.empty() ? std::string("has not reached the plate yet")
                              : fmt::format("has left contact but still moves toward the plate ({:.4g} m/s)",
                                            impactor.velocity());
    return fmt::format("the run ended at time.end = {:.6g} s (t = {:.6g} s) while the impactor {}: the event "
                       "is not over, so rebound_velocity and absorbed_energy are not given (null). Set "
                       "[time] end = \"auto\" (the end-of-event rule) or a later time to get them",
                       *s_.end, t, state);
  }

  ImpactResult& r_;
  const LoopSettings& s_;
  bool in_contact_ = false;
  double last_separation_ = -1.0;
  double last_force_ = 0.0;
  std::optional<SeparationRule> separation_; ///< engaged with LoopSettings::separation_compliance
  long separation_check_every_;
};

/// The plies' damage of the stepper's model after the last accepted step; null without.
const PlyDamageView* ply_damage_of(const PlateStepper& stepper) {
  const ModelResults* r = stepper.results();
  return r ? r->ply_damage : nullptr;
}

/// Its interfaces; empty without.
std::optional<DelaminationResult> delamination_of(const PlateStepper& stepper) {
  const ModelResults* r = stepper.results();
  return r && r->interfaces ? std::optional(r->interfaces->result()) : std::nullopt;
}

/// The plate's part of the step view: expanded displacements and energies, computed on demand.
class PlateAccess final : public PlateStateAccess {
public:
  PlateAccess(const PlateStepper& stepper, const PlateState& state, const double& force)
      : stepper_(stepper), state_(state), force_(force) {}
  void next_step() { expanded_ = false, kinetic_.reset(), strain_.reset(), areas_state_ = unknown; }
  [[nodiscard]] const Eigen::VectorXd& displacement() const override {
    if (!expanded_) stepper_.to_model(state_.u, model_u_), expanded_ = true;
    return model_u_;
  }
  // Once per step however many observers ask (history.csv, the report's curves).
  [[nodiscard]] double kinetic_energy() const override {
    if (!kinetic_) kinetic_ = stepper_.kinetic_energy(state_);
    return *kinetic_;
  }
  [[nodiscard]] double strain_energy() const override {
    if (!strain_) strain_ = stepper_.strain_energy(state_, force_);
    return *strain_;
  }
  [[nodiscard]] double dissipated_energy() const override {
    const ModelResults* r = stepper_.results();
    return r ? r->dissipated_energy() : 0.0;
  }
  [[nodiscard]] const PlyDamageView* damage() const override { return ply_damage_of(stepper_); }
  [[nodiscard]] std::optional<DelaminationResult> delamination() const override {
    return delamination_of(stepper_);
  }
  [[nodiscard]] const DelaminationAreas* delamination_areas() const override {
    if (areas_state_ == unknown) {
      const ModelResults* r = stepper_.results();
      areas_state_ = r && r->interfaces ? known : none;
      if (areas_state_ == known) r->interfaces->areas(areas_);
    }
    return areas_state_ == known ? &areas_ : nullptr;
  }

private:
  const PlateStepper& stepper_;
  const PlateState& state_;
  const double& force_;
  mutable Eigen::VectorXd model_u_;
  mutable bool expanded_ = false;
  mutable std::optional<double> kinetic_, strain_;
  enum AreasState { unknown, known, none };
  mutable AreasState areas_state_ = unknown;
  mutable DelaminationAreas areas_; ///< its vectors are reused from step to step
};

/// |e0 − (impactor + plate kinetic + plate strain + dissipated + the contact law's work)| / e0 at `v`.
double balance_error(const StepView& v, double e0, double law_work) {
  const double total = v.impactor_energy + v.plate_kinetic_energy() + v.plate_strain_energy() +
                       v.plate_dissipated_energy() + law_work;
  return std::abs(e0 - total) / e0;
}

/// Why a run stops at `v`, whose running balance error passed LoopSettings::stop_at_energy_error.
std::string energy_stop_reason(const StepView& v, double limit) {
  return fmt::format("stopped at step {} (t = {:.6g} s): the energy balance error reached {:.3g} % of the "
                     "impact energy, above [time] stop_at_energy_error = {:.3g} %: the run could not recover "
                     "what it lost; the results up to here are written",
                     v.step, v.t, 100.0 * *v.energy_balance_error, 100.0 * limit);
}

/// The checks of a finished run (guards.hpp): the energy balance (suspect above
/// energy_balance_tolerance) and a linear plate deflected beyond max_linear_deflection thicknesses.
/// The balance counts the contact's share as the contact law's exact work ∫F dα along the path of α
/// (`law_work`): the time integration's own trapezoidal work (contact_work) balances the other energies
/// by construction for a point load, so only the law tells whether a step was too coarse to follow it.
void check_after_run(ImpactResult& r, const StepView& end, double e0, double law_work, const Impactor& imp,
                     double k, ContactLoad load, const LoopSettings& s) {
  if (e0 > 0.0) r.energy_balance_error = balance_error(end, e0, law_work);
  EnergyBalanceClues clues;
  clues.load = load;
  clues.dissipated_fraction = e0 > 0.0 ? end.plate_dissipated_energy() / e0 : 0.0;
  clues.contact_episodes = r.episodes.size();
  if (auto why = energy_balance_reason(r.energy_balance_error, e0, imp.mass, imp.velocity, k, s.dt,
                                       contact_exponent(imp.nose), clues)) {
    r.suspect = true;
    r.suspect_reason = *why;
    r.warnings.push_back(std::move(*why));
  }
  if (r.added_mass_kinetic_energy)
    if (auto w = added_mass_warning(*r.added_mass_kinetic_energy, e0)) r.warnings.push_back(std::move(*w));
  if (s.linear_thickness)
    if (auto w = large_deflection_warning(r.peak_contact_deflection, *s.linear_thickness))
      r.warnings.push_back(std::move(*w));
}

/// When each mode first appeared, and which mode the plies first cracked in: the step where `d` first
/// shows it.
void record_damage_onsets(const PlyDamageView& d, double t, double force, ProgressiveDamageResult& out) {
  for (const DamageMode m : all_damage_modes)
    if (const auto& first = d.first_damage_by_mode()[m]; first && !out.first_by_mode[m])
      out.first_by_mode[m] = FirstDamageOfMode{first->ply + 1, t, force};
  if (d.first_damage() && !out.first_mode) out.first_mode = d.first_damage()->mode;
}

/// v += c6 a + c7 a_next (2.16), blocks of entries on the element-loop threads.
void update_velocity(const NewmarkCoefficients& nc, const Eigen::VectorXd& a, const Eigen::VectorXd& a_next,
                     Eigen::VectorXd& v) {
  elementwise_on_threads(v.size(), [&](Eigen::Index first, Eigen::Index last) {
    const Eigen::Index n = last - first;
    v.segment(first, n) += nc.c6 * a.segment(first, n) + nc.c7 * a_next.segment(first, n);
  });
}

} // namespace

ImpactResult run_impact_loop(const StepPolicy& policy, const Impactor& imp, double k,
                             const ContactLawParameters& contact, const LoopSettings& s,
                             std::span<ImpactObserver* const> observers) {
  const auto wall0 = std::chrono::steady_clock::now();
  check_end_after_first_step(s.dt, s.end);
  const NewmarkCoefficients nc(s.dt, s.newmark_beta, s.newmark_gamma);
  std::optional<TimeStepControl> control;
  if (s.adaptive) {
    if (!policy.variable_time_step())
      throw std::invalid_argument(
          "adaptive time steps are available for the linear plate only (no progressive "
          "damage, delamination or non-linear plate): set [time] adaptive = false");
    control.emplace(nc, *s.adaptive,
                    rigid_target_indentation(imp.mass, imp.velocity, k, contact_exponent(imp.nose)));
  }
  const std::unique_ptr<PlateStepper> plate = policy.start(imp, s.contact_point_response && !control);
  // The plate state (ws, ẇs, ẅs) of the contact point alone: no field, the plate's energy all strain.
  const bool contact_point_only = plate->contact_point_only();
  const auto equations = static_cast<Eigen::Index>(policy.equations());
  const bool rigid = equations == 0;
  const Eigen::Index n = contact_point_only ? 1 : equations; // the state's size

  HertzContact law(k, contact, contact_exponent(imp.nose));
  NewmarkStepper impactor(nc, imp.mass, 0.0, imp.velocity);
  PlateState state{Eigen::VectorXd::Zero(n), Eigen::VectorXd::Zero(n), Eigen::VectorXd::Zero(n)};
  Eigen::VectorXd u_next(n), a_next(n);

  ImpactResult r;
  r.warnings = s.warnings;
  r.dofs = static_cast<int>(equations);
  r.contact_point_response = contact_point_only;
  r.inplane_eliminated = policy.inplane_eliminated();
  const double e0 = 0.5 * imp.mass * imp.velocity * imp.velocity;
  double force = 0.0, alpha = 0.0, ws = 0.0, contact_work = 0.0, law_work = 0.0;
  ImpactEvent event(r, s);
  ProgressiveDamageResult damage_onsets; ///< when and where the plies first cracked, per mode too
  PlateAccess plate_access(*plate, state, force);

  StepView view;
  view.dt = s.dt;
  view.plate = rigid ? nullptr : &plate_access;
  const auto update_view = [&](long step, double t) {
    view.step = step;
    view.t = t;
    view.force = force;
    view.indentation = alpha;
    view.plate_w = ws;
    view.impactor_w = impactor.displacement();
    view.impactor_v = impactor.velocity();
    view.impactor_energy = impactor.kinetic_energy();
    view.contact_work = contact_work;
    plate_access.next_step();
  };
  update_view(0, 0.0);
  for (ImpactObserver* o : observers)
    o->on_start(view);
  const auto observer_stop = [&] {
    return std::any_of(observers.begin(), observers.end(),
                       [](const ImpactObserver* o) { return o->wants_stop(); });
  };

  long step = 0;
  double t = 0.0;
  bool ended = false;
  for (;;) {
    if (event.must_stop(step, t, step > 0 && observer_stop())) break;
    ++step;

    // 1. Plate and contact force together (the step policy), solved again at a shorter step while the
    //    error control asks for one.
    ContactSolution cs;
    const NewmarkCoefficients* step_nc = &nc;
    const double t_accepted = t;
    std::optional<std::string> failure; // the step's error, where the run keeps what it computed
    try {
      for (;;) {
        if (control) {
          if (s.end) control->end_by(*s.end);
          plate->set_time_step_level(control->level());
          impactor.set_coefficients(control->coefficients());
          step_nc = &control->coefficients();
          t = control->step_end_time();
        } else {
          t = static_cast<double>(step) * s.dt;
        }
        cs = plate->advance(step, t, state, CondensedContact(law, impactor, {force, alpha}), u_next);
        plate->next_acceleration(*step_nc, state, u_next, a_next);
        if (!control) break;
        if (cs.force == 0.0 && force == 0.0) { // out of contact: nothing to control
          control->accept_free_flight();
          break;
        }
        if (control->accept(control->indentation_errors(impactor.acceleration(), -cs.force / imp.mass,
                                                        plate->contact_deflection(state.a),
                                                        plate->contact_deflection(a_next))))
          break;
      }
    } catch (const NewtonFailure& e) {
      if (!s.keep_failed_run) throw;
      failure = e.what();
    } catch (const BandLimitError& e) { // a ply mode starts where the mesh is too coarse for its law
      if (!s.keep_failed_run) throw;
      failure = e.what();
    }
    if (failure) { // the run ends at the last accepted step, what it computed kept (keep_failed_run)
      r.failure = r.stop_reason = *failure;
      --step;
      t = t_accepted;
      break;
    }
    r.newton_iterations_max = std::max(r.newton_iterations_max, cs.iterations);
    const double force_old = force, alpha_old = alpha;
    force = cs.force;
    alpha = cs.alpha;
    check_finite_step(step, t, {{"contact force Fc [N]", force}, {"indentation alpha [m]", alpha}});
    law_work += law.work(alpha_old, alpha); // the energy balance's contact work (check_after_run)
    law.commit(alpha);
    contact_work += 0.5 * (force + force_old) * (alpha - alpha_old);
    impactor.advance(force);

    // 2. Newmark update of the plate (2.11)–(2.16).
    plate->accept(state, u_next);
    update_velocity(*step_nc, state.a, a_next, state.v);
    state.u.swap(u_next);
    state.a.swap(a_next);
    ws = rigid ? 0.0 : plate->contact_deflection(state.u);
    check_finite_step(step, t,
                      {{"impactor displacement [m]", impactor.displacement()},
                       {"impactor velocity [m/s]", impactor.velocity()},
                       {"contact-point deflection ws [m]", ws}});
    if (const std::optional<double> added = plate->added_mass_kinetic_energy(state))
      r.added_mass_kinetic_energy = std::max(r.added_mass_kinetic_energy.value_or(0.0), *added);
    if (!rigid && step % full_state_check_every == 0) {
      check_finite_vector(step, t, "plate displacement u", state.u);
      check_finite_vector(step, t, "plate velocity", state.v);
      check_finite_vector(step, t, "plate acceleration", state.a);
    }

    // 3. Episodes and peaks, observers, end of the event.
    event.record(t, step_nc->dt, force, alpha, ws);
    if (const PlyDamageView* d = ply_damage_of(*plate)) record_damage_onsets(*d, t, force, damage_onsets);
    view.dt = step_nc->dt;
    update_view(step, t);
    if (step % energy_check_every == 0 && e0 > 0.0)
      view.energy_balance_error = balance_error(view, e0, law_work);
    for (ImpactObserver* o : observers)
      o->on_step(view);
    if (s.stop_at_energy_error && view.energy_balance_error &&
        *view.energy_balance_error > *s.stop_at_energy_error) {
      r.stop_reason = energy_stop_reason(view, *s.stop_at_energy_error);
      break;
    }
    const auto separation_state = [&] {
      return SeparationState{
          t,  impactor.displacement(),     impactor.velocity(),
          ws, law.permanent_indentation(), view.plate_kinetic_energy() + view.plate_strain_energy()};
    };
    if (event.over(step, t, separation_state)) {
      ended = true;
      break;
    }
  }
  event.finish(ended, step, t, law, impactor, e0, contact_work);
  check_after_run(r, view, e0, law_work, imp, k, contact.load, s);
  r.newton = plate->statistics();
  if (control) {
    r.time_steps = control->result(policy.factorizations());
    if (r.time_steps->steps_above_tolerance > 0)
      r.warnings.push_back(fmt::format("adaptive time steps: {} steps at the smallest allowed step, {:.4g} "
                                       "s, kept a local error up to {:.3g} "
                                       "times the tolerance: raise [time] levels or lower dt",
                                       r.time_steps->steps_above_tolerance, r.time_steps->smallest_allowed_dt,
                                       r.time_steps->largest_error_ratio));
  }
  r.delamination = delamination_of(*plate);
  if (const PlyDamageView* d = ply_damage_of(*plate)) {
    ProgressiveDamageResult pd = damage_onsets;
    pd.dissipated = d->dissipated();
    pd.ply_damage_area = d->ply_damage_area();
    pd.projected_damage_area = d->projected_damage_area();
    pd.element_ply_damage = d->element_ply_damage();
    pd.active_elements = d->active_elements();
    pd.strength_reduction = d->strength_reduction();
    r.progressive = std::move(pd);
  }
  if (view.plate) r.final_plate_energy = view.plate_kinetic_energy() + view.plate_strain_energy();
  r.wall_time = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();
  for (ImpactObserver* o : observers)
    o->on_finish(view, r);
  return r;
}

} // namespace plyimpact
