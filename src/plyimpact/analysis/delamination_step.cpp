// The delamination step policy (issue 19, docs/delamination.md "Impact on the stacked plate"): the
// laminate cut into sub-laminates tied by cohesive interfaces (fem/stacked_plate.hpp), struck on the top
// sub-laminate.
//
// Step n → n+1, unknowns u (every sub-laminate) and Fc, as in the Newton policy (newton_step.cpp):
//   r(u, Fc) = Fc s − M a(u) − f(u; d) = 0,   f = K_plates u + Σ f_coh(u; d),   Fc = F(α), α = wᵢ − sᵀu,
// with s the contact load on the top sub-laminate. Each iteration solves with an iteration matrix K̄:
// û = u + K̄⁻¹ g(u), g = −M a(u) − f(u), and u' = û + Fc K̄⁻¹ s, so sᵀu' is affine in Fc and the contact
// law is solved exactly inside every iteration.
//
// K̄ is the elastic one, K_plates + K_penalty + c0 M (symmetric positive definite), factored once per
// case and shared by its runs; while every interface point stays elastic the problem is linear and one
// iteration solves the step. Where points soften the iterations slow down (the elastic matrix is far
// stiffer than the softening tangent), and the stepper factors the consistent tangent K_T + c0 M at the
// iterate (unsymmetric under mixed mode: sparse LU) and keeps it for the following steps, until they
// slow down again. K_T + c0 M stays positive only for Δt below the limit (DL5) of
// largest_delamination_time_step, which the policy enforces. (Measured on the §3.6 plate: above it, at
// 1 µs against 0.75 µs, the tangent's corrections were 1e4 m long; the secant (1 − d) K, positive at any
// Δt, contracts the error by only 0.99 per iteration at the onset of softening, where it is 50 times
// stiffer than the tangent.)
// The damage of the interface points is evaluated from the state of the last accepted step and
// committed with the step: iterated with it (implicit), or held at the last accepted step's while the
// step is solved and updated from its converged separation (lagged, the default; the energy the damage
// releases within a step is counted at its end, an error first order in Δt). Under the trapezoidal rule
// (β = ¼, γ = ½) the lagged step is solved in its two-point form, with the interfaces' mean traction
// over the step (CohesiveLaw::step_mean, DL6; DL7 below): with the damage held, the step then keeps the
// energy exactly, also where faces open or close inside it (with the law's end tractions the clapping
// of delaminated faces, held apart by the penalty K, created energy: docs/delamination.md, "The lagged
// step keeps the energy").
#include "plyimpact/analysis/capabilities.hpp"
#include "plyimpact/analysis/contact_iteration.hpp"
#include "plyimpact/analysis/guards.hpp"
#include "plyimpact/analysis/newton_solver.hpp"
#include "plyimpact/analysis/nonlinear_static.hpp"
#include "plyimpact/analysis/stacked_plate_step.hpp"
#include "plyimpact/analysis/step_policy.hpp"

#include <Eigen/Eigenvalues>
#include <Eigen/SparseLU>
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>

