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
#include "plyimpact/analysis/guards.hpp"
#include "plyimpact/analysis/nonlinear_static.hpp"
#include "plyimpact/analysis/step_policy.hpp"

#include <Eigen/Eigenvalues>
#include <Eigen/SparseLU>
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <stdexcept>
#include <string>

namespace plyimpact {

namespace {

class DelaminationStepPolicy;

/// The cohesive zone's length against the interface points' spacing [m].
struct ProcessZone {
  double length = 0.0;
  double point_spacing = 0.0;
};

/// Halvings of a correction that did not lower the residual by this fraction (DelaminationStepper::advance).
constexpr int max_halvings = 6;
constexpr double sufficient_decrease = 1e-4;
/// A refresh of the lagged step's iteration matrix updates its factor (DelaminationStepper::update_factor)
/// with at most this many rank-one terms, and a factor is refactored after this many in all (the
/// round-off of the updates accumulates).
constexpr int max_update_rank = 1000;
constexpr int max_total_update_rank = 20000;

class DelaminationStepper final : public PlateStepper {
public:
  DelaminationStepper(const DelaminationStepPolicy& policy, const Impactor& impactor);
  ContactSolution advance(long step, double t, const PlateState& s, const ContactStep& contact,
                          Eigen::VectorXd& u_next) override;
  void accept(const PlateState& before, const Eigen::VectorXd& u_next) override;
  [[nodiscard]] double kinetic_energy(const PlateState& s) const override;
  [[nodiscard]] double strain_energy(const PlateState& s, double force) const override;
  [[nodiscard]] double dissipated_energy() const override { return dissipated_; }
  [[nodiscard]] double contact_deflection(const Eigen::VectorXd& u) const override {
    return loading_.sampler().dot(u);
  }
  void to_model(const Eigen::VectorXd& u, Eigen::VectorXd& out) const override;
  [[nodiscard]] std::optional<NewtonStatistics> statistics() const override { return stats_; }
  [[nodiscard]] std::optional<DelaminationResult> delamination() const override;
  bool delamination_areas(DelaminationAreas& out) const override;

private:
  /// x = K̄⁻¹ b with the iteration matrix in use.
  [[nodiscard]] Eigen::VectorXd solve(const Eigen::VectorXd& b) const;
  /// The part of the two-point trapezoidal step (DL7) fixed by its start u_n: f(u_n) − Fc_n s_n.
  [[nodiscard]] Eigen::VectorXd step_start(const Eigen::VectorXd& u_n, const ContactStep& contact) const;
  /// Factors the tangent K_T + c0 M and iterates with it from now on; the lagged step records the
  /// interface points' tangents at uk that it holds (for update_factor).
  void use_tangent(const SparseMatrix& tangent, const Eigen::VectorXd& uk, CohesiveDamage damage);
  /// The lagged step's refresh where few interface points changed their tangent since the factor was
  /// made: K̄ + Σ_p J_pᵀ ΔT_p J_p by a rank update of the factor (SpdSolver::modify), ΔT_p split into
  /// its eigenvalues' signs. False, with the factor to be made anew, where that is not possible.
  bool update_factor(const Eigen::VectorXd& uk, CohesiveDamage damage);
  /// A refresh may try update_factor: the lagged step's own Cholesky factor is in use and updates are on.
  [[nodiscard]] bool may_update_factor() const;
  /// Has the iterate converged: small residual, and a small next correction estimated without a solve.
  [[nodiscard]] bool converged(const Eigen::VectorXd& g, const Eigen::VectorXd& inertia,
                               const Eigen::VectorXd& force, const ContactSolution& cs,
                               const Eigen::VectorXd& uk) const;

