// The one factory of step policies (issue 49): a cell of the table of what runs (capabilities.hpp), the
// plate's laws and its integrator, becomes a model of fem/ (mechanical_model.hpp, stacked_model.hpp) under
// one of the integrators written once: linear Newmark (linear_step.cpp), Newton–Newmark
// (newton_newmark_step.cpp) or central differences (central_difference_step.cpp). What differs from cell
// to cell is only how Newton iterates and what its messages advise, and the bound (DL5) on the implicit
// steps of the stacked plate.
#include "plyimpact/analysis/capabilities.hpp"
#include "plyimpact/analysis/step_policy.hpp"
#include "plyimpact/fem/mechanical_model.hpp"
#include "plyimpact/fem/stacked_model.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace plyimpact {

namespace {

/// The iteration settings every physics' settings carry (NonlinearImpactSettings, ProgressiveDamageSettings,
/// DelaminationSettings: solves per step, tolerances, the contraction ratio that refreshes the matrix), as
/// Newton–Newmark's, its failure messages naming `physics`.
template <class PhysicsSettings>
NewtonSettings newton_settings_of(const PhysicsSettings& s, std::string physics) {
  NewtonSettings ns;
  ns.control.max_iterations = s.max_iterations;
  ns.residual_tolerance = s.residual_tolerance;
  ns.displacement_tolerance = s.displacement_tolerance;
  ns.control.refresh_ratio = s.refresh_ratio;
  ns.physics = std::move(physics);
  return ns;
}

/// How Newton–Newmark iterates the stacked plate: with the delamination settings' iterations; where the
/// sub-laminates deflect largely also the periodic refresh of the non-linear settings (the tangents move
/// with u). Where the interfaces are iterated, and on the lagged linear stack, the corrections that do not
/// lower the residual are halved and the matrix refreshed every `refresh_after` solves, as the stacked
/// plate's own step did; the lagged stacks with ply damage or large deflections, written on Newton–Newmark
/// first, refresh after `refresh_after` solves and do not halve (each kept so that no example's numbers
/// move).
NewtonSettings stack_newton_settings(const PlatePhysics& p) {
  const DelaminationSettings& ds = *p.interfaces;
  NewtonSettings ns = newton_settings_of(ds, p.large_deflection ? "non-linear delamination"
                                             : p.ply_damage     ? "ply damage and delamination"
                                                                : "delamination");
  if ((p.ply_damage || p.large_deflection) && ds.integration == DamageIntegration::lagged) {
    ns.control.refresh_after = ds.refresh_after;
  } else {
    ns.control.refresh_every = ds.refresh_after;
    ns.max_halvings = 6;
  }
  if (p.ply_damage && ds.integration == DamageIntegration::implicit)
    ns.advice = "set integration = \"lagged\" in [damage] and [delamination] (no iteration on either law), "
                "or reduce time.dt";
  return ns;
}

/// The damage settings' iterations. The large-deflection settings' refresh after `refresh_after` solves is
/// left out: the damage's tighter tolerance takes more solves per step, and with it the plate of
/// examples/damage-progressive.toml refactored in 415 of its 266 steps (13 s) instead of 44 times (2.5 s)
/// with the contraction rule alone.
NewtonSettings damage_newton_settings(const ProgressiveDamageSettings& damage) {
  NewtonSettings ns = newton_settings_of(damage, "progressive damage");
  if (damage.integration != DamageIntegration::lagged)
    ns.advice = "set [damage] integration = \"lagged\" (no iteration on the damage; its energy balance "
                "error shrinks with time.dt), or reduce time.dt";
  return ns;
}

/// How Newton–Newmark iterates the plate of `p`; where it is von Kármán's, refreshed at most every
/// `refresh_interval` steps as well (its tangent moves with u).
NewtonSettings newton_settings(const PlatePhysics& p) {
  NewtonSettings ns;
  if (p.interfaces) {
    ns = stack_newton_settings(p);
  } else if (p.ply_damage) {
    ns = damage_newton_settings(*p.ply_damage);
  } else {
    ns = newton_settings_of(*p.large_deflection, "non-linear impact");
    ns.control.refresh_after = p.large_deflection->refresh_after;
  }
  if (p.large_deflection) ns.refresh_interval = p.large_deflection->refresh_interval;
  return ns;
}

/// The implicit step's Δt against (DL5), for the stacks without ply damage (the stack with cracking plies
/// takes half its stable step, plies_with_interfaces_step_fraction).
void check_delamination_time_step(const PlateModel& model, const StepPolicyOptions& options,
                                  const DelaminationSettings& settings) {
  const double dt = options.newmark.dt;
  const double limit = largest_delamination_time_step(model.laminate(), settings.stack, options.newmark.beta);
  if (dt > limit)
    throw std::invalid_argument(fmt::format(
        "delamination: time.dt = {:.4g} s is above {:.4g} s, the largest step at which an interface point "
        "that starts softening keeps the step solvable (the softening slope of the interface law against "
        "the inertia of the sub-laminates, docs/delamination.md); set [time] dt <= {:.3g} or \"auto\"",
        dt, limit, limit));
}

} // namespace

std::string explicit_key(const PlatePhysics& p) {
  if (p.interfaces) return "[delamination] integration = \"explicit\"";
  if (p.ply_damage) return "[damage] integration = \"explicit\"";
  return "[time] integration = \"explicit\"";
}

std::unique_ptr<MechanicalModel> mechanical_model(const PlateModel& plate, const PlatePhysics& p) {
  const ModelKind kind{false, p.large_deflection.has_value(), p.ply_damage.has_value(),
                       p.interfaces.has_value()};
  if (auto why = refusal(kind, p.integrator)) throw std::invalid_argument(*why); // capabilities.hpp
  std::optional<StrainMeasure> measure;
  if (p.large_deflection) measure = p.large_deflection->measure;
  if (p.ply_damage && measure && *measure != StrainMeasure::von_karman)
    throw std::invalid_argument(
        "progressive damage takes the von Kármán strains of a non-linear plate: set strain_measure = "
        "\"von-karman\" (the Green–Lagrange measure is not built for the layered section whose plies crack)");
  if (p.interfaces) return stacked_plate_model(plate, *p.interfaces, p.ply_damage, measure);
  if (p.ply_damage)
    return damaging_plate_model(plate, *p.ply_damage, measure ? Kinematics::von_karman : Kinematics::linear);
  if (measure) return von_karman_plate_model(plate, *measure);
  return elastic_plate_model(plate);
}

std::unique_ptr<StepPolicy> step_policy(const PlateModel& plate, const StepPolicyOptions& options,
                                        const PlatePhysics& p, std::unique_ptr<const MechanicalModel> model) {
  const bool linear = !p.large_deflection && !p.ply_damage && !p.interfaces;
  if (linear && p.integrator == Integrator::implicit) return linear_step_policy(plate, options);
  if (!model) model = mechanical_model(plate, p);
  if (p.integrator == Integrator::central_difference)
    return central_difference_step_policy(std::move(model), options, explicit_key(p));
  if (p.interfaces && !p.ply_damage) check_delamination_time_step(plate, options, *p.interfaces);
  return newton_newmark_step_policy(std::move(model), options, newton_settings(p));
}

double largest_delamination_time_step(const Laminate& laminate, const StackSettings& stack,
                                      double newmark_beta) {
  const SofteningMode mode = fastest_softening(laminate, stack);
  return std::sqrt(mode.reduced_mass / (newmark_beta * mode.slope)); // (DL5)
}

} // namespace plyimpact
