#pragma once
// What the step policies of the stacked plate share (fem/stacked_plate.hpp; docs/delamination.md): the
// stack cut from the impact's plate, the mesh guidance and warnings, and in each run the interfaces'
// committed states, their areas and dissipation. Newton iterations (delamination_step.cpp) and explicit
// central differences (explicit_delamination_step.cpp) differ only in how a step is solved.
#include "plyimpact/analysis/step_policy.hpp"

#include <string>
#include <vector>

namespace plyimpact {

/// The cohesive zone's length against the interface points' spacing [m].
struct ProcessZone {
  double length = 0.0;
  double point_spacing = 0.0;
};

/// The laminate of `model` (one laminate, no regions) cut as `settings` says, with the supports of
/// `model` on the sub-laminates that `settings` names. Throws std::invalid_argument for a plate with
/// regions of other laminates.
[[nodiscard]] StackedPlateModel impact_stack(const PlateModel& model, const DelaminationSettings& settings);

class StackedPlatePolicy : public StepPolicy {
public:
  StackedPlatePolicy(const PlateModel& model, const StepPolicyOptions& options,
                     const DelaminationSettings& settings);

  [[nodiscard]] int equations() const override { return stack_.size(); }
  /// A cohesive zone spanning fewer than three interface points, and strengths whose ratio does not keep
  /// the mixed-mode toughness.
  [[nodiscard]] std::vector<std::string> warnings() const override;
  /// The cohesive zone l = E2 G_c / τ² (Hillerborg, M = 1) of the shorter mode against the spacing of the
  /// interface points (half the largest element side with the nodal rule): fewer than three points in it
  /// and the onset and growth of a delamination depend on the mesh.
  [[nodiscard]] ProcessZone process_zone() const;

  const PlateModel& model_;
  StepPolicyOptions options_;
  DelaminationSettings settings_;
  StackedPlateModel stack_;
  EquationSubset top_equations_; ///< every equation of the top sub-laminate
  MassOperator M_;
  std::vector<int> model_of_top_; ///< model equation of each top sub-laminate equation (−1: none)
};

/// One run on the stacked plate: the impactor's contact on the top sub-laminate and the interfaces'
/// states, committed with each accepted step.
class StackedPlateStepper : public PlateStepper {
public:
  StackedPlateStepper(const StackedPlatePolicy& policy, const Impactor& impactor);

  void accept(const PlateState& before, const Eigen::VectorXd& u_next) override;
  [[nodiscard]] double kinetic_energy(const PlateState& s) const override {
    return base_.M_.kinetic_energy(s.v, scratch_);
  }
  /// ½ uᵀ K_plates u + the interfaces' stored energy at their committed damage.
  [[nodiscard]] double strain_energy(const PlateState& s, double force) const override;
  [[nodiscard]] double dissipated_energy() const override { return dissipated_; }
  [[nodiscard]] double contact_deflection(const Eigen::VectorXd& u) const override {
    return loading_.sampler().dot(u);
  }
  /// The top sub-laminate's displacements in the model's numbering.
  void to_model(const Eigen::VectorXd& u, Eigen::VectorXd& out) const override;
  [[nodiscard]] std::optional<DelaminationResult> delamination() const override;
  bool delamination_areas(DelaminationAreas& out) const override;

protected:
  /// The states (and the energy dissipated reaching them) that accept() commits. Swapped in: `trial`
  /// receives storage of earlier states to write the next trial into without allocating.
  void set_trial(StackedPlateState& trial, double dissipated) {
    std::swap(trial_, trial);
    trial_dissipated_ = dissipated;
  }
  [[nodiscard]] const StackedPlateState& committed() const { return committed_; }

  ContactLoading loading_; ///< on the top sub-laminate, in the stacked numbering

private:
  const StackedPlatePolicy& base_;
  StackedPlateState committed_, trial_;
  mutable Eigen::VectorXd scratch_; ///< M v and K u of the energies, sized once
  double trial_dissipated_ = 0.0, dissipated_ = 0.0;
};

} // namespace plyimpact