  const DelaminationStepPolicy& p_;
  ContactLoading loading_; ///< s_load, K̄⁻¹ s_load and c = swᵀ K̄⁻¹ s_load with the matrix in use
  Eigen::SparseLU<SparseMatrix> tangent_lu_; ///< implicit: unsymmetric under mixed mode
  SpdSolver frozen_factor_;                  ///< lagged: the secant at fixed damage, symmetric positive
  bool tangent_in_use_ = false;
  std::vector<std::vector<Eigen::Matrix3d>>
      factored_tangents_; ///< per interface and point, in frozen_factor_
  int update_rank_ = 0;   ///< rank-one updates since its factorization
  Eigen::VectorXd kbar_diagonal_;
  StackedPlateState committed_, trial_;
  double trial_dissipated_ = 0.0, dissipated_ = 0.0;
  NewtonStatistics stats_;
};

class DelaminationStepPolicy final : public StepPolicy {
public:
  DelaminationStepPolicy(const PlateModel& model, const StepPolicyOptions& options,
                         const DelaminationSettings& settings)
      : model_(model), options_(options), settings_(settings),
        stack_(model.mesh(), single_laminate(model), settings.stack,
               Discretization{model.mass_kind(), model.formulation()}, [&](int k) { return supports_of(k); }),
        top_equations_(stack_.sublaminate(0).size()), M_(stack_.mass(), 1e-14),
        elastic_(options.solver, options.ordering) {
    check_time_step();
    const SparseMatrix Kbar =
        stack_.evaluate(Eigen::VectorXd::Zero(stack_.size()), stack_.virgin_state()).tangent +
        options.newmark.c0 * M_.matrix();
    if (options.memory_limit_bytes)
      check_factor_memory(estimate_factor_memory(Kbar), *options.memory_limit_bytes);
    elastic_.factorize(Kbar);
    elastic_diagonal_ = Kbar.diagonal();
    map_top_to_model();
  }

  [[nodiscard]] int equations() const override { return stack_.size(); }
  [[nodiscard]] std::unique_ptr<PlateStepper> start(const Impactor& impactor) const override {
    return std::make_unique<DelaminationStepper>(*this, impactor);
  }
  [[nodiscard]] std::vector<std::string> warnings() const override {
    std::vector<std::string> w;
    if (auto zone = process_zone_warning()) w.push_back(std::move(*zone));
    if (auto ratio = strength_ratio_warning(settings_.stack.interface)) w.push_back(std::move(*ratio));
    return w;
  }

  const PlateModel& model_;
  StepPolicyOptions options_;
  DelaminationSettings settings_;
  StackedPlateModel stack_;
  EquationSubset top_equations_; ///< every equation of the top sub-laminate
  MassOperator M_;
  SpdSolver elastic_;                ///< K_plates + K_penalty + c0 M, shared by the runs
  Eigen::VectorXd elastic_diagonal_; ///< its diagonal
  std::vector<int> model_of_top_;    ///< model equation of each top sub-laminate equation (−1: none)

