// The explicit step policy of the plate whose plies crack (fem/damaged_plate.hpp): central differences
// with the lumped mass, as Abaqus/Explicit, LS-DYNA (MAT_054/058) and OpenRadioss (LAW25) run such laws.
//
//   u_{n+1} = uₙ + Δt vₙ + ½Δt² aₙ                                    (CD1: Newmark with β = 0)
//   Fc_{n+1} = F(α),  α = w_i,n+1 − sᵀu_{n+1}                         (CD2: u_{n+1} does not depend on
//                                                                       Fc_{n+1}; the contact compliance
//                                                                       of the plate is 0)
//   a_{n+1} = M⁻¹ (Fc_{n+1} s_load − f_int(u_{n+1}))                   (CD3: the law once, at u_{n+1})
//   v_{n+1} = vₙ + ½Δt (aₙ + a_{n+1})                                  (CD4: γ = ½, the time loop's update)
//
// Nothing is solved or iterated, so no step can stall where many points soften at once (the implicit
// step's limit, docs/progressive_damage.md), and the law sees each point's strain at the step's own end:
// no crack closes a step late (what pumped energy in the lagged step). The impactor keeps its implicit
// Newmark update through the scalar contact problem of SPEC §4 with the plate's compliance 0.
//
// Stability: the undamped central-difference step is stable for Δt ω_max < 2, ω_max the highest
// frequency of K φ = ω² M φ (damage only lowers it). The policy refuses Δt > 0.9 · 2/ω_max of the
// undamaged plate (CD5); the contact spring adds ω_c² = k_c sᵀM⁻¹s at the impact point, which each step
// checks with the secant k_c of the contact law (CD6) and stops the run, naming the step to use, where
// Δt √(ω_max² + ω_c²) > 2.
#include "plyimpact/analysis/modal_analysis.hpp"
#include "plyimpact/analysis/nonlinear_static.hpp"
#include "plyimpact/analysis/step_policy.hpp"

#include <fmt/format.h>

#include <cmath>

namespace plyimpact {

namespace {

/// The largest Δt the policy accepts, as a fraction of the undamaged plate's stable step 2/ω_max (CD5).
constexpr double stable_step_fraction = 0.9;

/// The lumped mass as a diagonal; throws where M is not diagonal or a DOF carries no mass.
const Eigen::VectorXd& diagonal_mass(const MassOperator& M) {
  if (M.diagonal().size() == 0 || !(M.diagonal().minCoeff() > 0.0))
    throw std::invalid_argument(
        "[damage] integration = \"explicit\" needs a diagonal mass with every DOF carrying mass: set "
        "[mesh] mass = \"lumped\"; a laminate that is not symmetric couples its lumped mass (I1 != 0), "
        "use integration = \"lagged\" for it");
  return M.diagonal();
}

/// CD5: the largest Δt accepted for K0 and the lumped mass M.
double stable_step(double omega_max) {
  return stable_step_fraction * 2.0 / omega_max;
}

class ExplicitDamagePolicy;

class ExplicitDamageStepper final : public PlateStepper {
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
  [[nodiscard]] double strain_energy(const PlateState& /*s*/, double /*force*/) const override {
    return field_.stored_energy(); // ½ uᵀ K_s(d) u of the accepted state
  }
  [[nodiscard]] double dissipated_energy() const override { return field_.dissipated().sum(); }
  [[nodiscard]] const DamageField* damage() const override { return &field_; }
  [[nodiscard]] double contact_deflection(const Eigen::VectorXd& u) const override {
    return loading_.sampler().dot(u);
  }
  void to_model(const Eigen::VectorXd& u, Eigen::VectorXd& out) const override { out = u; }
  /// No solve and no factorization: all zero.
  [[nodiscard]] std::optional<NewtonStatistics> statistics() const override { return NewtonStatistics{}; }

private:
  /// CD6: stops the run when the contact spring of secant stiffness k makes the step unstable.
  void check_contact_stability(long step, double t, const ContactSolution& cs,
                               const ContactStep& contact) const;

  const ExplicitDamagePolicy& p_;
  ContactLoading loading_;
  DamageField field_;
  Eigen::VectorXd f_int_; ///< f_int(u_{n+1}) of the last advance()
  Eigen::VectorXd a_next_;
  double contact_flexibility_ = 0.0; ///< sᵀM⁻¹s, 1 / the mass the contact spring moves [1/kg]
};

class ExplicitDamagePolicy final : public StepPolicy {
public:
  ExplicitDamagePolicy(const PlateModel& model, const StepPolicyOptions& options,
                       const ProgressiveDamageSettings& settings)
      : model_(model), options_(options), plate_(model, settings), equations_(model.size()),
        M_(model.mass(), 1e-14) {
    if (options.newmark.gamma != 0.5)
      throw std::invalid_argument(fmt::format(
          "[damage] integration = \"explicit\" is central differences (gamma = 0.5), got [time] gamma = {}",
          options.newmark.gamma));
    inverse_mass_ = diagonal_mass(M_).cwiseInverse();
    omega_max_ = highest_angular_frequency(plate_.undamaged_stiffness(), M_.diagonal());
    const double largest = stable_step(omega_max_);
    if (options.newmark.dt > largest)
      throw std::invalid_argument(fmt::format(
          "[damage] integration = \"explicit\": time.dt = {:.4g} s is above the stable step of this plate "
          "and mesh: set time.dt <= {:.4g} s, or dt = \"auto\" ({} x 2/omega_max, omega_max = {:.4g} "
          "rad/s; finer elements lower it)",
          options.newmark.dt, largest, stable_step_fraction, omega_max_));
  }

