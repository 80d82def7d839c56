// The Newton step policy: large-deflection impact (SPEC §8, §4), total Lagrangian plate
// (NonlinearPlateModel), Newton iterations in each step on the coupled plate–impactor–contact system.
//
// Step n → n+1, unknowns u (plate) and Fc. With a = c0 (u − uₙ) − c2 vₙ − c3 aₙ, the plate residual is
//   r(u, Fc) = Fc s − M a(u) − f_int(u) = 0,   and the contact law Fc = F(α), α = wᵢ(Fc) − sᵀu.
// Each Newton iteration linearizes the plate with K̄ = K_T + c0 M: u' = û + Fc t, û = u + K̄⁻¹ g(u),
// g = −M a(u) − f_int(u), t = K̄⁻¹ s, so sᵀu' is affine in Fc and the contact law is solved exactly
// inside every iteration: plate and contact are solved together. K̄ is factored at the start of a run
// and refreshed (modified Newton) only when the iterations slow down (contraction ratio above
// `refresh_ratio` or more than `refresh_after` iterations in a step); at small Δt, c0 M dominates K̄
// and one factorization typically serves the whole event.
#include "plyimpact/analysis/contact_iteration.hpp"
#include "plyimpact/analysis/guards.hpp"
#include "plyimpact/analysis/nonlinear_static.hpp"
#include "plyimpact/analysis/step_policy.hpp"
#include "plyimpact/fem/nonlinear_plate_model.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace plyimpact {

namespace {

class NewtonStepPolicy;

class NewtonStepper final : public PlateStepper {
public:
  NewtonStepper(const NewtonStepPolicy& policy, const Impactor& impactor);
  ContactSolution advance(long step, double t, const PlateState& s, const ContactStep& contact,
                          Eigen::VectorXd& u_next) override;
  void accept(const PlateState& before, const Eigen::VectorXd& u_next) override;
  [[nodiscard]] double kinetic_energy(const PlateState& s) const override;
  [[nodiscard]] double strain_energy(const PlateState& /*s*/, double /*force*/) const override {
    return strain_energy_; // ∫ f_intᵀ du (trapezoidal): the elastic energy of the plate
  }
  [[nodiscard]] double contact_deflection(const Eigen::VectorXd& u) const override { return sw().dot(u); }
  void to_model(const Eigen::VectorXd& u, Eigen::VectorXd& out) const override { out = u; }
  [[nodiscard]] std::optional<NewtonStatistics> statistics() const override { return stats_; }

private:
  [[nodiscard]] const Eigen::VectorXd& sw() const { return loading_.sampler(); }
  void refactor(const Eigen::VectorXd& at);

  const NewtonStepPolicy& p_;
  ContactLoading loading_; ///< s_load, K̄⁻¹ s_load and c = swᵀ K̄⁻¹ s_load with the current factor
  SpdSolver factor_;
  Eigen::VectorXd kbar_diagonal_;
  Eigen::VectorXd f_int_, f_int_previous_step_;
  double strain_energy_ = 0.0;
  long last_refactor_ = 0;
  bool refresh_ = false; ///< the last step needed more than one solve: refactor at uₙ first
  NewtonStatistics stats_;
  SpdSolver::Workspace workspace_;
  ContactIteration iteration_;      ///< a step allocates nothing but where it refactors
  mutable Eigen::VectorXd scratch_; ///< M v of the kinetic energy
};

class NewtonStepPolicy final : public StepPolicy {
public:
  NewtonStepPolicy(const PlateModel& model, const StepPolicyOptions& options,
                   const NonlinearImpactSettings& settings)
      : model_(model), options_(options), settings_(settings), plate_(model, settings.measure),
        equations_(model.size()), M_(model.mass(), 1e-14) {}

  [[nodiscard]] int equations() const override { return model_.size(); }
  [[nodiscard]] std::unique_ptr<PlateStepper> start(const Impactor& impactor) const override {
    return std::make_unique<NewtonStepper>(*this, impactor);
  }

