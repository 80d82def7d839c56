// Explicit central differences on a lumped mass for any plate model, written once against the model
// interface of fem/mechanical_model.hpp (the elastic, von Kármán, cracking and stacked plates), as
// Abaqus/Explicit, LS-DYNA and OpenRadioss run them:
//
//   u_{n+1} = uₙ + Δt vₙ + ½Δt² aₙ                                    (CD1: Newmark with β = 0)
//   Fc_{n+1} = F(α),  α = w_i,n+1 − sᵀu_{n+1}                         (CD2: u_{n+1} does not depend on
//                                                                       Fc_{n+1}; the plate's contact
//                                                                       compliance is 0)
//   a_{n+1} = M⁻¹ (Fc_{n+1} s_load − f_int(u_{n+1}))                   (CD3: the law once, at u_{n+1}, from
//                                                                       the state committed before; M
//                                                                       diagonal, or block-diagonal with
//                                                                       selective mass scaling; again
//                                                                       where the model admits an element
//                                                                       that reached a failure surface)
//   v_{n+1} = vₙ + ½Δt (aₙ + a_{n+1})                                  (CD4: γ = ½, the time loop's update)
//
// Stability: the undamped central-difference step is stable for Δt ω_max < 2, ω_max the highest
// frequency of K₀ φ = ω² M φ with K₀ the undamaged stiffness (damage only lowers it). A policy refuses
// Δt > 0.9 · 2/ω_max (CD5); the contact spring adds ω_c² = k_c sᵀM⁻¹s at the impact point, which each
// step checks with the secant k_c of the contact law (CD6), stopping the run, with the step to use, where
// Δt √(ω_max² + ω_c²) > 2.
//
// Nothing is solved or iterated, so no step can stall where many points soften at once (the implicit
// damage step's limit, docs/progressive_damage.md), and a law sees each point's strain at the step's own
// end. The impactor keeps its implicit Newmark update through the scalar contact problem of SPEC §4 with
// the plate's compliance 0.
#include "plyimpact/analysis/integrators/model_stepper.hpp"
#include "plyimpact/analysis/plate_analyses/modal_analysis.hpp"
#include "plyimpact/analysis/plate_analyses/nonlinear_static.hpp"
#include "plyimpact/fem/dof_map.hpp"
#include "plyimpact/fem/element_loop.hpp"
#include "plyimpact/fem/mechanical_model.hpp"

#include <fmt/format.h>

#include <cmath>
#include <memory>
#include <optional>
#include <stdexcept>
#include <utility>

namespace plyimpact {

namespace {

/// The largest Δt accepted, as a fraction of the undamaged plate's stable step 2/ω_max (CD5).
constexpr double stable_step_fraction = 0.9;

/// `m` where it is a diagonal mass with every DOF carrying mass; throws otherwise.
Eigen::VectorXd diagonal_mass(const Eigen::VectorXd& m, const std::string& key) {
  if (m.size() == 0 || !(m.minCoeff() > 0.0))
    throw std::invalid_argument(fmt::format(
        "{} needs a diagonal mass with every DOF carrying mass: set [mesh] mass = \"lumped\"; a laminate "
        "that is not symmetric couples its lumped mass (I1 != 0), use integration = \"lagged\" for it",
        key));
  return m;
}

/// The lumped mass as a diagonal; throws where M is not diagonal or a DOF carries no mass.
Eigen::VectorXd diagonal_mass(const MassOperator& M, const std::string& key) {
  return diagonal_mass(M.diagonal(), key);
}

class CentralDifferencePolicy;

class CentralDifferenceStepper final : public ModelStepper {
public:
  CentralDifferenceStepper(const CentralDifferencePolicy& policy, const Impactor& impactor);
  ContactSolution advance(long step, double t, const PlateState& s, const CondensedContact& contact,
                          Eigen::VectorXd& u_next) override;
  void next_acceleration(const NewmarkCoefficients& /*nc*/, const PlateState& /*s*/,
                         const Eigen::VectorXd& /*u_next*/, Eigen::VectorXd& a_next) const override {
    a_next = a_next_; // CD3: from the equation of motion, not from Newmark's (2.11)
  }

private:
  /// CD6: throws NewtonFailure, naming the step to use, where the contact spring of the step's secant
  /// stiffness on the mass 1/`contact_flexibility_` makes Δt unstable.
  void check_contact(long step, double t, const ContactSolution& cs, const CondensedContact& contact) const;