namespace plyimpact {

namespace {

class DelaminationStepPolicy;

/// Halvings of a correction that did not lower the residual by this fraction (DelaminationStepper::advance).
constexpr int max_halvings = 6;
constexpr double sufficient_decrease = 1e-4;
/// A refresh of the lagged step's iteration matrix updates its factor (DelaminationStepper::update_factor)
/// with at most this many rank-one terms, and a factor is refactored after this many in all (the
/// round-off of the updates accumulates).
constexpr int max_update_rank = 1000;
constexpr int max_total_update_rank = 20000;

class DelaminationStepper final : public StackedPlateStepper {
public:
  DelaminationStepper(const DelaminationStepPolicy& policy, const Impactor& impactor);
  ContactSolution advance(long step, double t, const PlateState& s, const ContactStep& contact,
                          Eigen::VectorXd& u_next) override;
  [[nodiscard]] std::optional<NewtonStatistics> statistics() const override { return stats_; }

private:
  class StepProblem;
  /// x = K̄⁻¹ b with the iteration matrix in use, into x (sized once), without allocating where the factor
  /// is a Cholesky one.
  void solve(const Eigen::VectorXd& b, Eigen::VectorXd& x);
  /// The same numbers in a new vector (the contact loading's responses).
  [[nodiscard]] Eigen::VectorXd solve(const Eigen::VectorXd& b) {
    Eigen::VectorXd x(b.size());
    solve(b, x);
    return x;
  }
  /// The part of the two-point trapezoidal step (DL7) fixed by its start u_n, f(u_n) − Fc_n s_n, into
  /// start_.
  void step_start(const Eigen::VectorXd& u_n, const ContactStep& contact);
  /// f(u_k) into force_ and the trial states into trial_, their tangent returned where asked for;
  /// returns the energy dissipated reaching the trial states.
  double internal_force(const Eigen::VectorXd& uk, CohesiveDamage damage,
                        std::optional<SparseMatrix>* tangent);
  /// Factors the tangent K_T + c0 M and iterates with it from now on; the lagged step records the
  /// interface points' tangents at uk that it holds (for update_factor).
  void use_tangent(const SparseMatrix& tangent, const Eigen::VectorXd& uk, CohesiveDamage damage);
  /// The lagged step's refresh where few interface points changed their tangent since the factor was
  /// made: K̄ + Σ_p J_pᵀ ΔT_p J_p by a rank update of the factor (SpdSolver::modify), ΔT_p split into
  /// its eigenvalues' signs. False, with the factor to be made anew, where that is not possible.
  bool update_factor(const Eigen::VectorXd& uk, CohesiveDamage damage);
  /// A refresh may try update_factor: the lagged step's own Cholesky factor is in use and updates are on.
  [[nodiscard]] bool may_update_factor() const;
  const DelaminationStepPolicy& p_;
  Eigen::SparseLU<SparseMatrix> tangent_lu_; ///< implicit: unsymmetric under mixed mode
  SpdSolver frozen_factor_;                  ///< lagged: the secant at fixed damage, symmetric positive
  bool tangent_in_use_ = false;
  std::vector<std::vector<Eigen::Matrix3d>>
      factored_tangents_; ///< per interface and point, in frozen_factor_
  int update_rank_ = 0;   ///< rank-one updates since its factorization
  Eigen::VectorXd kbar_diagonal_;
  NewtonStatistics stats_;
  /// The iterations' vectors and buffers, sized once: a step allocates nothing but where it refactors
  /// (the workspaces after the factors they serve, which they must not outlive).
  ContactIteration iteration_;
  Eigen::VectorXd u_start_, force_, start_, previous_load_;
  StackedPlateState trial_;
  SpdSolver::Workspace elastic_workspace_, frozen_workspace_;
};

class DelaminationStepPolicy final : public StackedPlatePolicy {
public:
  DelaminationStepPolicy(const PlateModel& model, const StepPolicyOptions& options,
                         const DelaminationSettings& settings)
      : StackedPlatePolicy(model, options, settings), elastic_(options.solver, options.ordering) {
    check_time_step();
    const SparseMatrix Kbar =
        stack_.evaluate(Eigen::VectorXd::Zero(stack_.size()), stack_.virgin_state()).tangent +
        options.newmark.c0 * M_.matrix();
    if (options.memory_limit_bytes)
      check_factor_memory(estimate_factor_memory(elastic_, Kbar), *options.memory_limit_bytes);
    elastic_.factorize(Kbar);
    elastic_diagonal_ = Kbar.diagonal();
  }

  [[nodiscard]] std::unique_ptr<PlateStepper> start(const Impactor& impactor) const override {
    return std::make_unique<DelaminationStepper>(*this, impactor);
  }

