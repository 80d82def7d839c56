// Newton–Newmark for any plate model of fem/mechanical_model.hpp, written once: the von Kármán plate
// (SPEC §8), the plate whose plies crack (docs/progressive_damage.md) and their composition.
//
// Step n → n+1, unknowns u (plate) and Fc. With a = c0 (u − uₙ) − c2 vₙ − c3 aₙ, the plate residual is
//   r(u, Fc) = Fc s − M a(u) − f_int(u) = 0,   and the contact law Fc = F(α), α = wᵢ(Fc) − sᵀu,
// f_int the model's trial force from its committed state. Each iteration linearizes the plate with
// K̄ = K + c0 M, K the model's iteration matrix (the tangent K_T of the von Kármán plate, the secant of the
// damage of the last trial): u' = û + Fc t, û = u + K̄⁻¹ g(u), g = −M a(u) − f_int(u), t = K̄⁻¹ s, so sᵀu'
// is affine in Fc and the contact law is solved exactly inside every iteration (SPEC §4): plate and
// contact are solved together.
//
// K̄ is factored at the start of a run and refreshed (modified Newton) only where it pays:
// - within a step, when the iterations slow down (contraction ratio above `refresh_ratio`, or more than
//   `refresh_after` solves); where the matrix is that of the last trial (lagged damage) the refresh waits
//   for the trial at the next iterate, and a trial that changed a law's branch (a crack opened or closed)
//   refreshes it at once (semi-smooth Newton on the modes);
// - before a step, when the model says its state has drifted from the factored one (damage grown beyond
//   its tolerance), or, with `refresh_interval`, at most every that many steps after a step that needed
//   more than one solve.
// A step is accepted when the residual and the correction are small and the model admits the iterate
// (an element its trial left out has not reached a failure surface there). At small Δt, c0 M dominates
// K̄ and one factorization typically serves the whole event.
#include "plyimpact/analysis/contact_iteration.hpp"
#include "plyimpact/analysis/guards.hpp"
#include "plyimpact/analysis/model_stepper.hpp"
#include "plyimpact/analysis/newton_solver.hpp"
#include "plyimpact/analysis/nonlinear_static.hpp"
#include "plyimpact/analysis/step_policy.hpp"
#include "plyimpact/fem/mechanical_model.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <utility>

namespace plyimpact {

namespace {

class NewtonNewmarkPolicy;

class NewtonNewmarkStepper final : public ModelStepper {
public:
  NewtonNewmarkStepper(const NewtonNewmarkPolicy& policy, const Impactor& impactor);
  ContactSolution advance(long step, double t, const PlateState& s, const ContactStep& contact,
                          Eigen::VectorXd& u_next) override;
  [[nodiscard]] double kinetic_energy(const PlateState& s) const override;
  [[nodiscard]] std::optional<NewtonStatistics> statistics() const override { return stats_; }

private:
  class StepProblem;
  void refactor(const Eigen::VectorXd& at);
  /// The refreshes due before step `step` from uₙ = `u`.
  void refresh_before(long step, const Eigen::VectorXd& u);
  [[noreturn]] void fail(const char* what, long step, double t) const;
  /// The part of the two-point trapezoidal step (DL7) fixed by its start u_n, f(u_n) − Fc_n s_n, into
  /// start_.
  void step_start(const Eigen::VectorXd& u_n, const ContactStep& contact);

  const NewtonNewmarkPolicy& p_;
  SpdSolver factor_;
  SpdSolver::Workspace workspace_;
  Eigen::VectorXd kbar_diagonal_;         // f_int_ holds with the two-point form f'(u) + f(u_n) − Fc_n s_n
  Eigen::VectorXd start_, previous_load_; ///< the two-point form's start terms
  long last_refresh_ = 0;
  bool needed_more_than_one_solve_ = false;
  NewtonStatistics stats_;
  ContactIteration iteration_;      ///< a step allocates nothing but where it refactors
  mutable Eigen::VectorXd scratch_; ///< M v of the kinetic energy
};

class NewtonNewmarkPolicy final : public StepPolicy {
public:
  NewtonNewmarkPolicy(std::unique_ptr<const MechanicalModel> model, const StepPolicyOptions& options,
                      NewtonSettings settings)
      : model_(std::move(model)), options_(options),
        settings_(std::move(settings)), control_{settings_.max_iterations, settings_.refresh_ratio,
                                                 settings_.refresh_after},
        M_(model_->mass(), 1e-14) {}

  [[nodiscard]] int equations() const override { return model_->size(); }
  [[nodiscard]] bool inplane_eliminated() const override { return model_->inplane_eliminated(); }
  [[nodiscard]] std::unique_ptr<PlateStepper> start(const Impactor& impactor) const override {
    return std::make_unique<NewtonNewmarkStepper>(*this, impactor);
  }
  [[nodiscard]] std::vector<std::string> warnings() const override { return model_->warnings(); }

