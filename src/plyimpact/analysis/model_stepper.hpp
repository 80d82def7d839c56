#pragma once
// What a run of every integrator written against fem/mechanical_model.hpp shares (Newton–Newmark,
// central differences): the impactor's load on the model's contact plate, the run's ModelState with the
// trial force of the step, and what the time loop reads through them (energies, the contact point's
// deflection, the displacement in the case's numbering, the model's results). The integrators differ
// only in how a step is solved (advance).
#include "plyimpact/analysis/step_policy.hpp"
#include "plyimpact/fem/mechanical_model.hpp"

#include <memory>

namespace plyimpact {

class ModelStepper : public PlateStepper {
public:
  /// `M`: the model's mass as the integrator applies it (the policy's, outliving the run).
  ModelStepper(const MechanicalModel& model, const StepPolicyOptions& options, const Impactor& impactor,
               const MassOperator& M)
      : model_(model),
        loading_(model.contact_plate(), model.contact_equations(), impactor, options.load, model.size()),
        state_(model.virgin_state()), f_int_(Eigen::VectorXd::Zero(model.size())), M_(M),
        scratch_(model.size()) {}

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
  [[nodiscard]] double dissipated_energy() const override { return state_->dissipated_energy(); }
  [[nodiscard]] double contact_deflection(const Eigen::VectorXd& u) const override {
    return loading_.sampler().dot(u);
  }
  void to_model(const Eigen::VectorXd& u, Eigen::VectorXd& out) const override { model_.to_model(u, out); }
  [[nodiscard]] const ModelResults* results() const override { return state_.get(); }

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
