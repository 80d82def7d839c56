// The linear step policy (SPEC §4): K̄ = K + M/(βΔt²) factored once per case; each step one
// back-substitution for the load-free predictor û = K̄⁻¹ M (c0 u + c2 v + c3 a), the exact scalar
// contact solve with ws = sᵀû + c Fc, c = sᵀK̄⁻¹s, and u_{n+1} = û + Fc K̄⁻¹ s_load.
#include "plyimpact/analysis/guards.hpp"
#include "plyimpact/analysis/step_policy.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>

namespace plyimpact {

MassOperator::MassOperator(const SparseMatrix& M, double tolerance) : M_(M) {
  const double m_max = M_.rows() > 0 ? M_.diagonal().cwiseAbs().maxCoeff() : 0.0;
  for (int col = 0; col < M_.outerSize(); ++col)
    for (SparseMatrix::InnerIterator it(M_, col); it; ++it)
      if (it.row() != col && std::abs(it.value()) > tolerance * m_max) return;
  diagonal_ = M_.diagonal();
}

namespace {

class LinearStepPolicy;

class LinearStepper final : public PlateStepper {
public:
  LinearStepper(const LinearStepPolicy& policy, const Impactor& impactor);
  ContactSolution advance(long step, double t, const PlateState& s, const ContactStep& contact,
                          Eigen::VectorXd& u_next) override;
  [[nodiscard]] double kinetic_energy(const PlateState& s) const override;
  [[nodiscard]] double strain_energy(const PlateState& s, double force) const override;
  [[nodiscard]] double contact_deflection(const Eigen::VectorXd& u) const override { return sw().dot(u); }
  void to_model(const Eigen::VectorXd& u, Eigen::VectorXd& out) const override;

private:
  [[nodiscard]] const Eigen::VectorXd& sw() const { return loading_.sampler(); }

  const LinearStepPolicy& p_;
  ContactLoading loading_; ///< s_load, K̄⁻¹ s_load and the compliance c = swᵀ K̄⁻¹ s_load
  // The step's vectors, sized once: no allocation in the time loop.
  Eigen::VectorXd predictor_, rhs_, u_hat_;
  mutable Eigen::VectorXd scratch_; ///< M v and M a of the energies
  SpdSolver::Workspace workspace_;  ///< CHOLMOD's arrays, reused by every solve
  double alpha_ = 0.0;              ///< indentation of the last step (its load vector)
};

class LinearStepPolicy final : public StepPolicy {
public:
  LinearStepPolicy(const PlateModel& model, const StepPolicyOptions& options, const SparseMatrix& K,
                   const SparseMatrix& M)
      : model_(model), options_(options), equations_(bending_equations_if_decoupled(model, K, M)),
        K_(equations_.restrict(K)), M_(equations_.restrict(M), 0.0) {
    const SparseMatrix Kbar = K_ + options.newmark.c0 * M_.matrix(); // effective stiffness, factored once
    if (options.memory_limit_bytes)
      check_factor_memory(estimate_factor_memory(Kbar), *options.memory_limit_bytes);
    factor_ = SpdSolver(options.solver, options.ordering);
    factor_.factorize(Kbar);
  }

  [[nodiscard]] int equations() const override { return equations_.size(); }
  [[nodiscard]] bool inplane_eliminated() const override { return !equations_.all(); }
  [[nodiscard]] std::unique_ptr<PlateStepper> start(const Impactor& impactor) const override {
    return std::make_unique<LinearStepper>(*this, impactor);
  }

  [[nodiscard]] double time_one_solve(int repeats) const override {
    if (equations() == 0) return 0.0;
    Eigen::VectorXd b = Eigen::VectorXd::Ones(equations());
    std::vector<double> t;
    Eigen::VectorXd x;
    for (int i = 0; i < repeats; ++i) {
      const auto t0 = std::chrono::steady_clock::now();
      x = factor_.solve(b);
      t.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
      b(0) += 1e-30 * x(0);
    }
    std::nth_element(t.begin(), t.begin() + repeats / 2, t.end());
    return t[static_cast<std::size_t>(repeats / 2)];
  }

  const PlateModel& model_;
  StepPolicyOptions options_;
  EquationSubset equations_;
  SparseMatrix K_;
  MassOperator M_; ///< exactly diagonal when lumped with I1 = 0
  SpdSolver factor_;
};

LinearStepper::LinearStepper(const LinearStepPolicy& policy, const Impactor& impactor)
    : p_(policy), loading_(policy.model_, policy.equations_, impactor, policy.options_.load),
      predictor_(policy.equations()), rhs_(policy.equations()), u_hat_(policy.equations()),
      scratch_(policy.equations()) {
  loading_.set_solver([&factor = p_.factor_](const Eigen::VectorXd& b) { return factor.solve(b); });
}

ContactSolution LinearStepper::advance(long /*step*/, double /*t*/, const PlateState& s,
                                       const ContactStep& contact, Eigen::VectorXd& u_next) {
  const NewmarkCoefficients& nc = p_.options_.newmark;
  // 1. Load-free predictor û = K̄⁻¹ M (c0 u + c2 v + c3 a): one back-substitution.
  predictor_ = nc.c0 * s.u + nc.c2 * s.v + nc.c3 * s.a;
  p_.M_.apply(predictor_, rhs_);
  p_.factor_.solve(rhs_, u_hat_, workspace_);
  // 2. Scalar contact problem with ws affine in Fc.
  const ContactSolution cs = loading_.solve(contact, sw().dot(u_hat_));
  alpha_ = cs.alpha;
  // 3. The plate under the converged force.
  u_next = u_hat_;
  loading_.add_response(cs.alpha, cs.force, u_next);
  return cs;
}

double LinearStepper::kinetic_energy(const PlateState& s) const {
  return p_.M_.kinetic_energy(s.v, scratch_);
}

double LinearStepper::strain_energy(const PlateState& s, double force) const {
  p_.M_.apply(s.a, scratch_);
  return 0.5 * (force * loading_.load_dot(alpha_, s.u) - s.u.dot(scratch_)); // K u = F s − M a
}

void LinearStepper::to_model(const Eigen::VectorXd& u, Eigen::VectorXd& out) const {
  p_.equations_.expand(u, out);
}

} // namespace

std::unique_ptr<StepPolicy> linear_step_policy(const PlateModel& model, const StepPolicyOptions& options) {
  return std::make_unique<LinearStepPolicy>(model, options, model.stiffness(), model.mass());
}

} // namespace plyimpact
