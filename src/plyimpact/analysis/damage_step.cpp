// The damage step policy: the plate whose plies crack (fem/damaged_plate.hpp), implicit Newmark with the
// secant stiffness.
//
// Step n → n+1, unknowns u and Fc. With a = c0 (u − uₙ) − c2 vₙ − c3 aₙ the plate residual is
//   r(u, Fc) = Fc s − M a(u) − f_int(u),  f_int(u) = K_s(d(u)) u,  d(u) from the damage committed at n,
// and the contact law Fc = F(α). Each iteration solves with K̄ = K_s(d*) + c0 M, d* the damage of the last
// factorization: û = u + K̄⁻¹ g(u), g = −M a(u) − f_int(u), then the scalar contact problem exactly as the
// linear policy does (SPEC §4). While no point softens, K̄ is the exact secant of the step and one solve
// gives the answer (the second residual evaluation confirms it). Where damage grows, K̄ is stiffer than
// the secant and the iterations contract; K̄ is refactored (numeric factorization only: the symbolic
// analysis of CHOLMOD is kept) when they slow down, and before a step once the damage has grown by more
// than `refactor_tolerance` since the last factorization. The step is accepted when the residual is
// small and the damage the law returns at u is the damage that produced f_int (same evaluation).
//
// Lagged damage (DamageIntegration::lagged): the same iterations with the damage held at d_n, the value
// committed by the previous step (DamagedPlateModel::frozen_internal_force), the cracks opening or closing
// with the iterate's strain. K̄ is refactored with the iterate's secant where a crack opened or closed
// (semi-smooth Newton on the modes) or the iterations slow down. The law is called once per step, at the
// accepted u_{n+1}, for d_{n+1} and the dissipation.
#include "plyimpact/analysis/contact_iteration.hpp"
#include "plyimpact/analysis/damaged_plate_step.hpp"
#include "plyimpact/analysis/guards.hpp"
#include "plyimpact/analysis/nonlinear_static.hpp"
#include "plyimpact/analysis/step_policy.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace plyimpact {

namespace {

class DamageStepPolicy;

class DamageStepper final : public DamagedPlateStepper {
public:
  DamageStepper(const DamageStepPolicy& policy, const Impactor& impactor);
  ContactSolution advance(long step, double t, const PlateState& s, const ContactStep& contact,
                          Eigen::VectorXd& u_next) override;
  void accept(const PlateState& before, const Eigen::VectorXd& u_next) override;
  [[nodiscard]] double kinetic_energy(const PlateState& s) const override;
  [[nodiscard]] std::optional<NewtonStatistics> statistics() const override { return stats_; }

private:
  void refactor(const SparseMatrix& K);
  [[nodiscard]] bool lagged() const;

  /// f_int at uk into f_int_: the law's trial (implicit) or the damage held at d_n (lagged).
  void evaluate_internal_force(const Eigen::VectorXd& uk);

  const DamageStepPolicy& p_;
  SpdSolver factor_;
  SpdSolver::Workspace workspace_;
  Eigen::VectorXd kbar_diagonal_;
  NewtonStatistics stats_;
  ContactIteration iteration_;      ///< a step allocates nothing but where it refactors
  mutable Eigen::VectorXd scratch_; ///< M v of the kinetic energy
};

class DamageStepPolicy final : public DamagedPlatePolicy {
public:
  DamageStepPolicy(const PlateModel& model, const StepPolicyOptions& options,
                   const ProgressiveDamageSettings& settings)
      : DamagedPlatePolicy(model, options, settings), M_(model.mass(), 1e-14) {}

  [[nodiscard]] std::unique_ptr<PlateStepper> start(const Impactor& impactor) const override {
    return std::make_unique<DamageStepper>(*this, impactor);
  }

