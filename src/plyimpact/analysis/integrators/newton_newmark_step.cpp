// Newton–Newmark for any plate model of fem/mechanical_model.hpp, written once: the von Kármán plate
// (SPEC §8), the plate whose plies crack (docs/progressive_damage.md), the stacked plate whose interfaces
// delaminate (docs/delamination.md), and their compositions.
//
// A step is the iteration on (u, Fc) of contact_iteration.hpp, f_int the model's trial force from its
// committed state and K̄ = K + c0 M, K the model's iteration matrix (the tangent K_T of the von Kármán
// plate, the secant of the damage of the last trial): plate and contact are solved together.
//
// K̄ of the virgin undeformed model is factored once per case and shared by its runs until a run refreshes
// it (modified Newton) where it pays:
// - within a step, when the iterations slow down (contraction ratio above `refresh_ratio`, or more than
//   `refresh_after` solves); where the matrix is that of the last trial (held damage) the refresh waits
//   for the trial at the next iterate, and a trial that changed a law's branch (a crack opened or closed)
//   refreshes it at once (semi-smooth Newton on the modes);
// - before a step, when the model says its state has drifted from the factored one (damage grown beyond
//   its tolerance), or, with `refresh_interval`, at most every that many steps after a step that needed
//   more than one solve.
// A run's own factor is a Cholesky one, updated instead of made anew where the model gives the change as a
// low-rank one (the lagged stack's interface points, DL8), or a sparse LU where the model's matrix is
// unsymmetric (interfaces softening under mixed mode with their damage iterated). Where the settings ask
// (the stack, whose law is only piecewise smooth: points start or stop softening, faces open or close, and
// full corrections can cycle between its pieces) a correction with a run's own factor that did not lower
// the residual by the fraction `sufficient_decrease` is halved, up to `max_halvings` times (the last is
// kept; an exact two-cycle, equal residuals at both ends, was measured after separation). The elastic
// factor's corrections are short (it is stiffer than the tangent) and are not halved.
// A step is accepted when the residual and the correction are small and the model admits the iterate
// (an element its trial left out has not reached a failure surface there). At small Δt, c0 M dominates
// K̄ and one factorization typically serves the whole event.
#include "plyimpact/analysis/contact/contact_iteration.hpp"
#include "plyimpact/analysis/impact/guards.hpp"
#include "plyimpact/analysis/integrators/model_stepper.hpp"
#include "plyimpact/analysis/integrators/step_policy.hpp"
#include "plyimpact/analysis/plate_analyses/nonlinear_static.hpp"
#include "plyimpact/fem/mechanical_model.hpp"

#include <Eigen/SparseLU>
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
  ContactSolution advance(long step, double t, const PlateState& s, const CondensedContact& contact,
                          Eigen::VectorXd& u_next) override;

private:
  class StepProblem;
  /// Which factor of K̄ the run solves with.
  enum class Factor { shared, cholesky, lu };
  /// A new K̄ at `at`: the factor's update where the model gives the change (DL8), else a new factor.
  void refactor(const Eigen::VectorXd& at);
  /// The model's low-rank change applied to the run's Cholesky factor; false where there is none or the
  /// modified matrix is not positive definite (the factor is then made anew).
  bool update_factor(const Eigen::VectorXd& at);
  /// The contact loading's responses K̄⁻¹ s with the factor in use, once it has changed.
  void use_factor(Factor factor);
  /// x = K̄⁻¹ b with the factor in use, into x (sized once), without allocating where it is a Cholesky
  /// one.
  void solve(const Eigen::VectorXd& b, Eigen::VectorXd& x);
  /// The refreshes due before step `step` from uₙ = `u`.
  void refresh_before(long step, const Eigen::VectorXd& u);
  /// The part of the two-point trapezoidal step (DL7) fixed by its start u_n, f(u_n) − Fc_n s_n, into
  /// start_.
  void step_start(const Eigen::VectorXd& u_n, const CondensedContact& contact);

  const NewtonNewmarkPolicy& p_;
  Factor in_use_ = Factor::shared;
  SpdSolver factor_;                 ///< the run's own Cholesky factor (the policy's analysis adopted)
  Eigen::SparseLU<SparseMatrix> lu_; ///< … or LU, for an unsymmetric matrix
  SpdSolver::Workspace workspace_;
  Eigen::VectorXd kbar_diagonal_;         // f_int_ holds with the two-point form f'(u) + f(u_n) − Fc_n s_n
  Eigen::VectorXd start_, previous_load_; ///< the two-point form's start terms
  const bool two_point_;                  ///< the steps are solved in the trapezoid's two-point form
  IterationMatrixFacts matrix_;           ///< what the iteration matrix of the run's trials is
  NewtonControl control_; ///< the settings' control, deferring refreshes where the model's trials give them
  long last_refresh_ = 0;
  bool needed_more_than_one_solve_ = false;
  NewtonStatistics stats_;
  ContactIteration iteration_; ///< a step allocates nothing but where it refactors
  Eigen::VectorXd u_start_;    ///< where the last correction started (the halving line search)
};

