// A rigid, immovable target (closed-form checks of the contact law): the plate has no equations and
// ws = 0, so the step is the impactor against the contact law alone.
#include "plyimpact/analysis/integrators/step_policy.hpp"

namespace plyimpact {

namespace {

class RigidStepper final : public PlateStepper {
public:
  ContactSolution advance(long /*step*/, double /*t*/, const PlateState& /*s*/,
                          const CondensedContact& contact, Eigen::VectorXd& /*u_next*/) override {
    return contact.solve(0.0, 0.0);
  }
  [[nodiscard]] double kinetic_energy(const PlateState& /*s*/) const override { return 0.0; }
  [[nodiscard]] double strain_energy(const PlateState& /*s*/, double /*force*/) const override { return 0.0; }
  [[nodiscard]] double contact_deflection(const Eigen::VectorXd& /*u*/) const override { return 0.0; }
  void to_model(const Eigen::VectorXd& /*u*/, Eigen::VectorXd& out) const override { out.resize(0); }
  void set_time_step_level(int /*level*/) override {} // nothing is factored: any step will do
};

class RigidTargetPolicy final : public StepPolicy {
public:
  RigidTargetPolicy() { set_equations({0, false, true, {}}); } // nothing is factored: any step will do
  [[nodiscard]] std::unique_ptr<PlateStepper> start(const Impactor& /*impactor*/,
                                                    bool /*contact_point_suffices*/) const override {
    return std::make_unique<RigidStepper>();
  }
};

} // namespace

std::unique_ptr<StepPolicy> rigid_target_policy() {
  return std::make_unique<RigidTargetPolicy>();
}

} // namespace plyimpact