  MassOperator M_;
};

bool DamageStepper::lagged() const {
  return p_.plate_.settings().integration == DamageIntegration::lagged;
}

DamageStepper::DamageStepper(const DamageStepPolicy& policy, const Impactor& impactor)
    : DamagedPlateStepper(policy, impactor), p_(policy),
      factor_(policy.options_.solver, policy.options_.ordering), iteration_(policy.equations()),
      scratch_(policy.equations()) {
  const SparseMatrix& K0 = p_.plate_.undamaged_stiffness();
  if (policy.options_.memory_limit_bytes) // from the analysis that refactor() then reuses
    check_factor_memory(estimate_factor_memory(factor_, K0 + p_.options_.newmark.c0 * p_.M_.matrix()),
                        *policy.options_.memory_limit_bytes);
  refactor(K0);
}

void DamageStepper::refactor(const SparseMatrix& K) {
  const SparseMatrix Kbar = K + p_.options_.newmark.c0 * p_.M_.matrix();
  factor_.factorize(Kbar);
  kbar_diagonal_ = Kbar.diagonal();
  loading_.set_solver([this](const Eigen::VectorXd& b) { return factor_.solve(b); });
  field_.mark_factorized();
  ++stats_.factorizations;
}

ContactSolution DamageStepper::advance(long step, double t, const PlateState& s, const ContactStep& contact,
                                       Eigen::VectorXd& u_next) {
  const ProgressiveDamageSettings& ds = p_.plate_.settings();
  const NewmarkCoefficients& nc = p_.options_.newmark;
  if (field_.growth_since_factorization() > ds.refactor_tolerance)
    refactor(
        p_.plate_.secant_stiffness(field_)); // the committed damage's secant (sections of the last trial)
  ContactIteration& it = iteration_;
  it.predict(s, nc);
  ContactSolution cs;
  double previous_correction = INFINITY;
  bool refresh = false;
  int iterations = 0;
  for (;;) {
    it.newmark_inertia(s, nc, p_.M_);
    evaluate_internal_force(it.uk());
    it.set_internal_force(f_int_);
    if (iterations > 0 && it.converged(loading_, cs, f_int_, kbar_diagonal_, ds.residual_tolerance,
                                       ds.displacement_tolerance)) {
      // Equilibrium with the elements evaluated; an element left out that has reached a Hashin
      // surface at u_k joins, and the step iterates on.
      if (lagged() || !p_.plate_.activate_reached(it.uk(), field_)) break;
      continue;
    }
    // Lagged: semi-smooth Newton on the crack modes (the secant at the iterate's modes is the tangent of
    // the frozen-damage problem): refactor where a crack opened or closed, or where the iterations slow.
    if (lagged() && (field_.take_modes_changed() || refresh)) {
      refactor(p_.plate_.secant_stiffness(field_));
      previous_correction = INFINITY;
    }
    refresh = false;
    if (iterations == ds.max_iterations)
      throw NewtonFailure(fmt::format(
          "progressive damage: the iterations did not converge in step {} (t = {:.6g} s) after {} solves; "
          "{}",
          step, t, ds.max_iterations,
          lagged() ? "reduce time.dt"
                   : "set [damage] integration = \"lagged\" (no iteration on the damage; its energy balance "
                     "error shrinks with time.dt), or reduce time.dt"));
    const double correction =
        it.correct([this](const Eigen::VectorXd& g, Eigen::VectorXd& x) { factor_.solve(g, x, workspace_); },
                   loading_, contact, cs);
    ++iterations;
    if (!std::isfinite(correction) || !std::isfinite(cs.force))
      throw NewtonFailure(fmt::format(
          "progressive damage: non-finite state in step {} (t = {:.6g} s); reduce time.dt", step, t));
    const bool slow = iterations > 1 && correction > ds.refresh_ratio * previous_correction;
    previous_correction = correction;
    if (slow && lagged()) {
      refresh = true; // at the next iterate, once its sections are evaluated
    } else if (slow) {
      refactor(p_.plate_.secant_stiffness(field_)); // the secant at the last iterate's damage
      previous_correction = INFINITY;
    }
  }
  stats_.iterations += iterations;
  stats_.max_iterations_per_step = std::max(stats_.max_iterations_per_step, iterations);
  u_next.swap(it.uk());
  return cs;
}

void DamageStepper::accept(const PlateState& /*before*/, const Eigen::VectorXd& u_next) {
  if (!lagged()) {
    p_.plate_.commit(u_next, f_int_, field_);
    return;
  }
  // Lagged damage: the law once at u_{n+1} (elements that reached a surface there join first); its
  // secant sections are those of the next step.
  (void)p_.plate_.activate_reached(u_next, field_);
  p_.plate_.internal_force_into(u_next, p_.options_.newmark.dt, field_, f_int_);
  p_.plate_.commit(u_next, f_int_, field_);
}

void DamageStepper::evaluate_internal_force(const Eigen::VectorXd& uk) {
  if (lagged())
    p_.plate_.frozen_internal_force_into(uk, field_, f_int_);
  else
    p_.plate_.internal_force_into(uk, p_.options_.newmark.dt, field_, f_int_);
}

double DamageStepper::kinetic_energy(const PlateState& s) const {
  return p_.M_.kinetic_energy(s.v, scratch_);
}

} // namespace

std::unique_ptr<StepPolicy> damage_step_policy(const PlateModel& model, const StepPolicyOptions& options,
                                               const ProgressiveDamageSettings& settings) {
  if (settings.integration == DamageIntegration::central_difference)
    return explicit_damage_step_policy(model, options, settings);
  return std::make_unique<DamageStepPolicy>(model, options, settings);
}

} // namespace plyimpact