  [[nodiscard]] int equations() const override { return model_.size(); }
  [[nodiscard]] int factorizations() const override { return 0; }
  [[nodiscard]] std::unique_ptr<PlateStepper> start(const Impactor& impactor) const override {
    return std::make_unique<ExplicitDamageStepper>(*this, impactor);
  }
  [[nodiscard]] std::vector<std::string> warnings() const override {
    if (auto w = plate_.strength_reduction_warning()) return {std::move(*w)};
    return {};
  }

  const PlateModel& model_;
  StepPolicyOptions options_;
  DamagedPlateModel plate_;
  EquationSubset equations_;
  MassOperator M_;
  Eigen::VectorXd inverse_mass_;
  double omega_max_ = 0.0;
};

ExplicitDamageStepper::ExplicitDamageStepper(const ExplicitDamagePolicy& policy, const Impactor& impactor)
    : p_(policy), loading_(policy.model_, policy.equations_, impactor, policy.options_.load),
      field_(policy.plate_.virgin_field()), f_int_(Eigen::VectorXd::Zero(policy.equations())),
      a_next_(Eigen::VectorXd::Zero(policy.equations())) {
  const Eigen::VectorXd& s = loading_.sampler();
  contact_flexibility_ = s.dot(p_.inverse_mass_.cwiseProduct(s));
}

ContactSolution ExplicitDamageStepper::advance(long step, double t, const PlateState& s,
                                               const ContactStep& contact, Eigen::VectorXd& u_next) {
  const double dt = p_.options_.newmark.dt;
  u_next = s.u + dt * s.v + (0.5 * dt * dt) * s.a;                               // CD1
  const ContactSolution cs = contact.solve(loading_.sampler().dot(u_next), 0.0); // CD2
  check_contact_stability(step, t, cs, contact);
  f_int_ = p_.plate_.internal_force(u_next, dt, field_);
  // An element the screen left out that has reached a Hashin surface at u_{n+1} joins, and the law is
  // evaluated again at the same u_{n+1} (no solve: the displacement does not depend on it).
  if (p_.plate_.activate_reached(u_next, field_)) f_int_ = p_.plate_.internal_force(u_next, dt, field_);
  a_next_ = p_.inverse_mass_.cwiseProduct(cs.force * loading_.load(cs.alpha) - f_int_); // CD3
  if (!std::isfinite(a_next_.squaredNorm()))
    throw NewtonFailure(fmt::format("progressive damage (explicit): non-finite acceleration in step {} "
                                    "(t = {:.6g} s); reduce time.dt",
                                    step, t));
  return cs;
}

void ExplicitDamageStepper::check_contact_stability(long step, double t, const ContactSolution& cs,
                                                    const ContactStep& contact) const {
  const double d_alpha = cs.alpha - contact.previous_indentation();
  if (cs.force <= 0.0 || contact.previous_force() <= 0.0 || d_alpha == 0.0) return;
  const double k_secant = std::abs((cs.force - contact.previous_force()) / d_alpha);
  const double omega2 = p_.omega_max_ * p_.omega_max_ + k_secant * contact_flexibility_;
  const double dt = p_.options_.newmark.dt;
  if (dt * std::sqrt(omega2) <= 2.0) return;
  throw NewtonFailure(fmt::format(
      "progressive damage (explicit): in step {} (t = {:.6g} s) the contact spring (secant stiffness {:.4g} "
      "N/m on the impact point's lumped mass) makes time.dt = {:.4g} s unstable: set time.dt <= {:.4g} s",
      step, t, k_secant, dt, stable_step(std::sqrt(omega2))));
}

void ExplicitDamageStepper::accept(const PlateState& /*before*/, const Eigen::VectorXd& u_next) {
  p_.plate_.commit(u_next, f_int_, field_);
}

double ExplicitDamageStepper::kinetic_energy(const PlateState& s) const {
  return p_.M_.kinetic_energy(s.v);
}

} // namespace

double explicit_stable_time_step(const PlateModel& model) {
  const MassOperator M(model.mass(), 1e-14);
  return stable_step(highest_angular_frequency(model.stiffness(), diagonal_mass(M)));
}

std::unique_ptr<StepPolicy> explicit_damage_step_policy(const PlateModel& model,
                                                        const StepPolicyOptions& options,
                                                        const ProgressiveDamageSettings& settings) {
  return std::make_unique<ExplicitDamagePolicy>(model, options, settings);
}

} // namespace plyimpact
