#pragma once
// What a run of every integrator written against fem/mechanical_model.hpp shares (Newton–Newmark,
// central differences): the impactor's load on the model's contact plate, the run's ModelState with the
// trial force of the step, and what the time loop reads through them (energies, the contact point's
// deflection, the displacement in the case's numbering, the model's results). The integrators differ
// only in how a step is solved (advance).
#include "plyimpact/analysis/integrators/step_policy.hpp"
#include "plyimpact/fem/mechanical_model.hpp"

#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace plyimpact {

/// The model's mass as the integrators apply it: the lumped mass is diagonal when I1 = 0, and a symmetric
/// layup gives I1 at round-off level (~1e-20), whose u–θ entries are dropped rather than turning every
/// M·x into a sparse product.
[[nodiscard]] inline MassOperator integrator_mass(const MechanicalModel& model) {
  return {model.mass(), 1e-14};
}

/// What the policy of every integrator written against the model holds for its runs: the model, the
/// options and the mass, built once per case.
class ModelPolicy : public StepPolicy {
public:
  ModelPolicy(std::unique_ptr<const MechanicalModel> model, const StepPolicyOptions& options)
      : ModelPolicy(std::move(model), options, std::nullopt) {}
  /// With the mass `M` in place of the model's (a scaled lumped mass, mass_scaling.hpp).
  ModelPolicy(std::unique_ptr<const MechanicalModel> model, const StepPolicyOptions& options,
              std::optional<MassOperator> M)
      : model_(std::move(model)), options_(options), M_(M ? std::move(*M) : integrator_mass(*model_)) {
    set_equations({model_->size(), model_->inplane_eliminated(), false, model_->warnings()});
  }

  std::unique_ptr<const MechanicalModel> model_;
  StepPolicyOptions options_;
  MassOperator M_;
};

class ModelStepper : public PlateStepper {
public:
  /// `policy` outlives the run.
  ModelStepper(const ModelPolicy& policy, const Impactor& impactor)
      : model_(*policy.model_), loading_(model_.contact_plate(), model_.contact_equations(), impactor,
                                         policy.options_.load, model_.size()),
        state_(model_.virgin_state()), f_int_(Eigen::VectorXd::Zero(model_.size())), M_(policy.M_),
        scratch_(model_.size()) {
    set_facts({.results = &state_->results()});
  }

  /// The trial of the accepted step, whose force f_int_ holds, is committed.
  void accept(const PlateState& /*before*/, const Eigen::VectorXd& u_next) override {
    state_->commit(u_next, f_int_);
  }
  [[nodiscard]] double kinetic_energy(const PlateState& s) const override {
    return M_.kinetic_energy(s.v, scratch_);
  }
  [[nodiscard]] double strain_energy(const PlateState& s, double /*force*/) const override {
    return state_->stored_energy(s.u);
  }
  [[nodiscard]] double contact_deflection(const Eigen::VectorXd& u) const override {
    return loading_.sampler().dot(u);
  }
  void to_model(const Eigen::VectorXd& u, Eigen::VectorXd& out) const override { model_.to_model(u, out); }

protected:
  const MechanicalModel& model_;
  ContactLoading loading_; ///< s_load, and with the factor of a Newton step K̄⁻¹ s_load and c = swᵀ K̄⁻¹ s_load
  std::unique_ptr<ModelState> state_;
  Eigen::VectorXd f_int_; ///< f_int of the step's last trial, sized once
  const MassOperator& M_;

private:
  mutable Eigen::VectorXd scratch_; ///< M v of the kinetic energy
};

} // namespace plyimpact
