// What the step policies of the stacked plate share (stacked_plate_step.hpp).
#include "plyimpact/analysis/stacked_plate_step.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <stdexcept>

namespace plyimpact {

namespace {

const Laminate& single_laminate(const PlateModel& model) {
  if (!model.single_section())
    throw std::invalid_argument("delamination: the stacked plate needs one laminate over the whole plate; "
                                "[[regions]] with other laminates are not available with [delamination] "
                                "yet (docs/delamination.md, limits)");
  return model.laminate();
}

std::optional<std::string> process_zone_warning(const ProcessZone& z, CohesiveIntegration rule) {
  if (z.length >= 3.0 * z.point_spacing) return std::nullopt;
  return fmt::format(
      "delamination: the cohesive zone of the interfaces, E2 G_c / strength^2 = {:.3g} mm in the shorter "
      "mode, spans {:.2g} interface points ({:.3g} mm apart): fewer than 3, so the onset and growth of "
      "delaminations depend on the mesh. Refine to elements of {:.3g} mm or less, or lower both "
      "strengths (Turon et al. 2007: tau = sqrt(9 pi E2 G_c / (32 * 3 * {:.3g} mm))) "
      "(docs/delamination.md)",
      z.length * 1e3, z.length / z.point_spacing, z.point_spacing * 1e3,
      2.0 * z.length / 3.0 * 1e3 * (rule == CohesiveIntegration::nodal ? 1.0 : 1.5), z.point_spacing * 1e3);
}

/// Turon et al. (2010): with S/N ≠ √(G_IIc/G_Ic) the mixed-mode law does not dissipate G_c(B) along a
/// crack front whose mixity changes (measured: MMB 1.23 G_c with N halved alone).
std::optional<std::string> strength_ratio_warning(const CohesiveParameters& c) {
  const double ratio = (c.shear_strength / c.normal_strength) / std::sqrt(c.G_IIc / c.G_Ic);
  if (std::abs(ratio - 1.0) <= 0.1) return std::nullopt;
  return fmt::format("delamination: shear_strength / normal_strength = {:.3g} while sqrt(G_IIc / G_Ic) = "
                     "{:.3g}: under mixed mode the interfaces then dissipate more or less than G_c (Turon "
                     "et al. 2010; docs/delamination.md, MMB); set S = N sqrt(G_IIc / G_Ic) = {:.3g} MPa",
                     c.shear_strength / c.normal_strength, std::sqrt(c.G_IIc / c.G_Ic),
                     c.normal_strength * std::sqrt(c.G_IIc / c.G_Ic) * 1e-6);
}

/// The model equation of each equation of the stack's top sub-laminate (−1: none).
std::vector<int> top_equations_in_model(const PlateModel& model, const StackedPlateModel& stack) {
  const PlateModel& top = stack.sublaminate(0);
  std::vector<int> of_top(static_cast<std::size_t>(top.size()), -1);
  for (int n = 0; n < model.mesh().node_count(); ++n)
    for (int dof = 0; dof < 5; ++dof)
      if (const int eq = top.dofs().equation(n, dof); eq >= 0)
        of_top[static_cast<std::size_t>(eq)] = model.dofs().equation(n, dof);
  return of_top;
}

} // namespace

StackedPlateModel impact_stack(const PlateModel& model, const DelaminationSettings& settings) {
  const int bottom = static_cast<int>(settings.stack.cuts.size());
  return {model.mesh(), single_laminate(model), settings.stack,
          Discretization{model.mass_kind(), model.formulation()}, [&](int k) {
            return settings.supports_on_all || k == bottom ? model.boundary() : BoundaryConditions{};
          }};
}

StackedImpactPlate::StackedImpactPlate(const PlateModel& model, const DelaminationSettings& settings)
    : model_(model), settings_(settings), stack_(impact_stack(model, settings)),
      top_equations_(stack_.sublaminate(0).size()), M_(stack_.mass(), 1e-14),
      model_of_top_(top_equations_in_model(model, stack_)) {}

std::vector<std::string> StackedImpactPlate::stack_warnings() const {
  std::vector<std::string> w;
  if (auto zone = process_zone_warning(process_zone(), settings_.stack.rule)) w.push_back(std::move(*zone));
  if (auto ratio = strength_ratio_warning(settings_.stack.interface)) w.push_back(std::move(*ratio));
  return w;
}

ProcessZone StackedImpactPlate::process_zone() const {
  const CohesiveParameters& c = settings_.stack.interface;
  double E2 = INFINITY;
  for (const Material& m : model_.laminate().materials())
    E2 = std::min(E2, m.E2);
  double largest = 0.0;
  for (int e = 0; e < model_.mesh().element_count(); ++e) {
    const ElementCoordinates X = model_.mesh().element_coordinates(e);
    largest = std::max(
        {largest, X.col(0).maxCoeff() - X.col(0).minCoeff(), X.col(1).maxCoeff() - X.col(1).minCoeff()});
  }
  return {std::min(cohesive_zone_length(E2, c.G_Ic, c.normal_strength),
                   cohesive_zone_length(E2, c.G_IIc, c.shear_strength)),
          settings_.stack.rule == CohesiveIntegration::nodal ? 0.5 * largest : largest / 3.0};
}

void StackedImpactPlate::top_to_model(const Eigen::VectorXd& u, Eigen::VectorXd& out) const {
  out = Eigen::VectorXd::Zero(model_.size());
  for (std::size_t i = 0; i < model_of_top_.size(); ++i)
    if (const int eq = model_of_top_[i]; eq >= 0) out(eq) = u(static_cast<Eigen::Index>(i));
}

InterfaceStates::InterfaceStates(const StackedImpactPlate& plate)
    : plate_(plate), committed_(plate.stack_.virgin_state()) {}

void InterfaceStates::accept() {
  std::swap(committed_, trial_); // trial_ keeps the old states' storage for the next set_trial()
  dissipated_ += trial_dissipated_;
  trial_dissipated_ = 0.0;
}

void InterfaceStates::areas(DelaminationAreas& out) const {
  const StackedPlateModel& stack = plate_.stack_;
  const std::vector<std::vector<CohesiveState>>& states = committed_.interfaces;
  out.dissipated = dissipated_;
  out.delaminated_area.clear(); // keeps its capacity: no allocation after the first step
  out.delaminated_area.reserve(states.size());
  for (int i = 0; i < stack.interface_count(); ++i)
    out.delaminated_area.push_back(stack.interface(i).damaged_area(states[static_cast<std::size_t>(i)], 1.0));
  out.projected_area = 0.0;
  if (stack.interface_count() == 0) return;
  // Every interface has the same points (same mesh and rule): the union is taken point by point.
  const CohesiveInterface& points = stack.interface(0);
  for (int q = 0; q < points.point_count(); ++q)
    if (std::any_of(states.begin(), states.end(), [q](const std::vector<CohesiveState>& of_interface) {
          return of_interface[static_cast<std::size_t>(q)].damage >= 1.0;
        }))
      out.projected_area += points.point_area(q);
}

DelaminationResult InterfaceStates::result() const {
  const StackedPlateModel& stack = plate_.stack_;
  DelaminationResult r;
  DelaminationAreas areas;
  this->areas(areas);
  r.delaminated_area = std::move(areas.delaminated_area);
  r.projected_area = areas.projected_area;
  r.dissipated = areas.dissipated;
  const ProcessZone zone = plate_.process_zone();
  r.cohesive_zone_length = zone.length;
  r.interface_point_spacing = zone.point_spacing;
  for (int i = 0; i < stack.interface_count(); ++i) {
    const CohesiveInterface& ci = stack.interface(i);
    const std::vector<CohesiveState>& states = committed_.interfaces[static_cast<std::size_t>(i)];
    r.interface_after_ply.push_back(plate_.settings_.stack.cuts[static_cast<std::size_t>(i)] + 1);
    double softening = 0.0;
    const auto per_element = static_cast<std::size_t>(ci.points_per_element());
    std::vector<double>& of_element = r.element_damage.emplace_back(states.size() / per_element, 0.0);
    std::vector<double>& of_point = r.point_damage.emplace_back();
    for (std::size_t q = 0; q < states.size(); ++q) {
      const double d = states[q].damage;
      if (d > 0.0 && d < 1.0) softening += ci.point_area(static_cast<int>(q));
      double& largest = of_element[q / per_element];
      largest = std::max(largest, d);
      of_point.push_back(d);
    }
    r.process_zone_area.push_back(softening);
  }
  if (stack.interface_count() > 0)
    for (int q = 0; q < stack.interface(0).point_count(); ++q) {
      r.point_cells.push_back(stack.interface(0).point_cell(q));
      r.point_area.push_back(stack.interface(0).point_area(q));
    }
  return r;
}

} // namespace plyimpact
