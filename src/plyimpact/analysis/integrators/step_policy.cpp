// The one factory of step policies (issue 49): a cell of the table of what runs (capabilities.hpp), the
// plate's laws and its integrator, becomes a model of fem/ (mechanical_model.hpp, stacked_model.hpp) under
// one of the integrators written once: linear Newmark (linear_step.cpp), Newton–Newmark
// (newton_newmark_step.cpp) or central differences (central_difference_step.cpp). What differs from cell
// to cell is only how Newton iterates and what its messages advise, and the bound (DL5) on the implicit
// steps of the stacked plate.
#include "plyimpact/analysis/integrators/step_policy.hpp"
#include "plyimpact/analysis/impact/capabilities.hpp"
#include "plyimpact/fem/mechanical_model.hpp"
#include "plyimpact/fem/stacked_model.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace plyimpact {

namespace {

/// The implicit step's Δt against (DL5), for the stacks without ply damage.
void check_delamination_time_step(const DiscretePlate& model, const StepPolicyOptions& options,
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

/// The model `p` makes, as a row of the table of what runs (capabilities.hpp).
ModelKind model_kind_of(const PlatePhysics& p) {
  return {false, p.large_deflection.has_value(), p.ply_damage.has_value(), p.interfaces.has_value()};
}

} // namespace

std::string explicit_key(const PlatePhysics& p) {
  if (p.interfaces) return "[delamination] integration = \"explicit\"";
  if (p.ply_damage) return "[damage] integration = \"explicit\"";
  return "[time] integration = \"explicit\"";
}

DelaminationSettings interfaces_for(DelaminationSettings interfaces, Integrator integrator) {
  if (integrator == Integrator::central_difference)
    interfaces.stack.interface.cracked_closing_fraction = cracked_faces_closing_fraction; // (DL10)
  return interfaces;
}

std::unique_ptr<MechanicalModel> mechanical_model(const DiscretePlate& plate, const PlatePhysics& p) {
  const ModelKind kind = model_kind_of(p);
  if (auto why = refusal(kind, p.integrator)) throw std::invalid_argument(*why); // capabilities.hpp
  std::optional<StrainMeasure> measure;
  if (p.large_deflection) measure = p.large_deflection->measure;
  CaseOptions options;
  options.element = plate.formulation();
  options.strain_measure = measure.value_or(StrainMeasure::von_karman);
  if (const Restriction* r = broken_restriction(kind, p.integrator, options))
    throw std::invalid_argument(std::string(r->message));
  if (p.interfaces)
    return stacked_plate_model(plate, interfaces_for(*p.interfaces, p.integrator), p.ply_damage, measure);
  if (p.ply_damage)
    return damaging_plate_model(plate, *p.ply_damage, measure ? Kinematics::von_karman : Kinematics::linear);
  if (measure) return von_karman_plate_model(plate, *measure);
  return elastic_plate_model(plate);
}

std::unique_ptr<StepPolicy> step_policy(const DiscretePlate& plate, const StepPolicyOptions& options,
                                        const PlatePhysics& p, std::unique_ptr<const MechanicalModel> model) {
  const bool linear = !p.large_deflection && !p.ply_damage && !p.interfaces;
  if (linear && p.integrator == Integrator::implicit) return linear_step_policy(plate, options);
  if (!model) model = mechanical_model(plate, p);
  if (p.integrator == Integrator::central_difference)
    return central_difference_step_policy(std::move(model), options, explicit_key(p));
  if (p.interfaces && !p.ply_damage) check_delamination_time_step(plate, options, *p.interfaces);
  return newton_newmark_step_policy(
      std::move(model), options, p.newton.value_or(newton_newmark_defaults(model_kind_of(p), p.integrator)),
      p.integrator == Integrator::lagged);
}

double largest_delamination_time_step(const Laminate& laminate, const StackSettings& stack,
                                      double newmark_beta) {
  const SofteningMode mode = fastest_softening(laminate, stack);
  return std::sqrt(mode.reduced_mass / (newmark_beta * mode.slope)); // (DL5)
}

} // namespace plyimpact
