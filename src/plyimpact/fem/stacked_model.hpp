#pragma once
// The stacked plate of an impact as a model of mechanical_model.hpp (docs/delamination.md): the laminate
// of the impact's plate cut into sub-laminates tied by cohesive interfaces (stacked_plate.hpp), each
// sub-laminate elastic, with plies that crack (damaged_plate.hpp) or von Kármán's, struck on the top one.
// What builds it: the settings (DelaminationSettings), the stack cut from the impact's plate with its mesh
// guidance and warnings (StackedImpactPlate), and in each run the interfaces' committed states, their
// areas and dissipation (InterfaceStates); every integrator of analysis/ drives the model
// (stacked_plate_model).
#include "plyimpact/fem/damaged_plate.hpp"
#include "plyimpact/fem/mass_operator.hpp"
#include "plyimpact/fem/mechanical_model.hpp"
#include "plyimpact/fem/nonlinear_plate_element.hpp"
#include "plyimpact/fem/stacked_plate.hpp"

#include <cmath>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace plyimpact {

/// Settings of the stacked plate whose interfaces may delaminate (docs/delamination.md).
struct DelaminationSettings {
  StackSettings stack;         ///< the cuts, the interface law, its integration rule
  bool supports_on_all = true; ///< the supports hold every sub-laminate; false: the bottom one only
  /// The values of the law the deck left out, each with where it came from ("G_mt of the plies at the
  /// interfaces", ...), in the order G_Ic, G_IIc, bk_exponent, normal_strength, shear_strength.
  std::vector<std::pair<std::string, std::string>> law_defaults;
  /// Where delaminations grow: the check of the cohesive zone against the interface points' spacing
  /// (StackedImpactPlate::process_zone) measures the elements whose centre lies within zone_radius of
  /// (zone_x, zone_y) [m]; 0: every element.
  double zone_x = 0.0, zone_y = 0.0, zone_radius = 0.0;
  friend bool operator==(const DelaminationSettings&, const DelaminationSettings&) = default;
};

/// The cohesive zone's length against the interface points' spacing [m].
struct ProcessZone {
  double length = 0.0;
  double point_spacing = 0.0;
};

/// The laminate of `model` (one laminate, no regions) cut as `settings` says, with the supports of
/// `model` on the sub-laminates that `settings` names. Throws std::invalid_argument for a plate with
/// regions of other laminates.
[[nodiscard]] StackedPlate impact_stack(const DiscretePlate& model, const DelaminationSettings& settings);

/// The stacked plate of an impact case, as its policies and its explicit model share it: the stack cut
/// from the case's plate, its mass, its warnings and process zone, and the top sub-laminate's place in
/// the case's numbering.
class StackedImpactPlate {
public:
  StackedImpactPlate(const DiscretePlate& model, const DelaminationSettings& settings);

  /// A cohesive zone spanning fewer than three interface points, and strengths whose ratio does not keep
  /// the mixed-mode toughness.
  [[nodiscard]] std::vector<std::string> stack_warnings() const;
  /// The cohesive zone l = E2 G_c / τ² (Hillerborg, M = 1) of the shorter mode against the spacing of the
  /// interface points (half the largest element side with the nodal rule, over the elements of the
  /// settings' zone, or every element where none lies in it): fewer than three points in it and the onset
  /// and growth of a delamination depend on the mesh.
  [[nodiscard]] ProcessZone process_zone() const;
  /// The top sub-laminate's displacements (stack numbering) in the case model's numbering.
  void top_to_model(const Eigen::VectorXd& u, Eigen::VectorXd& out) const;

  const DiscretePlate& model_;
  DelaminationSettings settings_;
  StackedPlate stack_;
  EquationSubset top_equations_;  ///< every equation of the top sub-laminate
  SparseMatrix M_;                ///< the stack's mass, assembled once
  std::vector<int> model_of_top_; ///< model equation of each top sub-laminate equation (−1: none)
};

/// One run's interfaces: their committed states (a trial is committed with each accepted step), the
/// energy they dissipated, their areas and the whole result.
class InterfaceStates {
public:
  explicit InterfaceStates(const StackedImpactPlate& plate);

  /// The states (and the energy dissipated reaching them) that accept() commits. Swapped in: `trial`
  /// receives storage of earlier states to write the next trial into without allocating.
  void set_trial(StackedPlateState& trial, double dissipated) {
    std::swap(trial_, trial);
    trial_dissipated_ = dissipated;
  }
  void accept();
  [[nodiscard]] const StackedPlateState& committed() const { return committed_; }
  [[nodiscard]] double dissipated() const { return dissipated_; }
  /// Their areas and dissipation into `out` (its vectors reused from step to step).
  void areas(DelaminationAreas& out) const;
  [[nodiscard]] DelaminationResult result() const;

private:
  const StackedImpactPlate& plate_;
  StackedPlateState committed_, trial_;
  double trial_dissipated_ = 0.0, dissipated_ = 0.0;
};

/// The stack's fastest softening (DL5, docs/delamination.md): the steepest softening slope k_s of the
/// interface law over the pure modes, N/(2G_Ic/N − N/K) and S/(2G_IIc/S − S/K) [Pa/m], and the smallest
/// reduced mass per area m = m_u m_l/(m_u + m_l) of two neighbouring sub-laminates (I0 of each) [kg/m²].
struct SofteningMode {
  double slope = 0.0;
  double reduced_mass = INFINITY;
};
[[nodiscard]] SofteningMode fastest_softening(const Laminate& laminate, const StackSettings& stack);

/// The stacked plate as a model of fem/mechanical_model.hpp, for the integrators written once against it
/// (its trials advance or hold the laws, LawTrials: stacked_model.cpp). With `ply_damage` each
/// sub-laminate's plies crack too; with `large_deflection` each sub-laminate is a geometrically non-linear
/// plate with that strain measure (von Kármán's where the plies crack).
[[nodiscard]] std::unique_ptr<MechanicalModel>
stacked_plate_model(const DiscretePlate& model, const DelaminationSettings& settings,
                    const std::optional<ProgressiveDamageSettings>& ply_damage,
                    std::optional<StrainMeasure> large_deflection = std::nullopt);

} // namespace plyimpact