class NewtonNewmarkPolicy final : public ModelPolicy {
public:
  NewtonNewmarkPolicy(std::unique_ptr<const MechanicalModel> model, const StepPolicyOptions& options,
                      NewtonSettings settings, bool hold_laws)
      : ModelPolicy(std::move(model), options), settings_(std::move(settings)),
        initial_(options.solver, options.ordering) {
    const std::unique_ptr<ModelState> virgin = model_->virgin_state();
    trials_ = law_trials(hold_laws);
    virgin->set_law_trials(trials_);
    const SparseMatrix Kbar = iteration_kbar(*virgin, Eigen::VectorXd::Zero(model_->size()));
    if (options.memory_limit_bytes)
      check_factor_memory(estimate_factor_memory(initial_, Kbar), *options.memory_limit_bytes);
    initial_.factorize(Kbar);
    initial_diagonal_ = Kbar.diagonal();
  }

  [[nodiscard]] std::unique_ptr<PlateStepper> start(const Impactor& impactor,
                                                    bool /*contact_point_suffices*/) const override {
    return std::make_unique<NewtonNewmarkStepper>(*this, impactor);
  }
  /// K̄ = K + c0 M at u, K the iteration matrix of `state`.
  [[nodiscard]] SparseMatrix iteration_kbar(const ModelState& state, const Eigen::VectorXd& u) const {
    return state.iteration_matrix(u) + options_.newmark.c0 * M_.matrix();
  }

  /// Held laws give the end forces of the trapezoid's two-point form (DL7) where the model has one and
  /// the Newmark parameters are the trapezoid's (β = ¼, γ = ½).
  [[nodiscard]] LawTrials law_trials(bool hold_laws) const {
    if (!hold_laws) return LawTrials::advance;
    const NewmarkCoefficients& nc = options_.newmark;
    return model_->two_point_form() && nc.beta == 0.25 && nc.gamma == 0.5 ? LawTrials::hold_step_mean
                                                                          : LawTrials::hold;
  }

  NewtonSettings settings_;
  LawTrials trials_ = LawTrials::advance; ///< what the runs' trials do with the laws
  SpdSolver initial_;                     ///< K̄ of the virgin undeformed model, shared by the runs
  Eigen::VectorXd initial_diagonal_;      ///< its diagonal
};

NewtonNewmarkStepper::NewtonNewmarkStepper(const NewtonNewmarkPolicy& policy, const Impactor& impactor)
    : ModelStepper(policy, impactor), p_(policy), factor_(policy.options_.solver, policy.options_.ordering),
      kbar_diagonal_(policy.initial_diagonal_), start_(Eigen::VectorXd::Zero(policy.equations())),
      previous_load_(Eigen::VectorXd::Zero(policy.equations())),
      two_point_(policy.trials_ == LawTrials::hold_step_mean), iteration_(policy.equations()) {
  factor_.adopt_analysis_of(policy.initial_);
  matrix_ = state_->set_law_trials(policy.trials_);
  control_ = policy.settings_.control;
  control_.defer_refresh = matrix_.refresh_at_next_trial;
  use_factor(Factor::shared);
  stats_.factorizations = 1; // the shared factor
  set_facts({.results = &state_->results(), .statistics = &stats_});
  if (policy.settings_.max_halvings > 0) u_start_.resize(policy.equations());
}