  SpdSolver elastic_;                ///< K_plates + K_penalty + c0 M, shared by the runs
  Eigen::VectorXd elastic_diagonal_; ///< its diagonal

private:
  void check_time_step() const {
    const double dt = options_.newmark.dt;
    const double limit =
        largest_delamination_time_step(model_.laminate(), settings_.stack, options_.newmark.beta);
    if (dt > limit)
      throw std::invalid_argument(fmt::format(
          "delamination: time.dt = {:.4g} s is above {:.4g} s, the largest step at which an interface point "
          "that starts softening keeps the step solvable (the softening slope of the interface law against "
          "the inertia of the sub-laminates, docs/delamination.md); set [time] dt <= {:.3g} or \"auto\"",
          dt, limit, limit));
  }
};

DelaminationStepper::DelaminationStepper(const DelaminationStepPolicy& policy, const Impactor& impactor)
    : StackedPlateStepper(policy, impactor), p_(policy),
      frozen_factor_(policy.options_.solver, policy.options_.ordering),
      kbar_diagonal_(policy.elastic_diagonal_), iteration_(policy.equations()) {
  for (Eigen::VectorXd* v : {&u_start_, &force_, &start_, &previous_load_})
    v->resize(policy.equations());
  loading_.set_solver([this](const Eigen::VectorXd& b) { return solve(b); });
  stats_.factorizations = 1; // the policy's elastic factor
}

void DelaminationStepper::solve(const Eigen::VectorXd& b, Eigen::VectorXd& x) {
  if (!tangent_in_use_)
    p_.elastic_.solve(b, x, elastic_workspace_);
  else if (p_.settings_.integration == DamageIntegration::lagged)
    frozen_factor_.solve(b, x, frozen_workspace_);
  else
    x = tangent_lu_.solve(b);
}

double DelaminationStepper::internal_force(const Eigen::VectorXd& uk, CohesiveDamage damage,
                                           std::optional<SparseMatrix>* tangent) {
  if (tangent == nullptr) {
    force_.noalias() = p_.stack_.plate_stiffness() * uk;
    return p_.stack_.add_interface_forces(uk, committed(), force_, trial_, damage);
  }
  StackedPlateEvaluation e = p_.stack_.evaluate(uk, committed(), damage);
  force_.swap(e.force);
  std::swap(trial_, e.trial);
  *tangent = std::move(e.tangent);
  return e.dissipated;
}

void DelaminationStepper::use_tangent(const SparseMatrix& tangent, const Eigen::VectorXd& uk,
                                      CohesiveDamage damage) {
  const SparseMatrix Kbar = tangent + p_.options_.newmark.c0 * p_.M_.matrix();
  if (p_.settings_.integration == DamageIntegration::lagged) {
    frozen_factor_.factorize(Kbar);
    factored_tangents_.resize(static_cast<std::size_t>(p_.stack_.interface_count()));
    for (int i = 0; i < p_.stack_.interface_count(); ++i)
      p_.stack_.interface(i).point_tangents(uk, committed().interfaces[static_cast<std::size_t>(i)], damage,
                                            factored_tangents_[static_cast<std::size_t>(i)]);
    update_rank_ = 0;
  } else {
    tangent_lu_.compute(Kbar);
    if (tangent_lu_.info() != Eigen::Success)
      throw NewtonFailure("delamination: the tangent of the stacked plate is singular; reduce time.dt");
  }
  tangent_in_use_ = true;
  kbar_diagonal_ = Kbar.diagonal();
  loading_.set_solver([this](const Eigen::VectorXd& b) { return solve(b); }); // responses recomputed
  ++stats_.factorizations;
}

bool DelaminationStepper::may_update_factor() const {
  return p_.settings_.update_factor && p_.settings_.integration == DamageIntegration::lagged &&
         tangent_in_use_;
}

bool DelaminationStepper::update_factor(const Eigen::VectorXd& uk, CohesiveDamage damage) {
  if (!may_update_factor()) return false;
  struct Change {
    std::size_t interface, point;
    Eigen::Matrix3d tangent;
  };
  std::vector<Change> changes;
  std::vector<Eigen::Triplet<double>> up, down; // the columns of C₊ and C₋
  std::vector<std::pair<int, double>> rows[3];
  std::vector<Eigen::Matrix3d> now;
  for (int i = 0; i < p_.stack_.interface_count(); ++i) {
    const CohesiveInterface& face = p_.stack_.interface(i);
    const auto ii = static_cast<std::size_t>(i);
    face.point_tangents(uk, committed().interfaces[ii], damage, now);
    for (int p = 0; p < face.point_count(); ++p) {
      const Eigen::Matrix3d& held = factored_tangents_[ii][static_cast<std::size_t>(p)];
      const Eigen::Matrix3d D = now[static_cast<std::size_t>(p)] - held;
      const double scale = now[static_cast<std::size_t>(p)].norm() + held.norm();
      if (D.norm() <= 1e-12 * scale) continue;
      if ((D - D.transpose()).norm() > 1e-12 * scale) return false; // an unsymmetric tangent
      const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> split(0.5 * (D + D.transpose()));
      for (int k = 0; k < 3; ++k) {
        rows[k].clear();
        face.jump_row(p, k, rows[k]);
      }
      for (int m = 0; m < 3; ++m) {
        const double lambda = split.eigenvalues()(m);
        if (std::abs(lambda) <= 1e-12 * scale) continue;
        std::vector<Eigen::Triplet<double>>& side = lambda > 0.0 ? up : down;
        const int column = side.empty() ? 0 : side.back().col() + 1;
        for (int k = 0; k < 3; ++k)
          for (const auto& [eq, c] : rows[k])
            side.emplace_back(eq, column, std::sqrt(std::abs(lambda)) * split.eigenvectors()(k, m) * c);
      }
      changes.push_back({ii, static_cast<std::size_t>(p), now[static_cast<std::size_t>(p)]});
    }
  }
  const int rank = (up.empty() ? 0 : up.back().col() + 1) + (down.empty() ? 0 : down.back().col() + 1);
  if (rank > max_update_rank || update_rank_ + rank > max_total_update_rank) return false;
  if (rank == 0) return true; // the factor holds the tangent already
  const auto columns = [n = p_.stack_.size()](const std::vector<Eigen::Triplet<double>>& t) {
    SparseMatrix C(n, t.empty() ? 0 : t.back().col() + 1);
    C.setFromTriplets(t.begin(), t.end());
    return C;
  };
  const SparseMatrix C_up = columns(up), C_down = columns(down);
  // The update first: the matrix stays positive definite in between.
  if ((C_up.cols() > 0 && !frozen_factor_.modify(C_up, true)) ||
      (C_down.cols() > 0 && !frozen_factor_.modify(C_down, false)))
    return false;
  for (const Change& c : changes)
    factored_tangents_[c.interface][c.point] = c.tangent;
  kbar_diagonal_ += C_up.cwiseProduct(C_up) * Eigen::VectorXd::Ones(C_up.cols()) -
                    C_down.cwiseProduct(C_down) * Eigen::VectorXd::Ones(C_down.cols());
  update_rank_ += rank;
  loading_.set_solver([this](const Eigen::VectorXd& b) { return solve(b); }); // responses recomputed
  ++stats_.factor_updates;
  return true;
}

/// One step's Newton problem on (u, Fc) (the module comment), with the damage evolving, lagged, or lagged
/// in the two-point form.
class DelaminationStepper::StepProblem final : public NewtonProblem {
public:
  StepProblem(DelaminationStepper& stepper, long step, double t, const PlateState& s,
              const ContactStep& contact)
      : p_(stepper), step_(step), t_(t), s_(s), contact_(contact),
        lagged_(stepper.p_.settings_.integration == DamageIntegration::lagged),
        mean_form_(lagged_ && stepper.p_.options_.newmark.beta == 0.25 &&
                   stepper.p_.options_.newmark.gamma == 0.5),
        damage_(!lagged_     ? CohesiveDamage::evolve
                : mean_form_ ? CohesiveDamage::lagged_mean
                             : CohesiveDamage::lagged) {
    p_.iteration_.predict(s, stepper.p_.options_.newmark); // constant acceleration: a_{n+1} = aₙ
    if (mean_form_) p_.step_start(s.u, contact);
  }