  const CentralDifferencePolicy& p_;
  Eigen::VectorXd a_next_;
  Eigen::VectorXd force_;            ///< Fc s_load − f_int of the step (CD3), sized once
  double contact_flexibility_ = 0.0; ///< sᵀM⁻¹s, 1 / the mass the contact spring moves [1/kg]
  NewtonStatistics no_iterations_;   ///< no solve and no factorization: all zero
};

/// Refuses, naming `key` (the deck key that chose central differences), a mass that is not diagonal with
/// mass on every DOF, γ ≠ ½, and Δt above the stable step (CD5), ω_max of the model's initial stiffness
/// unless the options give it (the case computed it for dt = "auto").
class CentralDifferencePolicy final : public ModelPolicy {
public:
  CentralDifferencePolicy(std::unique_ptr<const MechanicalModel> model, const StepPolicyOptions& options,
                          std::string key)
      : CentralDifferencePolicy(policy_mass(*model, options, key), std::move(model), options,
                                std::move(key)) {}

  [[nodiscard]] std::unique_ptr<PlateStepper> start(const Impactor& impactor,
                                                    bool /*contact_point_suffices*/) const override {
    return std::make_unique<CentralDifferenceStepper>(*this, impactor);
  }
  [[nodiscard]] double dt() const { return options_.newmark.dt; }

  std::string key_;
  std::shared_ptr<const ScaledMass> mass_; ///< M_'s diagonal, and what scaling added to it
  Eigen::VectorXd inverse_mass_;           ///< of M_'s diagonal part (M_ itself where it has no blocks)
  double omega_max_;

private:
  /// The case's mass where it built one, else the model's own.
  static std::shared_ptr<const ScaledMass>
  policy_mass(const MechanicalModel& model, const StepPolicyOptions& options, const std::string& key) {
    if (options.explicit_mass) return options.explicit_mass;
    return std::make_shared<const ScaledMass>(explicit_mass(model, key, MassScaling{}));
  }

  CentralDifferencePolicy(std::shared_ptr<const ScaledMass> mass,
                          std::unique_ptr<const MechanicalModel>&& model, const StepPolicyOptions& options,
                          std::string key)
      : ModelPolicy(std::move(model), options, mass_operator(*mass)), key_(std::move(key)),
        mass_(std::move(mass)), inverse_mass_(diagonal_mass(mass_->mass, key_).cwiseInverse()),
        omega_max_(options.explicit_omega_max ? *options.explicit_omega_max
                                              : explicit_highest_mode(*model_, *mass_).omega_max) {
    if (options.newmark.gamma != 0.5)
      throw std::invalid_argument(fmt::format(
          "{} is central differences (gamma = 0.5), got [time] gamma = {}", key_, options.newmark.gamma));
    const double largest = stable_time_step(omega_max_);
    if (dt() > largest)
      throw std::invalid_argument(fmt::format(
          "{}: time.dt = {:.4g} s is above the stable step of this plate and mesh: set time.dt <= {:.4g} s, "
          "or dt = \"auto\" ({} x 2/omega_max, omega_max = {:.4g} rad/s; finer elements lower it)",
          key_, dt(), largest, stable_step_fraction, omega_max_));
  }