  /// The cohesive zone l = E2 G_c / τ² (Hillerborg, M = 1) of the shorter mode against the spacing of the
  /// interface points (half the largest element side with the nodal rule): fewer than three points in it
  /// and the onset and growth of a delamination depend on the mesh.
  [[nodiscard]] ProcessZone process_zone() const {
    const CohesiveParameters& c = settings_.stack.interface;
    double E2 = INFINITY;
    for (const Material& m : model_.laminate().materials())
      E2 = std::min(E2, m.E2);
    double largest = 0.0;
    for (int e = 0; e < model_.mesh().element_count(); ++e) {
      const ElementCoordinates X = model_.mesh().element_coordinates(e);
      largest = std::max(
          {largest, X.col(0).maxCoeff() - X.col(0).minCoeff(), X.col(1).maxCoeff() - X.col(1).minCoeff()});
    }
    return {std::min(cohesive_zone_length(E2, c.G_Ic, c.normal_strength),
                     cohesive_zone_length(E2, c.G_IIc, c.shear_strength)),
            settings_.stack.rule == CohesiveIntegration::nodal ? 0.5 * largest : largest / 3.0};
  }

private:
  [[nodiscard]] std::optional<std::string> process_zone_warning() const {
    const ProcessZone z = process_zone();
    if (z.length >= 3.0 * z.point_spacing) return std::nullopt;
    return fmt::format(
        "delamination: the cohesive zone of the interfaces, E2 G_c / strength^2 = {:.3g} mm in the shorter "
        "mode, spans {:.2g} interface points ({:.3g} mm apart): fewer than 3, so the onset and growth of "
        "delaminations depend on the mesh. Refine to elements of {:.3g} mm or less, or lower both "
        "strengths (Turon et al. 2007: tau = sqrt(9 pi E2 G_c / (32 * 3 * {:.3g} mm))) "
        "(docs/delamination.md)",
        z.length * 1e3, z.length / z.point_spacing, z.point_spacing * 1e3,
        2.0 * z.length / 3.0 * 1e3 * (settings_.stack.rule == CohesiveIntegration::nodal ? 1.0 : 1.5),
        z.point_spacing * 1e3);
  }
  /// Turon et al. (2010): with S/N ≠ √(G_IIc/G_Ic) the mixed-mode law does not dissipate G_c(B) along a
  /// crack front whose mixity changes (measured: MMB 1.23 G_c with N halved alone).
  [[nodiscard]] static std::optional<std::string> strength_ratio_warning(const CohesiveParameters& c) {
    const double ratio = (c.shear_strength / c.normal_strength) / std::sqrt(c.G_IIc / c.G_Ic);
    if (std::abs(ratio - 1.0) <= 0.1) return std::nullopt;
    return fmt::format("delamination: shear_strength / normal_strength = {:.3g} while sqrt(G_IIc / G_Ic) = "
                       "{:.3g}: under mixed mode the interfaces then dissipate more or less than G_c (Turon "
                       "et al. 2010; docs/delamination.md, MMB); set S = N sqrt(G_IIc / G_Ic) = {:.3g} MPa",
                       c.shear_strength / c.normal_strength, std::sqrt(c.G_IIc / c.G_Ic),
                       c.normal_strength * std::sqrt(c.G_IIc / c.G_Ic) * 1e-6);
  }
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
  static const Laminate& single_laminate(const PlateModel& model) {
    if (!model.single_section())
      throw std::invalid_argument("delamination: the stacked plate needs one laminate over the whole plate; "
                                  "[[regions]] with other laminates are not available with [delamination] "
                                  "yet (docs/delamination.md, limits)");
    return model.laminate();
  }
  [[nodiscard]] BoundaryConditions supports_of(int k) const {
    const int bottom = static_cast<int>(settings_.stack.cuts.size());
    return settings_.supports_on_all || k == bottom ? model_.boundary() : BoundaryConditions{};
  }
  void map_top_to_model() {
    const PlateModel& top = stack_.sublaminate(0);
    model_of_top_.assign(static_cast<std::size_t>(top.size()), -1);
    for (int n = 0; n < model_.mesh().node_count(); ++n)
      for (int dof = 0; dof < 5; ++dof)
        if (const int eq = top.dofs().equation(n, dof); eq >= 0)
          model_of_top_[static_cast<std::size_t>(eq)] = model_.dofs().equation(n, dof);
  }
};

DelaminationStepper::DelaminationStepper(const DelaminationStepPolicy& policy, const Impactor& impactor)
    : p_(policy), loading_(policy.stack_.sublaminate(0), policy.top_equations_, impactor,
                           policy.options_.load, policy.stack_.size()),
      frozen_factor_(policy.options_.solver, policy.options_.ordering),
      kbar_diagonal_(policy.elastic_diagonal_), committed_(policy.stack_.virgin_state()) {
  loading_.set_solver([this](const Eigen::VectorXd& b) { return solve(b); });
  stats_.factorizations = 1; // the policy's elastic factor
}

Eigen::VectorXd DelaminationStepper::solve(const Eigen::VectorXd& b) const {
  if (tangent_in_use_)
    return p_.settings_.integration == DamageIntegration::lagged ? frozen_factor_.solve(b)
                                                                 : tangent_lu_.solve(b);
  return p_.elastic_.solve(b);
}

void DelaminationStepper::use_tangent(const SparseMatrix& tangent, const Eigen::VectorXd& uk,
                                      CohesiveDamage damage) {
  const SparseMatrix Kbar = tangent + p_.options_.newmark.c0 * p_.M_.matrix();
  if (p_.settings_.integration == DamageIntegration::lagged) {
    frozen_factor_.factorize(Kbar);
    factored_tangents_.resize(static_cast<std::size_t>(p_.stack_.interface_count()));
    for (int i = 0; i < p_.stack_.interface_count(); ++i)
      p_.stack_.interface(i).point_tangents(uk, committed_.interfaces[static_cast<std::size_t>(i)], damage,
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
    face.point_tangents(uk, committed_.interfaces[ii], damage, now);
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

bool DelaminationStepper::converged(const Eigen::VectorXd& g, const Eigen::VectorXd& inertia,
                                    const Eigen::VectorXd& force, const ContactSolution& cs,
                                    const Eigen::VectorXd& uk) const {
  const DelaminationSettings& ds = p_.settings_;
  const Eigen::VectorXd s_load = loading_.load(cs.alpha);
  const Eigen::VectorXd residual = g + cs.force * s_load;
  const double scale = force.norm() + inertia.norm() + std::abs(cs.force) * s_load.norm();
  return residual.norm() <= ds.residual_tolerance * scale &&
         residual.cwiseQuotient(kbar_diagonal_).norm() <= ds.displacement_tolerance * uk.norm();
}

ContactSolution DelaminationStepper::advance(long step, double t, const PlateState& s,
                                             const ContactStep& contact, Eigen::VectorXd& u_next) {
  const DelaminationSettings& ds = p_.settings_;
  const NewmarkCoefficients& nc = p_.options_.newmark;
  // Start from constant acceleration (a_{n+1} = aₙ).
  Eigen::VectorXd uk = s.u + nc.dt * s.v + (0.5 * nc.dt * nc.dt) * s.a;
  Eigen::VectorXd u_start; // where the last correction started
  ContactSolution cs, cs_start;
  double previous_correction = INFINITY, start_residual = INFINITY;
  bool refactor = false;
  int iterations = 0, halvings = 0; // linear solves in this step; halvings of the last correction
  const bool lagged = ds.integration == DamageIntegration::lagged;
  const bool mean_form = lagged && nc.beta == 0.25 && nc.gamma == 0.5;
  const CohesiveDamage damage = !lagged     ? CohesiveDamage::evolve
                                : mean_form ? CohesiveDamage::lagged_mean
                                            : CohesiveDamage::lagged;
  const Eigen::VectorXd start = mean_form ? step_start(s.u, contact) : Eigen::VectorXd();
  for (;;) {
    const Eigen::VectorXd inertia = mean_form ? p_.M_.times(nc.c0 * (uk - s.u - nc.dt * s.v))
                                              : p_.M_.times(nc.c0 * (uk - s.u) - nc.c2 * s.v - nc.c3 * s.a);
    const bool assemble_tangent = refactor && !may_update_factor();
    StackedPlateEvaluation e = assemble_tangent ? p_.stack_.evaluate(uk, committed_, damage)
                                                : p_.stack_.internal_force(uk, committed_, damage);
    if (mean_form) e.force += start;
    const Eigen::VectorXd g = -inertia - e.force; // force-free residual
    if (iterations > 0) {
      if (converged(g, inertia, e.force, cs, uk)) {
        // Lagged: the trial states' damage already follows the converged separation (for the next step).
        trial_ = std::move(e.trial);
        trial_dissipated_ = e.dissipated;
        break;
      }
      // Backtracking: the law is only piecewise smooth (points start or stop softening, open or close),
      // and full corrections can cycle between its pieces; a correction that did not lower the residual
      // by the fraction sufficient_decrease is halved, up to max_halvings times (the last is kept). (An
      // exact two-cycle, equal residuals at both ends, was measured after separation.)
      const double residual = (g + cs.force * loading_.load(cs.alpha)).norm();
      if (residual > (1.0 - sufficient_decrease) * start_residual && tangent_in_use_ &&
          halvings < max_halvings) {
        uk = 0.5 * (u_start + uk);
        cs.force = 0.5 * (cs_start.force + cs.force);
        cs.alpha = 0.5 * (cs_start.alpha + cs.alpha);
        ++halvings;
        continue;
      }
      start_residual = residual;
    }
    if (refactor && !update_factor(uk, damage))
      use_tangent(assemble_tangent ? e.tangent : p_.stack_.evaluate(uk, committed_, damage).tangent, uk,
                  damage);
    refactor = false;
    halvings = 0;
    if (iterations == ds.max_iterations)
      throw NewtonFailure(fmt::format("delamination: Newton iterations did not converge in step {} (t = "
                                      "{:.6g} s) after {} iterations; reduce time.dt",
                                      step, t, ds.max_iterations));
    // Plate predictor û and the exact scalar contact problem with ws affine in Fc (SPEC §4).
    u_start = uk;
    cs_start = cs;
    const Eigen::VectorXd u_hat = uk + solve(g);
    cs = loading_.solve(contact, loading_.sampler().dot(u_hat));
    Eigen::VectorXd u_iterate = u_hat;
    loading_.add_response(cs.alpha, cs.force, u_iterate);
    const double correction = (u_iterate - uk).norm();
    ++iterations;
    if (!std::isfinite(correction) || !std::isfinite(cs.force))
      throw NewtonFailure(
          fmt::format("delamination: non-finite state in step {} (t = {:.6g} s); reduce time.dt", step, t));
    refactor = iterations > 1 &&
               (correction > ds.refresh_ratio * previous_correction || iterations % ds.refresh_after == 0);
    previous_correction = refactor ? INFINITY : correction;
    uk.swap(u_iterate);
  }
  stats_.iterations += iterations;
  stats_.max_iterations_per_step = std::max(stats_.max_iterations_per_step, iterations);
  u_next.swap(uk);
  return cs;
}

// The trapezoidal rule over the step in its two-point form, (u − u_n)/Δt = (v_n + v)/2 and
// M (v − v_n)/Δt = the mean of the step's forces, is
//   Fc s + Fc_n s_n − c0 M (u − u_n − Δt v_n) − f'(u) − f(u_n) = 0,                          (DL7)
// with f(u_n) = K_plates u_n + the interfaces' tractions at u_n, and f' the force of the end tractions
// 2 τ̄ − τ(δ_n) (CohesiveDamage::lagged_mean), all at the held damage: the mean of the step's forces is
// then ½ K_plates (u_n + u) + the interfaces' mean f̄ (DL6). aₙ does not enter: where the damage
// changed or faces opened or closed, the Newmark accelerations are not the equilibrium ones.
Eigen::VectorXd DelaminationStepper::step_start(const Eigen::VectorXd& u_n,
                                                const ContactStep& contact) const {
  Eigen::VectorXd start = p_.stack_.internal_force(u_n, committed_, CohesiveDamage::lagged_mean).force;
  if (contact.previous_force() != 0.0)
    start -= contact.previous_force() * loading_.load(contact.previous_indentation());
  return start;
}

void DelaminationStepper::accept(const PlateState& /*before*/, const Eigen::VectorXd& /*u_next*/) {
  committed_ = std::move(trial_);
  trial_ = {};
  dissipated_ += trial_dissipated_;
  trial_dissipated_ = 0.0;
}

double DelaminationStepper::kinetic_energy(const PlateState& s) const {
  return p_.M_.kinetic_energy(s.v);
}

double DelaminationStepper::strain_energy(const PlateState& s, double /*force*/) const {
  return p_.stack_.stored_energy(s.u, committed_);
}

void DelaminationStepper::to_model(const Eigen::VectorXd& u, Eigen::VectorXd& out) const {
  out = Eigen::VectorXd::Zero(p_.model_.size());
  for (std::size_t i = 0; i < p_.model_of_top_.size(); ++i)
    if (const int eq = p_.model_of_top_[i]; eq >= 0) out(eq) = u(static_cast<Eigen::Index>(i));
}

bool DelaminationStepper::delamination_areas(DelaminationAreas& out) const {
  const StackedPlateModel& stack = p_.stack_;
  const std::vector<std::vector<CohesiveState>>& states = committed_.interfaces;
  out.dissipated = dissipated_;
  out.delaminated_area.clear(); // keeps its capacity: no allocation after the first step
  out.delaminated_area.reserve(states.size());
  for (int i = 0; i < stack.interface_count(); ++i)
    out.delaminated_area.push_back(stack.interface(i).damaged_area(states[static_cast<std::size_t>(i)], 1.0));
  out.projected_area = 0.0;
  if (stack.interface_count() == 0) return true;
  // Every interface has the same points (same mesh and rule): the union is taken point by point.
  const CohesiveInterface& points = stack.interface(0);
  for (int q = 0; q < points.point_count(); ++q)
    if (std::any_of(states.begin(), states.end(), [q](const std::vector<CohesiveState>& of_interface) {
          return of_interface[static_cast<std::size_t>(q)].damage >= 1.0;
        }))
      out.projected_area += points.point_area(q);
  return true;
}

std::optional<DelaminationResult> DelaminationStepper::delamination() const {
  const StackedPlateModel& stack = p_.stack_;
  DelaminationResult r;
  DelaminationAreas areas;
  (void)delamination_areas(areas);
  r.delaminated_area = std::move(areas.delaminated_area);
  r.projected_area = areas.projected_area;
  r.dissipated = areas.dissipated;
  const ProcessZone zone = p_.process_zone();
  r.cohesive_zone_length = zone.length;
  r.interface_point_spacing = zone.point_spacing;
  for (int i = 0; i < stack.interface_count(); ++i) {
    const CohesiveInterface& ci = stack.interface(i);
    const std::vector<CohesiveState>& states = committed_.interfaces[static_cast<std::size_t>(i)];
    r.interface_after_ply.push_back(p_.settings_.stack.cuts[static_cast<std::size_t>(i)] + 1);
    double softening = 0.0;
    const auto per_element = static_cast<std::size_t>(ci.points_per_element());
    std::vector<double>& of_element = r.element_damage.emplace_back(states.size() / per_element, 0.0);
    std::vector<double>& of_point = r.point_damage.emplace_back();
    for (std::size_t q = 0; q < states.size(); ++q) {
      const double d = states[q].damage;
      if (d > 0.0 && d < 1.0) softening += ci.point_area(static_cast<int>(q));
      double& largest = of_element[q / per_element];
      largest = std::max(largest, d);
      of_point.push_back(d);
    }
    r.process_zone_area.push_back(softening);
  }
  if (stack.interface_count() > 0)
    for (int q = 0; q < stack.interface(0).point_count(); ++q) {
      r.point_cells.push_back(stack.interface(0).point_cell(q));
      r.point_area.push_back(stack.interface(0).point_area(q));
    }
  return r;
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

std::unique_ptr<StepPolicy> delamination_step_policy(const PlateModel& model,
                                                     const StepPolicyOptions& options,
                                                     const DelaminationSettings& settings) {
  return std::make_unique<DelaminationStepPolicy>(model, options, settings);
}

} // namespace plyimpact