  // Backtracking: the law is only piecewise smooth (points start or stop softening, open or close), and
  // full corrections can cycle between its pieces; a correction that did not lower the residual by the
  // fraction sufficient_decrease is halved, up to max_halvings times (the last is kept). (An exact
  // two-cycle, equal residuals at both ends, was measured after separation.)
  Trial trial(int corrections) override {
    for (;;) {
      const double dissipated = evaluate();
      if (corrections == 0) return Trial::iterate;
      const DelaminationSettings& ds = p_.p_.settings_;
      if (p_.iteration_.converged(p_.loading_, cs_, p_.force_, p_.kbar_diagonal_, ds.residual_tolerance,
                                  ds.displacement_tolerance)) {
        // Lagged: the trial states' damage already follows the converged separation (for the next step).
        p_.set_trial(p_.trial_, dissipated);
        return Trial::converged;
      }
      const double residual = p_.iteration_.residual_norm();
      if (residual > (1.0 - sufficient_decrease) * start_residual_ && p_.tangent_in_use_ &&
          halvings_ < max_halvings) {
        p_.iteration_.uk() = 0.5 * (p_.u_start_ + p_.iteration_.uk());
        cs_.force = 0.5 * (cs_start_.force + cs_.force);
        cs_.alpha = 0.5 * (cs_start_.alpha + cs_.alpha);
        ++halvings_;
        continue;
      }
      start_residual_ = residual;
      return Trial::iterate;
    }
  }
  void refactor() override {
    if (!p_.update_factor(p_.iteration_.uk(), damage_))
      p_.use_tangent(tangent_ ? *tangent_
                              : p_.p_.stack_.evaluate(p_.iteration_.uk(), p_.committed(), damage_).tangent,
                     p_.iteration_.uk(), damage_);
    refresh_pending_ = false;
  }
  double correct() override {
    halvings_ = 0;
    p_.u_start_ = p_.iteration_.uk();
    cs_start_ = cs_;
    const double correction = p_.iteration_.correct(
        [this](const Eigen::VectorXd& g, Eigen::VectorXd& x) { p_.solve(g, x); }, p_.loading_, contact_, cs_);
    return std::isfinite(cs_.force) ? correction : NAN;
  }
  /// The refresh waits for the next trial, which assembles the tangent where the factor cannot be updated.
  bool defer_refresh() override { return refresh_pending_ = true; }
  [[nodiscard]] std::string why_not_converged(int max_iterations) const override {
    return fmt::format("delamination: Newton iterations did not converge in step {} (t = {:.6g} s) after {} "
                       "iterations; reduce time.dt",
                       step_, t_, max_iterations);
  }
  [[nodiscard]] std::string why_failed() const override {
    return fmt::format("delamination: non-finite state in step {} (t = {:.6g} s); reduce time.dt", step_, t_);
  }
  [[nodiscard]] const ContactSolution& contact_solution() const { return cs_; }

private:
  /// The force (and where a refresh waits for it, the tangent) at the iterate; the energy dissipated
  /// reaching the trial states.
  double evaluate() {
    const NewmarkCoefficients& nc = p_.p_.options_.newmark;
    ContactIteration& it = p_.iteration_;
    it.step_inertia(s_, nc, p_.p_.M_, mean_form_);
    const bool assemble_tangent = refresh_pending_ && !p_.may_update_factor();
    tangent_.reset();
    const double dissipated = p_.internal_force(it.uk(), damage_, assemble_tangent ? &tangent_ : nullptr);
    if (mean_form_) p_.force_ += p_.start_;
    it.set_internal_force(p_.force_);
    return dissipated;
  }