  /// The mass the time loop's energies use: diagonal, or with selective scaling the sparse diag + coupling.
  static MassOperator mass_operator(const ScaledMass& mass) {
    if (mass.blocks) return {mass.matrix(), 0.0};
    return MassOperator(mass.mass);
  }
};

/// x = M⁻¹ r of the policy's mass (CD3).
void apply_inverse_mass(const CentralDifferencePolicy& p, const Eigen::VectorXd& r, Eigen::VectorXd& x) {
  if (p.mass_->blocks)
    p.mass_->blocks->solve(r, x);
  else
    parallel_cwise_product(p.inverse_mass_, r, x);
}

/// u_next = u + Δt v + ½Δt² a (CD1), blocks of entries on the element-loop threads.
void predict_displacement(double dt, const PlateState& s, Eigen::VectorXd& u_next) {
  u_next.resize(s.u.size());
  elementwise_on_threads(s.u.size(), [&](Eigen::Index first, Eigen::Index last) {
    const Eigen::Index n = last - first;
    u_next.segment(first, n) =
        s.u.segment(first, n) + dt * s.v.segment(first, n) + (0.5 * dt * dt) * s.a.segment(first, n);
  });
}

/// sᵀM⁻¹s: 1 / the mass the contact spring moves at the impact point [1/kg].
double contact_flexibility(const CentralDifferencePolicy& p, const Eigen::VectorXd& s) {
  Eigen::VectorXd x(s.size());
  apply_inverse_mass(p, s, x);
  return s.dot(x);
}

CentralDifferenceStepper::CentralDifferenceStepper(const CentralDifferencePolicy& policy,
                                                   const Impactor& impactor)
    : ModelStepper(policy, impactor), p_(policy), a_next_(Eigen::VectorXd::Zero(policy.equations())),
      force_(Eigen::VectorXd::Zero(policy.equations())),
      contact_flexibility_(contact_flexibility(policy, loading_.sampler())) {
  const bool scaled = policy.mass_->report.kind != MassScalingKind::none;
  set_facts({.results = &state_->results(),
             .statistics = &no_iterations_,
             .scaled_mass = scaled ? policy.mass_.get() : nullptr});
}

ContactSolution CentralDifferenceStepper::advance(long step, double t, const PlateState& s,
                                                  const CondensedContact& contact, Eigen::VectorXd& u_next) {
  const double dt = p_.dt();
  predict_displacement(dt, s, u_next);                                           // CD1
  const ContactSolution cs = contact.solve(loading_.sampler().dot(u_next), 0.0); // CD2
  check_contact(step, t, cs, contact);                                           // CD6
  state_->internal_force(u_next, dt, f_int_);
  if (!state_->admit(u_next)) state_->internal_force(u_next, dt, f_int_); // with what joined at u_{n+1}
  loading_.scaled_load_minus(cs.alpha, cs.force, f_int_, force_);
  apply_inverse_mass(p_, force_, a_next_); // CD3
  if (!std::isfinite(a_next_.squaredNorm()))
    // not only a step too long: with dt = "auto" the step is the model's stable one, and a value far out of
    // scale (penalty_stiffness = 1e300 was told to "reduce time.dt", issue 77) overflows first
    throw NewtonFailure(
        fmt::format("{}: non-finite acceleration in step {} (t = {:.6g} s): a value of the deck "
                    "far out of scale (a penalty stiffness, a modulus, a density: see its "
                    "plausibility warnings) or a fixed time.dt above the stable step; check "
                    "the values, or give a shorter time.dt",
                    p_.key_, step, t));
  return cs;
}

void CentralDifferenceStepper::check_contact(long step, double t, const ContactSolution& cs,
                                             const CondensedContact& contact) const {
  const double d_alpha = cs.alpha - contact.previous_indentation();
  if (cs.force <= 0.0 || contact.previous_force() <= 0.0 || d_alpha == 0.0) return;
  const double k_secant = std::abs((cs.force - contact.previous_force()) / d_alpha);
  const double omega2 = p_.omega_max_ * p_.omega_max_ + k_secant * contact_flexibility_; // CD6
  if (p_.dt() * std::sqrt(omega2) <= 2.0) return;
  throw NewtonFailure(fmt::format(
      "{}: in step {} (t = {:.6g} s) the contact spring (secant stiffness {:.4g} N/m on the impact point's "
      "lumped mass) makes time.dt = {:.4g} s unstable: set time.dt <= {:.4g} s",
      p_.key_, step, t, k_secant, p_.dt(), stable_time_step(std::sqrt(omega2))));
}

} // namespace

double stable_time_step(double omega_max) {
  return stable_step_fraction * 2.0 / omega_max;
}

ScaledMass explicit_mass(const MechanicalModel& model, const std::string& key, const MassScaling& scaling) {
  const Eigen::VectorXd m = diagonal_mass(integrator_mass(model), key);
  if (scaling.kind == MassScalingKind::none) {
    ScaledMass unscaled;
    unscaled.mass = m;
    return unscaled;
  }
  return scaled_mass(model.initial_stiffness(), m, model.places(), model.contact_plate().mesh().node_count(),
                     scaling, model.interface_stiffness());
}

StableStepSource explicit_highest_mode(const MechanicalModel& model, const ScaledMass& mass) {
  const HighestMode mode = mass.blocks ? highest_mode(model.initial_stiffness(), *mass.blocks)
                                       : highest_mode(model.initial_stiffness(), mass.mass);
  StableStepSource source;
  source.omega_max = mode.omega;
  source.place = model.place_of(mode.equation);
  source.xy = model.contact_plate().mesh().node(source.place.node);
  return source;
}

std::string stable_step_place_text(const StableStepSource& source, bool stacked) {
  return fmt::format("{}{} at ({:.4g}, {:.4g}) mm", dof_name(source.place.dof),
                     stacked ? fmt::format(" of sub-laminate {}", source.place.sublaminate + 1) : "",
                     1e3 * source.xy.x(), 1e3 * source.xy.y());
}

std::unique_ptr<StepPolicy> central_difference_step_policy(std::unique_ptr<const MechanicalModel> model,
                                                           const StepPolicyOptions& options,
                                                           std::string key) {
  return std::make_unique<CentralDifferencePolicy>(std::move(model), options, std::move(key));
}

} // namespace plyimpact
