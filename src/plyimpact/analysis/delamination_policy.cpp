// The step policies of the stacked plate (docs/delamination.md): the stacked model (fem/stacked_model.hpp)
// under Newton–Newmark (newton_newmark_step.cpp), its interfaces iterated (implicit) or held over the step
// (lagged), or under central differences (central_difference_step.cpp); what the table of capabilities
// refuses; the implicit steps' Δt bound (DL5) and the explicit one's stable step.
#include "plyimpact/analysis/capabilities.hpp"
#include "plyimpact/analysis/central_difference.hpp"
#include "plyimpact/analysis/step_policy.hpp"
#include "plyimpact/fem/stacked_model.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace plyimpact {

namespace {

/// The deck key that chooses explicit steps for the stacked plate, for its messages.
constexpr const char* explicit_key = "[delamination] integration = \"explicit\"";

/// How Newton–Newmark iterates the stacked plate: with the delamination settings' iterations; where the
/// sub-laminates deflect largely also the periodic refresh of the non-linear settings (the tangents move
/// with u). Where the interfaces are iterated, and on the lagged linear stack, the corrections that do not
/// lower the residual are halved and the matrix refreshed every `refresh_after` solves, as the stacked
/// plate's own step did; the lagged stacks with ply damage or large deflections, written on Newton–Newmark
/// first, refresh after `refresh_after` solves and do not halve (each kept so that no example's numbers
/// move).
NewtonSettings stack_newton_settings(const DelaminationSettings& ds, bool ply_damage,
                                     const std::optional<NonlinearImpactSettings>& large_deflection) {
  NewtonSettings ns = newton_settings_of(ds, large_deflection ? "non-linear delamination"
                                             : ply_damage     ? "ply damage and delamination"
                                                              : "delamination");
  if ((ply_damage || large_deflection) && ds.integration == DamageIntegration::lagged) {
    ns.refresh_after = ds.refresh_after;
  } else {
    ns.refresh_every = ds.refresh_after;
    ns.max_halvings = 6;
  }
  if (large_deflection) ns.refresh_interval = large_deflection->refresh_interval;
  if (ply_damage && ds.integration == DamageIntegration::implicit)
    ns.advice = "set integration = \"lagged\" in [damage] and [delamination] (no iteration on either law), "
                "or reduce time.dt";
  return ns;
}

/// Steepest softening slope of the law over the pure modes [Pa/m] (DL5).
double softening_slope(const CohesiveParameters& p) {
  const double K = p.penalty_stiffness;
  const auto slope = [K](double strength, double G_c) {
    return strength / (2.0 * G_c / strength - strength / K);
  };
  return std::max(slope(p.normal_strength, p.G_Ic), slope(p.shear_strength, p.G_IIc));
}

/// The implicit step's Δt against (DL5), for the stacks without ply damage (the stack with cracking plies
/// takes half its stable step, plies_with_interfaces_step_fraction).
void check_time_step(const PlateModel& model, const StepPolicyOptions& options,
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

double explicit_delamination_highest_frequency(const PlateModel& model,
                                               const DelaminationSettings& settings) {
  const StackedPlateModel stack = impact_stack(model, settings);
  const SparseMatrix elastic =
      stack.evaluate(Eigen::VectorXd::Zero(stack.size()), stack.virgin_state()).tangent;
  return explicit_highest_frequency(elastic, MassOperator(stack.mass(), 1e-14), explicit_key);
}

double explicit_delamination_time_step(const PlateModel& model, const DelaminationSettings& settings) {
  return stable_time_step(explicit_delamination_highest_frequency(model, settings));
}

std::unique_ptr<StepPolicy>
explicit_delamination_step_policy(const PlateModel& model, const StepPolicyOptions& options,
                                  const DelaminationSettings& settings,
                                  const std::optional<ProgressiveDamageSettings>& ply_damage,
                                  std::optional<StrainMeasure> large_deflection) {
  return central_difference_step_policy(stacked_plate_model(model, settings, ply_damage, large_deflection),
                                        options, explicit_key);
}

double largest_delamination_time_step(const Laminate& laminate, const StackSettings& stack,
                                      double newmark_beta) {
  const std::vector<Laminate> parts = split_laminate(laminate, stack.cuts, stack.shear_correction);
  const double k_s = softening_slope(stack.interface);
  double limit = INFINITY;
  for (std::size_t i = 0; i + 1 < parts.size(); ++i) {
    const double m_u = parts[i].inertia()[0], m_l = parts[i + 1].inertia()[0];
    limit = std::min(limit, std::sqrt(m_u * m_l / (m_u + m_l) / (newmark_beta * k_s)));
  }
  return limit;
}

std::unique_ptr<StepPolicy>
delamination_step_policy(const PlateModel& model, const StepPolicyOptions& options,
                         const DelaminationSettings& settings,
                         const std::optional<ProgressiveDamageSettings>& ply_damage,
                         const std::optional<NonlinearImpactSettings>& large_deflection) {
  const ModelKind kind{false, large_deflection.has_value(), ply_damage.has_value(), true};
  const Integrator integrator =
      resolve_integrator(kind, TimeIntegration::newmark,
                         ply_damage ? std::optional(integrator_of(ply_damage->integration)) : std::nullopt,
                         integrator_of(settings.integration));
  if (auto why = refusal(kind, integrator)) throw std::invalid_argument(*why); // capabilities.hpp
  std::optional<StrainMeasure> measure;
  if (large_deflection) {
    if (ply_damage && large_deflection->measure != StrainMeasure::von_karman)
      throw std::invalid_argument(
          "progressive damage takes the von Kármán strains of a non-linear plate: set strain_measure = "
          "\"von-karman\" (the Green–Lagrange measure is not built for the layered section whose plies "
          "crack)");
    measure = large_deflection->measure;
  }
  if (settings.integration == DamageIntegration::central_difference)
    return explicit_delamination_step_policy(model, options, settings, ply_damage, measure);
  if (!ply_damage) check_time_step(model, options, settings);
  return newton_newmark_step_policy(
      stacked_plate_model(model, settings, ply_damage, measure), options,
      stack_newton_settings(settings, ply_damage.has_value(), large_deflection));
}

} // namespace plyimpact
