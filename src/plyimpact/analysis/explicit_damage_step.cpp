// The explicit step policy of the plate whose plies crack (fem/damaged_plate.hpp): central differences
// with the lumped mass (central_difference.hpp, CD1 to CD6), as Abaqus/Explicit, LS-DYNA (MAT_054/058)
// and OpenRadioss (LAW25) run such laws. The ply law is evaluated once per step, at u_{n+1} (CD3).
//
// Nothing is solved or iterated, so no step can stall where many points soften at once (the implicit
// step's limit, docs/progressive_damage.md), and the law sees each point's strain at the step's own end:
// no crack closes a step late (what pumped energy in the lagged step). The impactor keeps its implicit
// Newmark update through the scalar contact problem of SPEC §4 with the plate's compliance 0.
#include "plyimpact/analysis/central_difference.hpp"
#include "plyimpact/analysis/damaged_plate_step.hpp"
#include "plyimpact/analysis/nonlinear_static.hpp"
#include "plyimpact/analysis/step_policy.hpp"

namespace plyimpact {

namespace {

/// The deck key that chooses this policy, for its messages.
constexpr const char* explicit_key = "[damage] integration = \"explicit\"";

class ExplicitDamagePolicy;

class ExplicitDamageStepper final : public DamagedPlateStepper {
public:
  ExplicitDamageStepper(const ExplicitDamagePolicy& policy, const Impactor& impactor);
  ContactSolution advance(long step, double t, const PlateState& s, const ContactStep& contact,
                          Eigen::VectorXd& u_next) override;
  void next_acceleration(const NewmarkCoefficients& /*nc*/, const PlateState& /*s*/,
                         const Eigen::VectorXd& /*u_next*/, Eigen::VectorXd& a_next) const override {
    a_next = a_next_;
  }
  void accept(const PlateState& before, const Eigen::VectorXd& u_next) override;
  [[nodiscard]] double kinetic_energy(const PlateState& s) const override;
  /// No solve and no factorization: all zero.
  [[nodiscard]] std::optional<NewtonStatistics> statistics() const override { return NewtonStatistics{}; }

private:
  const ExplicitDamagePolicy& p_;
  Eigen::VectorXd a_next_;
  Eigen::VectorXd force_;            ///< Fc s_load − f_int of the step (CD3), sized once
  double contact_flexibility_ = 0.0; ///< sᵀM⁻¹s, 1 / the mass the contact spring moves [1/kg]
};

class ExplicitDamagePolicy final : public DamagedPlatePolicy {
public:
  ExplicitDamagePolicy(const PlateModel& model, const StepPolicyOptions& options,
                       const ProgressiveDamageSettings& settings)
      : DamagedPlatePolicy(model, options, settings),
        scheme_(plate_.undamaged_stiffness(), MassOperator(model.mass(), 1e-14), options.newmark,
                explicit_key, options.explicit_omega_max) {}

  [[nodiscard]] int factorizations() const override { return 0; }
  [[nodiscard]] std::unique_ptr<PlateStepper> start(const Impactor& impactor) const override {
    return std::make_unique<ExplicitDamageStepper>(*this, impactor);
  }

  CentralDifference scheme_;
};

ExplicitDamageStepper::ExplicitDamageStepper(const ExplicitDamagePolicy& policy, const Impactor& impactor)
    : DamagedPlateStepper(policy, impactor), p_(policy), a_next_(Eigen::VectorXd::Zero(policy.equations())),
      force_(Eigen::VectorXd::Zero(policy.equations())),
      contact_flexibility_(policy.scheme_.flexibility(loading_.sampler())) {}

ContactSolution ExplicitDamageStepper::advance(long step, double t, const PlateState& s,
                                               const ContactStep& contact, Eigen::VectorXd& u_next) {
  p_.scheme_.predict(s, u_next);                                                 // CD1
  const ContactSolution cs = contact.solve(loading_.sampler().dot(u_next), 0.0); // CD2
  p_.scheme_.check_contact(step, t, cs, contact, contact_flexibility_);          // CD6
  // An element the screen left out that has reached a Hashin surface at u_{n+1} joins, and the law is
  // evaluated again at the same u_{n+1} (no solve: the displacement does not depend on it).
  p_.plate_.explicit_internal_force(u_next, p_.scheme_.time_step(), field_, f_int_);
  loading_.scaled_load(cs.alpha, cs.force, force_);
  force_ -= f_int_;
  p_.scheme_.accelerate(force_, step, t, a_next_); // CD3
  return cs;
}

void ExplicitDamageStepper::accept(const PlateState& /*before*/, const Eigen::VectorXd& u_next) {
  p_.plate_.commit(u_next, f_int_, field_);
}

double ExplicitDamageStepper::kinetic_energy(const PlateState& s) const {
  return p_.scheme_.kinetic_energy(s.v);
}

} // namespace

double explicit_damage_highest_frequency(const PlateModel& model) {
  return explicit_highest_frequency(model.stiffness(), MassOperator(model.mass(), 1e-14), explicit_key);
}

double explicit_stable_time_step(const PlateModel& model) {
  return stable_time_step(explicit_damage_highest_frequency(model));
}

std::unique_ptr<StepPolicy> explicit_damage_step_policy(const PlateModel& model,
                                                        const StepPolicyOptions& options,
                                                        const ProgressiveDamageSettings& settings) {
  return std::make_unique<ExplicitDamagePolicy>(model, options, settings);
}

} // namespace plyimpact