void NewtonNewmarkStepper::use_factor(Factor factor) {
  in_use_ = factor;
  loading_.set_solver([this](const Eigen::VectorXd& b) {
    Eigen::VectorXd x(b.size());
    solve(b, x);
    return x;
  });
}

void NewtonNewmarkStepper::solve(const Eigen::VectorXd& b, Eigen::VectorXd& x) {
  switch (in_use_) {
  case Factor::shared:
    p_.initial_.solve(b, x, workspace_);
    return;
  case Factor::cholesky:
    factor_.solve(b, x, workspace_);
    return;
  case Factor::lu:
    x = lu_.solve(b);
    return;
  }
}

void NewtonNewmarkStepper::refactor(const Eigen::VectorXd& at) {
  if (in_use_ == Factor::cholesky && p_.settings_.update_factor && update_factor(at)) return;
  const SparseMatrix Kbar = p_.iteration_kbar(*state_, at);
  Factor factor = Factor::cholesky;
  if (matrix_.symmetric) {
    factor_.factorize(Kbar);
  } else {
    lu_.compute(Kbar);
    if (lu_.info() != Eigen::Success)
      throw NewtonFailure(
          fmt::format("{}: the iteration matrix is singular; {}", p_.settings_.physics, p_.settings_.advice));
    factor = Factor::lu;
  }
  kbar_diagonal_ = Kbar.diagonal();
  state_->matrix_in_factor(at, FactorChange::factorized);
  use_factor(factor);
  ++stats_.factorizations;
}

bool NewtonNewmarkStepper::update_factor(const Eigen::VectorXd& at) {
  const std::optional<LowRankChange> change = state_->matrix_change(at);
  if (!change) return false;
  if (change->rank() == 0) return true; // the factor holds the matrix already
  // The update first: the matrix stays positive definite in between.
  if ((change->up.cols() > 0 && !factor_.modify(change->up, true)) ||
      (change->down.cols() > 0 && !factor_.modify(change->down, false)))
    return false;
  state_->matrix_in_factor(at, FactorChange::updated);
  kbar_diagonal_ += change->up.cwiseProduct(change->up) * Eigen::VectorXd::Ones(change->up.cols()) -
                    change->down.cwiseProduct(change->down) * Eigen::VectorXd::Ones(change->down.cols());
  use_factor(Factor::cholesky); // the responses recomputed
  ++stats_.factor_updates;
  return true;
}

