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
  /// The iteration's vectors, sized once: a step allocates nothing but where it refactors.
  Eigen::VectorXd uk_, ak_, inertia_, g_, s_load_, residual_, correction_, u_iterate_;
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
      f_int_previous_step_(Eigen::VectorXd::Zero(policy.equations())) {
  for (Eigen::VectorXd* v : {&uk_, &ak_, &inertia_, &g_, &s_load_, &residual_, &correction_, &u_iterate_})
    v->resize(policy.equations());
  const Eigen::VectorXd at_rest = Eigen::VectorXd::Zero(policy.equations());
  if (policy.options_.memory_limit_bytes)
    check_factor_memory(estimate_factor_memory(p_.plate_.tangent_stiffness(at_rest) +
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
  Eigen::VectorXd& uk = uk_;
  uk.noalias() = s.u + nc.dt * s.v + (0.5 * nc.dt * nc.dt) * s.a;
  ContactSolution cs;
  double previous_correction = INFINITY;
  int iterations = 0; // linear solves in this step
  for (;;) {
    ak_.noalias() = nc.c0 * (uk - s.u) - nc.c2 * s.v - nc.c3 * s.a;
    p_.M_.apply(ak_, inertia_);
    p_.plate_.internal_force(uk, f_int_);
    g_.noalias() = -inertia_ - f_int_; // force-free residual
    // Converged: the residual is small, and so is the next correction, estimated without a solve
    // by the diagonal of K̄ (δ ≈ diag(K̄)⁻¹ r).
    if (iterations > 0) {
      loading_.scaled_load(cs.alpha, 1.0, s_load_);
      residual_.noalias() = g_ + cs.force * s_load_;
      const double scale = f_int_.norm() + inertia_.norm() + std::abs(cs.force) * s_load_.norm();
      if (residual_.norm() <= ns.residual_tolerance * scale &&
          residual_.cwiseQuotient(kbar_diagonal_).norm() <= ns.displacement_tolerance * uk.norm())
        break;
    }
    if (iterations == ns.max_iterations)
      throw NewtonFailure(fmt::format(
          "non-linear impact: Newton iterations did not converge in step {} (t = {:.6g} s) after {} "
          "iterations; reduce time.dt",
          step, t, ns.max_iterations));
    // Plate predictor û and the exact scalar contact problem with ws affine in Fc (SPEC §4).
    factor_.solve(g_, correction_, workspace_);
    u_iterate_.noalias() = uk + correction_; // û, the iterate before the contact force
    cs = loading_.solve(contact, sw().dot(u_iterate_));
    loading_.add_response(cs.alpha, cs.force, u_iterate_);
    const double correction = (u_iterate_ - uk).norm();
    ++iterations;
    if (!std::isfinite(correction) || !std::isfinite(cs.force))
      throw NewtonFailure(fmt::format(
          "non-linear impact: non-finite state in step {} (t = {:.6g} s); reduce time.dt", step, t));
    const bool slow = correction > ns.refresh_ratio * previous_correction || iterations > ns.refresh_after;
    previous_correction = correction;
    uk.swap(u_iterate_);
    if (slow && iterations > 1) {
      refactor(uk); // modified Newton: a new tangent where the iterations slowed down
      previous_correction = INFINITY;
    }
  }
  refresh_ = iterations > 1;
  stats_.iterations += iterations;
  stats_.max_iterations_per_step = std::max(stats_.max_iterations_per_step, iterations);
  u_next.swap(uk);
  return cs;
}

void NewtonStepper::accept(const PlateState& before, const Eigen::VectorXd& u_next) {
  // Work of the internal forces, trapezoidal; f_int of the last iterate stands for f_int(u_{n+1}) to
  // the Newton tolerance (no extra evaluation).
  strain_energy_ += 0.5 * (f_int_ + f_int_previous_step_).dot(u_next - before.u);
  f_int_previous_step_ = f_int_;
}

double NewtonStepper::kinetic_energy(const PlateState& s) const {
  return p_.M_.kinetic_energy(s.v);
}

} // namespace

std::unique_ptr<StepPolicy> newton_step_policy(const PlateModel& model, const StepPolicyOptions& options,
                                               const NonlinearImpactSettings& settings) {
  return std::make_unique<NewtonStepPolicy>(model, options, settings);
}

} // namespace plyimpact
