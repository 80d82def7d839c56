#pragma once
// What the step policies of the plate whose plies crack share (fem/damaged_plate.hpp;
// docs/progressive_damage.md): the damaged plate built once per case with its warnings, and in each run
// the contact on the plate and the damage field, whose committed state gives the energies. Iterations
// with the secant (damage_step.cpp) and explicit central differences (central_difference_step.cpp, on any
// model of fem/mechanical_model.hpp) differ only in how a step is solved.
#include "plyimpact/analysis/step_policy.hpp"

#include <string>
#include <vector>

namespace plyimpact {

class DamagedPlatePolicy : public StepPolicy {
public:
  DamagedPlatePolicy(const PlateModel& model, const StepPolicyOptions& options,
                     const ProgressiveDamageSettings& settings)
      : model_(model), options_(options), plate_(model, settings), equations_(model.size()) {}

  [[nodiscard]] int equations() const override { return model_.size(); }
  /// Strengths lowered to the band limit, where they were.
  [[nodiscard]] std::vector<std::string> warnings() const override {
    if (auto w = plate_.strength_reduction_warning()) return {std::move(*w)};
    return {};
  }

  const PlateModel& model_;
  StepPolicyOptions options_;
  DamagedPlateModel plate_;
  EquationSubset equations_; ///< every equation of the plate
};

/// One run on the damaged plate: the impactor's contact and the damage field.
class DamagedPlateStepper : public PlateStepper {
public:
  DamagedPlateStepper(const DamagedPlatePolicy& policy, const Impactor& impactor)
      : loading_(policy.model_, policy.equations_, impactor, policy.options_.load),
        field_(policy.plate_.virgin_field()), f_int_(Eigen::VectorXd::Zero(policy.equations())) {}

  /// ½ uᵀ K_s(d) u of the accepted state.
  [[nodiscard]] double strain_energy(const PlateState& /*s*/, double /*force*/) const override {
    return field_.stored_energy();
  }
  [[nodiscard]] double dissipated_energy() const override { return field_.dissipated().sum(); }
  [[nodiscard]] const DamageField* damage() const override { return &field_; }
  [[nodiscard]] double contact_deflection(const Eigen::VectorXd& u) const override {
    return loading_.sampler().dot(u);
  }
  void to_model(const Eigen::VectorXd& u, Eigen::VectorXd& out) const override { out = u; }

protected:
  ContactLoading loading_;
  DamageField field_;
  Eigen::VectorXd f_int_; ///< f_int of the last evaluation of the law
};

} // namespace plyimpact