void NewtonNewmarkStepper::refresh_before(long step, const Eigen::VectorXd& u) {
  const NewtonSettings& ns = p_.settings_;
  if (state_->drift_since_factorization() > ns.refactor_tolerance) {
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
void NewtonNewmarkStepper::step_start(const Eigen::VectorXd& u_n, const CondensedContact& contact) {
  state_->start_force(u_n, start_);
  if (contact.previous_force() != 0.0) {
    loading_.scaled_load(contact.previous_indentation(), contact.previous_force(), previous_load_);
    start_ -= previous_load_;
  }
}

/// One step's Newton problem on (u, Fc) (the module comment): the iterate u_k of the contact iteration,
/// the model's trial at it, the correction with the stepper's factor and the contact solved inside it.
class NewtonNewmarkStepper::StepProblem final : public NewtonProblem {
public:
  StepProblem(NewtonNewmarkStepper& stepper, const PlateState& s, const CondensedContact& contact)
      : p_(stepper), s_(s), contact_(contact) {
    p_.iteration_.predict(s, stepper.p_.options_.newmark); // constant acceleration: a_{n+1} = aₙ
    if (p_.two_point_) p_.step_start(s.u, contact);
  }
  Trial trial(int corrections) override {
    const NewtonSettings& ns = p_.p_.settings_;
    for (;;) {
      evaluate();
      if (corrections == 0) return not_converged();
      if (p_.iteration_.converged(p_.loading_, cs_, p_.f_int_, p_.kbar_diagonal_, ns.residual_tolerance,
                                  ns.displacement_tolerance)) {
        if (p_.state_->admit(p_.iteration_.uk())) return Trial::converged;
        continue; // an element joined the model at the iterate: evaluate again with it
      }
      if (!halve()) return not_converged();
    }
  }
  void refactor() override { p_.refactor(p_.iteration_.uk()); }
  double correct() override {
    if (p_.p_.settings_.max_halvings > 0) {
      halvings_ = 0;
      p_.u_start_ = p_.iteration_.uk();
      cs_start_ = cs_;
    }
    const double correction = p_.iteration_.correct(
        [this](const Eigen::VectorXd& g, Eigen::VectorXd& x) { p_.solve(g, x); }, p_.loading_, contact_, cs_);
    return std::isfinite(cs_.force) ? correction : NAN;
  }
  [[nodiscard]] const ContactSolution& contact_solution() const { return cs_; }

private:
  /// Not converged, and whether the trial changed a law's branch.
  Trial not_converged() { return p_.state_->take_branch_changed() ? Trial::branch_changed : Trial::iterate; }
  /// The model's trial force at the iterate (with the two-point form's start terms) and the step's inertia.
  void evaluate() {
    const NewmarkCoefficients& nc = p_.p_.options_.newmark;
    ContactIteration& it = p_.iteration_;
    it.step_inertia(s_, nc, p_.p_.M_, p_.two_point_);
    p_.state_->internal_force(it.uk(), nc.dt, p_.f_int_);
    if (p_.two_point_) p_.f_int_ += p_.start_;
    it.set_internal_force(p_.f_int_);
  }
  /// Backtracking (the module comment): halves the last correction, with the run's own factor, where it
  /// did not lower the residual enough; false where it is kept.
  bool halve() {
    constexpr double sufficient_decrease = 1e-4;
    const double residual = p_.iteration_.residual_norm();
    if (residual > (1.0 - sufficient_decrease) * start_residual_ && p_.in_use_ != Factor::shared &&
        halvings_ < p_.p_.settings_.max_halvings) {
      p_.iteration_.uk() = 0.5 * (p_.u_start_ + p_.iteration_.uk());
      cs_.force = 0.5 * (cs_start_.force + cs_.force);
      cs_.alpha = 0.5 * (cs_start_.alpha + cs_.alpha);
      ++halvings_;
      return true;
    }
    start_residual_ = residual;
    return false;
  }

  NewtonNewmarkStepper& p_;
  const PlateState& s_;
  const CondensedContact& contact_;
  ContactSolution cs_, cs_start_; ///< cs_start_: where the last correction started, with u_start_
  double start_residual_ = INFINITY;
  int halvings_ = 0; ///< of the last correction
};

ContactSolution NewtonNewmarkStepper::advance(long step, double t, const PlateState& s,
                                              const CondensedContact& contact, Eigen::VectorXd& u_next) {
  refresh_before(step, s.u);
  StepProblem problem(*this, s, contact);
  const NewtonSettings& ns = p_.settings_;
  const NewtonOutcome o = solve_newton(problem, control_);
  if (!o.converged)
    throw NewtonFailure(
        fmt::format("{}: {} in step {} (t = {:.6g} s); {}", ns.physics, o.why, step, t, ns.advice));
  needed_more_than_one_solve_ = o.corrections > 1;
  stats_.iterations += o.corrections;
  stats_.max_iterations_per_step = std::max(stats_.max_iterations_per_step, o.corrections);
  u_next.swap(iteration_.uk());
  return problem.contact_solution();
}

} // namespace

std::unique_ptr<StepPolicy> newton_newmark_step_policy(std::unique_ptr<const MechanicalModel> model,
                                                       const StepPolicyOptions& options,
                                                       NewtonSettings settings, bool hold_laws) {
  return std::make_unique<NewtonNewmarkPolicy>(std::move(model), options, std::move(settings), hold_laws);
}

} // namespace plyimpact