  std::unique_ptr<const MechanicalModel> model_;
  StepPolicyOptions options_;
  NewtonSettings settings_;
  NewtonControl control_; ///< of settings_
  /// The lumped mass is diagonal when I1 = 0; a symmetric layup gives I1 at round-off level (~1e-20),
  /// whose u–θ entries are dropped rather than turning every M·x into a sparse product.
  MassOperator M_;
};

NewtonNewmarkStepper::NewtonNewmarkStepper(const NewtonNewmarkPolicy& policy, const Impactor& impactor)
    : ModelStepper(*policy.model_, policy.options_, impactor), p_(policy),
      factor_(policy.options_.solver, policy.options_.ordering),
      start_(Eigen::VectorXd::Zero(policy.equations())),
      previous_load_(Eigen::VectorXd::Zero(policy.equations())), iteration_(policy.equations()),
      scratch_(policy.equations()) {
  const Eigen::VectorXd at_rest = Eigen::VectorXd::Zero(policy.equations());
  if (policy.options_.memory_limit_bytes) // from the analysis that refactor() then reuses
    check_factor_memory(estimate_factor_memory(factor_, state_->iteration_matrix(at_rest) +
                                                            p_.options_.newmark.c0 * p_.M_.matrix()),
                        *policy.options_.memory_limit_bytes);
  refactor(at_rest);
}

void NewtonNewmarkStepper::refactor(const Eigen::VectorXd& at) {
  const SparseMatrix Kbar = state_->iteration_matrix(at) + p_.options_.newmark.c0 * p_.M_.matrix();
  factor_.factorize(Kbar);
  kbar_diagonal_ = Kbar.diagonal();
  loading_.set_solver([this](const Eigen::VectorXd& b) { return factor_.solve(b); });
  state_->matrix_factorized();
  ++stats_.factorizations;
}

void NewtonNewmarkStepper::refresh_before(long step, const Eigen::VectorXd& u) {
  const NewtonSettings& ns = p_.settings_;
  if (state_->matrix_outdated()) {
    refactor(u);
    return;
  }
  if (ns.refresh_interval && needed_more_than_one_solve_ && step - last_refresh_ >= *ns.refresh_interval) {
    refactor(u);
    last_refresh_ = step;
  }
}

// The trapezoidal rule over the step in its two-point form, (u − u_n)/Δt = (v_n + v)/2 and
// M (v − v_n)/Δt = the mean of the step's forces, is
//   Fc s + Fc_n s_n − c0 M (u − u_n − Δt v_n) − f'(u) − f(u_n) = 0,                          (DL7)
// f' the model's end forces and f(u_n) its start force, the laws held at the committed state: where the
// held model is linear the mean of the step's forces is then exact and the step keeps the energy, also
// where faces open or close within it. aₙ does not enter (where the laws moved at the commit, the Newmark
// accelerations are not the equilibrium ones).
void NewtonNewmarkStepper::step_start(const Eigen::VectorXd& u_n, const ContactStep& contact) {
  state_->start_force(u_n, start_);
  if (contact.previous_force() != 0.0) {
    loading_.scaled_load(contact.previous_indentation(), contact.previous_force(), previous_load_);
    start_ -= previous_load_;
  }
}

void NewtonNewmarkStepper::fail(const char* what, long step, double t) const {
  const NewtonSettings& ns = p_.settings_;
  throw NewtonFailure(
      fmt::format("{}: {} in step {} (t = {:.6g} s); {}", ns.physics, what, step, t, ns.advice));
}

/// One step's Newton problem on (u, Fc) (the module comment): the iterate u_k of the contact iteration,
/// the model's trial at it, the correction with the stepper's factor and the contact solved inside it.
class NewtonNewmarkStepper::StepProblem final : public NewtonProblem {
public:
  StepProblem(NewtonNewmarkStepper& stepper, const PlateState& s, const ContactStep& contact)
      : p_(stepper), s_(s), contact_(contact),
        two_point_(stepper.state_->two_point_form() && stepper.p_.options_.newmark.beta == 0.25 &&
                   stepper.p_.options_.newmark.gamma == 0.5) {
    p_.iteration_.predict(s, stepper.p_.options_.newmark); // constant acceleration: a_{n+1} = aₙ
    if (two_point_) p_.step_start(s.u, contact);
  }
  Trial trial(int corrections) override {
    const NewmarkCoefficients& nc = p_.p_.options_.newmark;
    ContactIteration& it = p_.iteration_;
    it.step_inertia(s_, nc, p_.p_.M_, two_point_);
    p_.state_->internal_force(it.uk(), nc.dt, p_.f_int_);
    if (two_point_) p_.f_int_ += p_.start_;
    it.set_internal_force(p_.f_int_);
    const NewtonSettings& ns = p_.p_.settings_;
    return corrections > 0 && it.converged(p_.loading_, cs_, p_.f_int_, p_.kbar_diagonal_,
                                           ns.residual_tolerance, ns.displacement_tolerance)
               ? Trial::converged
               : Trial::iterate;
  }
  bool admit() override { return p_.state_->admit(p_.iteration_.uk()); }
  void refactor() override { p_.refactor(p_.iteration_.uk()); }
  double correct() override {
    const double correction = p_.iteration_.correct(
        [this](const Eigen::VectorXd& g, Eigen::VectorXd& x) { p_.factor_.solve(g, x, p_.workspace_); },
        p_.loading_, contact_, cs_);
    return std::isfinite(cs_.force) ? correction : NAN;
  }
  bool take_branch_changed() override { return p_.state_->take_branch_changed(); }
  bool defer_refresh() override { return p_.state_->matrix_of_last_trial(); }
  [[nodiscard]] const ContactSolution& contact_solution() const { return cs_; }

private:
  NewtonNewmarkStepper& p_;
  const PlateState& s_;
  const ContactStep& contact_;
  const bool two_point_;
  ContactSolution cs_;
};

ContactSolution NewtonNewmarkStepper::advance(long step, double t, const PlateState& s,
                                              const ContactStep& contact, Eigen::VectorXd& u_next) {
  refresh_before(step, s.u);
  StepProblem problem(*this, s, contact);
  const NewtonOutcome o = solve_newton(problem, p_.control_);
  if (!o.converged) fail(o.why.c_str(), step, t);
  needed_more_than_one_solve_ = o.corrections > 1;
  stats_.iterations += o.corrections;
  stats_.max_iterations_per_step = std::max(stats_.max_iterations_per_step, o.corrections);
  u_next.swap(iteration_.uk());
  return problem.contact_solution();
}

double NewtonNewmarkStepper::kinetic_energy(const PlateState& s) const {
  return p_.M_.kinetic_energy(s.v, scratch_);
}

/// The damage settings' iterations, with the periodic refresh of the large-deflection settings where the
/// plate is also von Kármán's (its tangent moves with u as well as with the damage). Their refresh after
/// `refresh_after` solves is left out: the damage's tighter tolerance takes more solves per step, and
/// with it the plate of examples/damage-progressive.toml refactored in 415 of its 266 steps (13 s)
/// instead of 44 times (2.5 s) with the contraction rule alone.
NewtonSettings damage_newton_settings(const ProgressiveDamageSettings& damage,
                                      const std::optional<NonlinearImpactSettings>& large_deflection) {
  NewtonSettings ns;
  ns.max_iterations = damage.max_iterations;
  ns.residual_tolerance = damage.residual_tolerance;
  ns.displacement_tolerance = damage.displacement_tolerance;
  ns.refresh_ratio = damage.refresh_ratio;
  if (large_deflection) ns.refresh_interval = large_deflection->refresh_interval;
  ns.physics = "progressive damage";
  ns.advice = damage.integration == DamageIntegration::lagged
                  ? "reduce time.dt"
                  : "set [damage] integration = \"lagged\" (no iteration on the damage; its energy balance "
                    "error shrinks with time.dt), or reduce time.dt";
  return ns;
}

} // namespace

std::unique_ptr<StepPolicy> newton_newmark_step_policy(std::unique_ptr<const MechanicalModel> model,
                                                       const StepPolicyOptions& options,
                                                       NewtonSettings settings) {
  return std::make_unique<NewtonNewmarkPolicy>(std::move(model), options, std::move(settings));
}

std::unique_ptr<StepPolicy> newton_step_policy(const PlateModel& model, const StepPolicyOptions& options,
                                               const NonlinearImpactSettings& settings) {
  NewtonSettings ns;
  ns.max_iterations = settings.max_iterations;
  ns.residual_tolerance = settings.residual_tolerance;
  ns.displacement_tolerance = settings.displacement_tolerance;
  ns.refresh_ratio = settings.refresh_ratio;
  ns.refresh_after = settings.refresh_after;
  ns.refresh_interval = settings.refresh_interval;
  ns.physics = "non-linear impact";
  ns.advice = "reduce time.dt";
  return newton_newmark_step_policy(von_karman_plate_model(model, settings.measure), options, std::move(ns));
}

std::unique_ptr<StepPolicy>
damage_step_policy(const PlateModel& model, const StepPolicyOptions& options,
                   const ProgressiveDamageSettings& settings,
                   const std::optional<NonlinearImpactSettings>& large_deflection) {
  const Kinematics kinematics = large_deflection ? Kinematics::von_karman : Kinematics::linear;
  if (large_deflection && large_deflection->measure != StrainMeasure::von_karman)
    throw std::invalid_argument(
        "progressive damage takes the von Kármán strains of a non-linear plate: set strain_measure = "
        "\"von-karman\" (the Green–Lagrange measure is not built for the layered section whose plies crack)");
  if (settings.integration == DamageIntegration::central_difference)
    return explicit_damage_step_policy(model, options, settings, kinematics);
  return newton_newmark_step_policy(damaging_plate_model(model, settings, kinematics), options,
                                    damage_newton_settings(settings, large_deflection));
}

} // namespace plyimpact