  DelaminationStepper& p_;
  const long step_;
  const double t_;
  const PlateState& s_;
  const ContactStep& contact_;
  const bool lagged_, mean_form_;
  const CohesiveDamage damage_;
  ContactSolution cs_, cs_start_; ///< cs_start_: where the last correction started, with u_start_
  double start_residual_ = INFINITY;
  int halvings_ = 0; ///< of the last correction
  bool refresh_pending_ = false;
  std::optional<SparseMatrix> tangent_;
};

ContactSolution DelaminationStepper::advance(long step, double t, const PlateState& s,
                                             const ContactStep& contact, Eigen::VectorXd& u_next) {
  const DelaminationSettings& ds = p_.settings_;
  StepProblem problem(*this, step, t, s, contact);
  const NewtonOutcome o =
      solve_newton(problem, NewtonControl{ds.max_iterations, ds.refresh_ratio,
                                          std::numeric_limits<int>::max(), ds.refresh_after});
  if (!o.converged) throw NewtonFailure(o.why);
  stats_.iterations += o.corrections;
  stats_.max_iterations_per_step = std::max(stats_.max_iterations_per_step, o.corrections);
  u_next.swap(iteration_.uk());
  return problem.contact_solution();
}

// The trapezoidal rule over the step in its two-point form, (u − u_n)/Δt = (v_n + v)/2 and
// M (v − v_n)/Δt = the mean of the step's forces, is
//   Fc s + Fc_n s_n − c0 M (u − u_n − Δt v_n) − f'(u) − f(u_n) = 0,                          (DL7)
// with f(u_n) = K_plates u_n + the interfaces' tractions at u_n, and f' the force of the end tractions
// 2 τ̄ − τ(δ_n) (CohesiveDamage::lagged_mean), all at the held damage: the mean of the step's forces is
// then ½ K_plates (u_n + u) + the interfaces' mean f̄ (DL6). aₙ does not enter: where the damage
// changed or faces opened or closed, the Newmark accelerations are not the equilibrium ones.
void DelaminationStepper::step_start(const Eigen::VectorXd& u_n, const ContactStep& contact) {
  start_.noalias() = p_.stack_.plate_stiffness() * u_n;
  (void)p_.stack_.add_interface_forces(u_n, committed(), start_, trial_, CohesiveDamage::lagged_mean);
  if (contact.previous_force() != 0.0) {
    loading_.scaled_load(contact.previous_indentation(), contact.previous_force(), previous_load_);
    start_ -= previous_load_;
  }
}

/// The stack whose plies crack, or whose sub-laminates deflect largely, under the lagged step: Newton–
/// Newmark on the stacked model (stacked_model.cpp), with the delamination settings' iterations; with
/// large deflections also the periodic refresh of the non-linear settings (the tangents move with u).
NewtonSettings lagged_stack_newton_settings(const DelaminationSettings& ds,
                                            const std::optional<NonlinearImpactSettings>& large_deflection) {
  NewtonSettings ns;
  ns.max_iterations = ds.max_iterations;
  ns.residual_tolerance = ds.residual_tolerance;
  ns.displacement_tolerance = ds.displacement_tolerance;
  ns.refresh_ratio = ds.refresh_ratio;
  ns.refresh_after = ds.refresh_after;
  if (large_deflection) ns.refresh_interval = large_deflection->refresh_interval;
  ns.physics = large_deflection ? "non-linear delamination" : "ply damage and delamination";
  ns.advice = "reduce time.dt";
  return ns;
}

/// Steepest softening slope of the law over the pure modes [Pa/m] (DL5).
double softening_slope(const CohesiveParameters& p) {
  const double K = p.penalty_stiffness;
  const auto slope = [K](double strength, double G_c) {
    return strength / (2.0 * G_c / strength - strength / K);
  };
  return std::max(slope(p.normal_strength, p.G_Ic), slope(p.shear_strength, p.G_IIc));
}

} // namespace

double largest_delamination_time_step(const Laminate& laminate, const StackSettings& stack,
                                      double newmark_beta) {
  const std::vector<Laminate> parts = split_laminate(laminate, stack.cuts, stack.shear_correction);
  const double k_s = softening_slope(stack.interface);
  double limit = INFINITY;
  for (std::size_t i = 0; i + 1 < parts.size(); ++i) {
    const double m_u = parts[i].inertia()[0], m_l = parts[i + 1].inertia()[0];
    limit = std::min(limit, std::sqrt(m_u * m_l / (m_u + m_l) / (newmark_beta * k_s)));
  }
  return limit;
}

std::unique_ptr<StepPolicy>
delamination_step_policy(const PlateModel& model, const StepPolicyOptions& options,
                         const DelaminationSettings& settings,
                         const std::optional<ProgressiveDamageSettings>& ply_damage,
                         const std::optional<NonlinearImpactSettings>& large_deflection) {
  const ModelKind kind{false, large_deflection.has_value(), ply_damage.has_value(), true};
  const Integrator integrator =
      resolve_integrator(kind, TimeIntegration::newmark,
                         ply_damage ? std::optional(integrator_of(ply_damage->integration)) : std::nullopt,
                         integrator_of(settings.integration));
  if (auto why = refusal(kind, integrator)) throw std::invalid_argument(*why); // capabilities.hpp
  std::optional<StrainMeasure> measure;
  if (large_deflection) {
    if (ply_damage && large_deflection->measure != StrainMeasure::von_karman)
      throw std::invalid_argument(
          "progressive damage takes the von Kármán strains of a non-linear plate: set strain_measure = "
          "\"von-karman\" (the Green–Lagrange measure is not built for the layered section whose plies "
          "crack)");
    measure = large_deflection->measure;
  }
  if (settings.integration == DamageIntegration::central_difference)
    return explicit_delamination_step_policy(model, options, settings, ply_damage, measure);
  if (ply_damage || large_deflection)
    return newton_newmark_step_policy(stacked_plate_model(model, settings, ply_damage, measure), options,
                                      lagged_stack_newton_settings(settings, large_deflection));
  return std::make_unique<DelaminationStepPolicy>(model, options, settings);
}

} // namespace plyimpact