  const PlateModel& model_;
  StepPolicyOptions options_;
  NonlinearImpactSettings settings_;
  NonlinearPlateModel plate_;
  EquationSubset equations_;
  /// The lumped mass is diagonal when I1 = 0; a symmetric layup gives I1 at round-off level (~1e-20),
  /// whose u–θ entries are dropped rather than turning every M·x into a sparse product.
  MassOperator M_;
};

NewtonStepper::NewtonStepper(const NewtonStepPolicy& policy, const Impactor& impactor)
    : p_(policy), loading_(policy.model_, policy.equations_, impactor, policy.options_.load),
      factor_(policy.options_.solver, policy.options_.ordering),
      f_int_(Eigen::VectorXd::Zero(policy.equations())),
      f_int_previous_step_(Eigen::VectorXd::Zero(policy.equations())), iteration_(policy.equations()),
      scratch_(policy.equations()) {
  const Eigen::VectorXd at_rest = Eigen::VectorXd::Zero(policy.equations());
  if (policy.options_.memory_limit_bytes) // from the analysis that refactor() then reuses
    check_factor_memory(estimate_factor_memory(factor_, p_.plate_.tangent_stiffness(at_rest) +
                                                            p_.options_.newmark.c0 * p_.M_.matrix()),
                        *policy.options_.memory_limit_bytes);
  refactor(at_rest);
}

void NewtonStepper::refactor(const Eigen::VectorXd& at) {
  const SparseMatrix Kbar = p_.plate_.tangent_stiffness(at) + p_.options_.newmark.c0 * p_.M_.matrix();
  factor_.factorize(Kbar);
  kbar_diagonal_ = Kbar.diagonal();
  loading_.set_solver([this](const Eigen::VectorXd& b) { return factor_.solve(b); });
  ++stats_.factorizations;
}

ContactSolution NewtonStepper::advance(long step, double t, const PlateState& s, const ContactStep& contact,
                                       Eigen::VectorXd& u_next) {
  const NonlinearImpactSettings& ns = p_.settings_;
  const NewmarkCoefficients& nc = p_.options_.newmark;
  if (refresh_ && step - last_refactor_ >= ns.refresh_interval) {
    refactor(s.u);
    last_refactor_ = step;
  }
  // Newton iterations on (u, Fc); start from constant acceleration (a_{n+1} = aₙ).
  ContactIteration& it = iteration_;
  it.predict(s, nc);
  ContactSolution cs;
  double previous_correction = INFINITY;
  int iterations = 0; // linear solves in this step
  for (;;) {
    it.newmark_inertia(s, nc, p_.M_);
    p_.plate_.internal_force(it.uk(), f_int_);
    it.set_internal_force(f_int_);
    if (iterations > 0 &&
        it.converged(loading_, cs, f_int_, kbar_diagonal_, ns.residual_tolerance, ns.displacement_tolerance))
      break;
    if (iterations == ns.max_iterations)
      throw NewtonFailure(fmt::format(
          "non-linear impact: Newton iterations did not converge in step {} (t = {:.6g} s) after {} "
          "iterations; reduce time.dt",
          step, t, ns.max_iterations));
    const double correction =
        it.correct([this](const Eigen::VectorXd& g, Eigen::VectorXd& x) { factor_.solve(g, x, workspace_); },
                   loading_, contact, cs);
    ++iterations;
    if (!std::isfinite(correction) || !std::isfinite(cs.force))
      throw NewtonFailure(fmt::format(
          "non-linear impact: non-finite state in step {} (t = {:.6g} s); reduce time.dt", step, t));
    const bool slow = correction > ns.refresh_ratio * previous_correction || iterations > ns.refresh_after;
    previous_correction = correction;
    if (slow && iterations > 1) {
      refactor(it.uk()); // modified Newton: a new tangent where the iterations slowed down
      previous_correction = INFINITY;
    }
  }
  refresh_ = iterations > 1;
  stats_.iterations += iterations;
  stats_.max_iterations_per_step = std::max(stats_.max_iterations_per_step, iterations);
  u_next.swap(it.uk());
  return cs;
}

void NewtonStepper::accept(const PlateState& before, const Eigen::VectorXd& u_next) {
  // Work of the internal forces, trapezoidal; f_int of the last iterate stands for f_int(u_{n+1}) to
  // the Newton tolerance (no extra evaluation).
  strain_energy_ += 0.5 * (f_int_ + f_int_previous_step_).dot(u_next - before.u);
  f_int_previous_step_ = f_int_;
}

double NewtonStepper::kinetic_energy(const PlateState& s) const {
  return p_.M_.kinetic_energy(s.v, scratch_);
}

} // namespace

std::unique_ptr<StepPolicy> newton_step_policy(const PlateModel& model, const StepPolicyOptions& options,
                                               const NonlinearImpactSettings& settings) {
  return std::make_unique<NewtonStepPolicy>(model, options, settings);
}

} // namespace plyimpact
