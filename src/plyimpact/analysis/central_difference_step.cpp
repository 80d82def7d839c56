// Central differences on a lumped mass for any plate model (central_difference.hpp: CD1 to CD6), written
// once against the model interface of fem/mechanical_model.hpp: the elastic plate, the von Kármán plate,
// the plate whose plies crack and the stacked plate whose interfaces delaminate (stacked_model.cpp), as
// Abaqus/Explicit, LS-DYNA and OpenRadioss run them. The model's internal force is evaluated once per
// step, at u_{n+1} (CD3), from the state committed at the step before.
//
// Nothing is solved or iterated, so no step can stall where many points soften at once (the implicit
// damage step's limit, docs/progressive_damage.md), and a law sees each point's strain at the step's own
// end. The impactor keeps its implicit Newmark update through the scalar contact problem of SPEC §4 with
// the plate's compliance 0.
#include "plyimpact/analysis/central_difference.hpp"
#include "plyimpact/analysis/model_stepper.hpp"
#include "plyimpact/analysis/nonlinear_static.hpp"
#include "plyimpact/analysis/step_policy.hpp"
#include "plyimpact/fem/mechanical_model.hpp"

#include <utility>

namespace plyimpact {

namespace {

/// The deck key that chooses explicit steps for the plate whose plies crack, for its messages.
constexpr const char* explicit_damage_key = "[damage] integration = \"explicit\"";

class CentralDifferencePolicy;

class CentralDifferenceStepper final : public ModelStepper {
public:
  CentralDifferenceStepper(const CentralDifferencePolicy& policy, const Impactor& impactor);
  ContactSolution advance(long step, double t, const PlateState& s, const ContactStep& contact,
                          Eigen::VectorXd& u_next) override;
  void next_acceleration(const NewmarkCoefficients& /*nc*/, const PlateState& /*s*/,
                         const Eigen::VectorXd& /*u_next*/, Eigen::VectorXd& a_next) const override {
    a_next = a_next_; // CD3: from the equation of motion, not from Newmark's (2.11)
  }
  [[nodiscard]] double kinetic_energy(const PlateState& s) const override;
  /// No solve and no factorization: all zero.
  [[nodiscard]] std::optional<NewtonStatistics> statistics() const override { return NewtonStatistics{}; }

private:
  const CentralDifferencePolicy& p_;
  Eigen::VectorXd a_next_;
  Eigen::VectorXd force_;            ///< Fc s_load − f_int of the step (CD3), sized once
  double contact_flexibility_ = 0.0; ///< sᵀM⁻¹s, 1 / the mass the contact spring moves [1/kg]
};

class CentralDifferencePolicy final : public StepPolicy {
public:
  CentralDifferencePolicy(std::unique_ptr<const MechanicalModel> model, const StepPolicyOptions& options,
                          std::string key)
      : model_(std::move(model)), options_(options),
        scheme_(model_->initial_stiffness(), MassOperator(model_->mass(), 1e-14), options.newmark,
                std::move(key), options.explicit_omega_max) {}

  [[nodiscard]] int equations() const override { return model_->size(); }
  [[nodiscard]] bool inplane_eliminated() const override { return model_->inplane_eliminated(); }
  [[nodiscard]] int factorizations() const override { return 0; }
  [[nodiscard]] std::unique_ptr<PlateStepper> start(const Impactor& impactor) const override {
    return std::make_unique<CentralDifferenceStepper>(*this, impactor);
  }
  [[nodiscard]] std::vector<std::string> warnings() const override { return model_->warnings(); }

  std::unique_ptr<const MechanicalModel> model_;
  StepPolicyOptions options_;
  CentralDifference scheme_;
};

CentralDifferenceStepper::CentralDifferenceStepper(const CentralDifferencePolicy& policy,
                                                   const Impactor& impactor)
    : ModelStepper(*policy.model_, policy.options_, impactor), p_(policy),
      a_next_(Eigen::VectorXd::Zero(policy.equations())), force_(Eigen::VectorXd::Zero(policy.equations())),
      contact_flexibility_(policy.scheme_.flexibility(loading_.sampler())) {}

ContactSolution CentralDifferenceStepper::advance(long step, double t, const PlateState& s,
                                                  const ContactStep& contact, Eigen::VectorXd& u_next) {
  p_.scheme_.predict(s, u_next);                                                 // CD1
  const ContactSolution cs = contact.solve(loading_.sampler().dot(u_next), 0.0); // CD2
  p_.scheme_.check_contact(step, t, cs, contact, contact_flexibility_);          // CD6
  state_->internal_force(u_next, p_.scheme_.time_step(), f_int_);
  loading_.scaled_load(cs.alpha, cs.force, force_);
  force_ -= f_int_;
  p_.scheme_.accelerate(force_, step, t, a_next_); // CD3
  return cs;
}

double CentralDifferenceStepper::kinetic_energy(const PlateState& s) const {
  return p_.scheme_.kinetic_energy(s.v);
}

} // namespace

std::unique_ptr<StepPolicy> central_difference_step_policy(std::unique_ptr<const MechanicalModel> model,
                                                           const StepPolicyOptions& options,
                                                           std::string key) {
  return std::make_unique<CentralDifferencePolicy>(std::move(model), options, std::move(key));
}

double explicit_highest_frequency(const MechanicalModel& model, const std::string& key) {
  return explicit_highest_frequency(model.initial_stiffness(), MassOperator(model.mass(), 1e-14), key);
}

double explicit_damage_highest_frequency(const PlateModel& model) {
  return explicit_highest_frequency(model.stiffness(), MassOperator(model.mass(), 1e-14),
                                    explicit_damage_key);
}

double explicit_stable_time_step(const PlateModel& model) {
  return stable_time_step(explicit_damage_highest_frequency(model));
}

std::unique_ptr<StepPolicy> explicit_damage_step_policy(const PlateModel& model,
                                                        const StepPolicyOptions& options,
                                                        const ProgressiveDamageSettings& settings,
                                                        Kinematics kinematics) {
  return central_difference_step_policy(damaging_plate_model(model, settings, kinematics), options,
                                        explicit_damage_key);
}

} // namespace plyimpact
