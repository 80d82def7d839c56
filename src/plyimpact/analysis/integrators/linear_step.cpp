// The linear step policy (SPEC §4): K̄ = K + M/(βΔt²) factored once per case; each step one
// back-substitution for the load-free predictor û = K̄⁻¹ M (c0 u + c2 v + c3 a), the exact scalar
// contact solve with ws = sᵀû + c Fc, c = sᵀK̄⁻¹s, and u_{n+1} = û + Fc K̄⁻¹ s_load.
#include "plyimpact/analysis/contact/contact_point_response.hpp"
#include "plyimpact/analysis/impact/guards.hpp"
#include "plyimpact/analysis/integrators/step_policy.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <mutex>

namespace plyimpact {

namespace {

class LinearStepPolicy;

class LinearStepper final : public PlateStepper {
public:
  LinearStepper(const LinearStepPolicy& policy, const Impactor& impactor);
  ContactSolution advance(long step, double t, const PlateState& s, const CondensedContact& contact,
                          Eigen::VectorXd& u_next) override;
  [[nodiscard]] double kinetic_energy(const PlateState& s) const override;
  [[nodiscard]] double strain_energy(const PlateState& s, double force) const override;
  [[nodiscard]] double contact_deflection(const Eigen::VectorXd& u) const override { return sw().dot(u); }
  void to_model(const Eigen::VectorXd& u, Eigen::VectorXd& out) const override;
  void set_time_step_level(int level) override;
  /// The step with a given contact force instead of the contact problem (the impulse run of
  /// contact_point_response.hpp).
  void load_step(const PlateState& s, double force, Eigen::VectorXd& u_next);

private:
  /// û = K̄⁻¹ M (c0 u + c2 v + c3 a) into u_hat_: one back-substitution.
  void predict(const PlateState& s);
  [[nodiscard]] const Eigen::VectorXd& sw() const { return loadings_.front()->sampler(); }

  const LinearStepPolicy& p_;
  Impactor impactor_;
  /// per time-step level (built when first used): s_load, K̄⁻¹ s_load and the compliance c = swᵀ K̄⁻¹ s_load
  std::vector<std::unique_ptr<ContactLoading>> loadings_;
  int level_ = 0;
  // The step's vectors, sized once: no allocation in the time loop.
  Eigen::VectorXd predictor_, rhs_, u_hat_;
  mutable Eigen::VectorXd scratch_; ///< M v and M a of the energies
  SpdSolver::Workspace workspace_;  ///< CHOLMOD's arrays, reused by every solve
  double alpha_ = 0.0;              ///< indentation of the last step (its load vector)
};

/// The effective stiffness of one time step: K̄ = K + c0 M with its Newmark coefficients.
struct TimeStepLevel {
  NewmarkCoefficients newmark;
  SpdSolver factor;
};

class LinearStepPolicy final : public StepPolicy {
public:
  LinearStepPolicy(const DiscretePlate& model, const StepPolicyOptions& options, const SparseMatrix& K,
                   const SparseMatrix& M)
      : model_(model), options_(options), equations_(bending_equations_if_decoupled(model, K, M)),
        K_(equations_.restrict(K)), M_(equations_.restrict(M), 0.0) {
    std::call_once(once_[0], [this] { levels_[0] = factor_level(options_.newmark, true); });
    set_equations({.equations = equations_.size(),
                   .inplane_eliminated = !equations_.all(),
                   .variable_time_step = true,
                   .warnings = {},
                   .stiffness = &K_,
                   .mass = &M_.matrix(),
                   .shared_factor = &levels_[0]->factor,
                   .factorizations = &factorizations_});
  }

  /// The run's stepper; the contact point's alone where it suffices and is exact (CP1).
  [[nodiscard]] std::unique_ptr<PlateStepper> start(const Impactor& impactor,
                                                    bool contact_point_suffices) const override;

  /// Level k: Δt/2^k and its factor of K̄, factored on first use (once, whichever run asks first: runs
  /// on several threads share the policy).
  [[nodiscard]] const TimeStepLevel& level(int k) const {
    if (k < 0 || k >= max_levels)
      throw std::invalid_argument(fmt::format("time-step level {} outside 0 … {}", k, max_levels - 1));
    std::call_once(once_[static_cast<std::size_t>(k)], [this, k] {
      const NewmarkCoefficients newmark = options_.newmark.halved(k);
      check_levels_memory(newmark.dt);
      levels_[static_cast<std::size_t>(k)] = factor_level(newmark, false);
      ++factorizations_;
    });
    return *levels_[static_cast<std::size_t>(k)];
  }

  static constexpr int max_levels = 24;

  const DiscretePlate& model_;
  StepPolicyOptions options_;
  EquationSubset equations_;
  SparseMatrix K_;
  MassOperator M_; ///< exactly diagonal when lumped with I1 = 0

private:
  /// K̄ of `newmark` factored; `check_memory`: against the memory limit first (level 0: the other levels
  /// have the same pattern, so the same factor size).
  [[nodiscard]] std::unique_ptr<TimeStepLevel> factor_level(const NewmarkCoefficients& newmark,
                                                            bool check_memory) const {
    const SparseMatrix Kbar = K_ + newmark.c0 * M_.matrix(); // effective stiffness, factored once
    auto level = std::make_unique<TimeStepLevel>(
        TimeStepLevel{newmark, SpdSolver(options_.solver, options_.ordering)});
    if (levels_[0]) level->factor.adopt_analysis_of(levels_[0]->factor); // one pattern, one ordering
    if (check_memory && options_.memory_limit_bytes) { // from the analysis that the factorization reuses
      factor_memory_ = estimate_factor_memory(level->factor, Kbar);
      check_factor_memory(factor_memory_, *options_.memory_limit_bytes);
    }
    level->factor.factorize(Kbar);
    return level;
  }

  /// Before the factor of one more time-step level (a step of `dt`): the factors held then, all of level
  /// 0's size, must fit in the memory the case was given (InsufficientMemory otherwise).
  void check_levels_memory(double dt) const {
    if (!options_.memory_limit_bytes) return;
    const int held = factorizations_.load() + 1;
    const double bytes = held * factor_memory_.bytes;
    if (bytes <= *options_.memory_limit_bytes) return;
    throw InsufficientMemory(fmt::format(
        "adaptive time steps: a factor of K̄ for the step {:.4g} s would make {} factors held ({} non-zeros "
        "each), about {:.3g} MB in all, but only {:.3g} MB are available: raise [time] tolerance, lower "
        "levels or use fixed steps",
        dt, held, factor_memory_.factor_nonzeros, bytes / 1e6, *options_.memory_limit_bytes / 1e6));
  }

  /// The impulse response at (x, y), computed on first use and kept for the runs that follow.
  [[nodiscard]] std::shared_ptr<const ContactPointResponse>
  contact_point_response(const Impactor& impactor) const;

  struct PointResponse {
    double x = 0.0, y = 0.0; ///< the impact point [m]
    std::shared_ptr<const ContactPointResponse> response;
  };
  mutable std::mutex responses_mutex_;
  mutable std::vector<PointResponse> responses_;
  /// of level 0's factor (when the case has a memory limit), set once by its factorization in the constructor
  mutable FactorMemoryEstimate factor_memory_;
  mutable std::array<std::once_flag, max_levels> once_;
  mutable std::array<std::unique_ptr<TimeStepLevel>, max_levels> levels_;
  mutable std::atomic<int> factorizations_{1};
};

LinearStepper::LinearStepper(const LinearStepPolicy& policy, const Impactor& impactor)
    : p_(policy), impactor_(impactor), loadings_(LinearStepPolicy::max_levels),
      predictor_(policy.equations()), rhs_(policy.equations()), u_hat_(policy.equations()),
      scratch_(policy.equations()) {
  set_time_step_level(0);
}

void LinearStepper::set_time_step_level(int level) {
  const TimeStepLevel& l = p_.level(level);
  auto& loading = loadings_[static_cast<std::size_t>(level)];
  if (!loading) {
    ContactLoading::Solve solve = [&factor = l.factor](const Eigen::VectorXd& b) { return factor.solve(b); };
    if (level == 0) {
      loading = std::make_unique<ContactLoading>(p_.model_, p_.equations_, impactor_, p_.options_.load);
      loading->set_solver(std::move(solve));
    } else { // the loads of level 0, this level's responses
      loading = std::make_unique<ContactLoading>(*loadings_.front(), std::move(solve));
    }
  }
  level_ = level;
}

void LinearStepper::predict(const PlateState& s) {
  const TimeStepLevel& level = p_.level(level_);
  const NewmarkCoefficients& nc = level.newmark;
  predictor_ = nc.c0 * s.u + nc.c2 * s.v + nc.c3 * s.a;
  p_.M_.apply(predictor_, rhs_);
  level.factor.solve(rhs_, u_hat_, workspace_);
}

ContactSolution LinearStepper::advance(long /*step*/, double /*t*/, const PlateState& s,
                                       const CondensedContact& contact, Eigen::VectorXd& u_next) {
  const ContactLoading& loading = *loadings_[static_cast<std::size_t>(level_)];
  // 1. Load-free predictor û = K̄⁻¹ M (c0 u + c2 v + c3 a): one back-substitution.
  predict(s);
  // 2. Scalar contact problem with ws affine in Fc.
  const ContactSolution cs = loading.solve(contact, sw().dot(u_hat_));
  alpha_ = cs.alpha;
  // 3. The plate under the converged force.
  u_next = u_hat_;
  loading.add_response(cs.alpha, cs.force, u_next);
  return cs;
}

void LinearStepper::load_step(const PlateState& s, double force, Eigen::VectorXd& u_next) {
  predict(s);
  u_next = u_hat_;
  loadings_[static_cast<std::size_t>(level_)]->add_response(0.0, force, u_next);
}

double LinearStepper::kinetic_energy(const PlateState& s) const {
  return p_.M_.kinetic_energy(s.v, scratch_);
}

double LinearStepper::strain_energy(const PlateState& s, double force) const {
  p_.M_.apply(s.a, scratch_);
  return 0.5 * (force * loadings_.front()->load_dot(alpha_, s.u) - s.u.dot(scratch_)); // K u = F s − M a
}

void LinearStepper::to_model(const Eigen::VectorXd& u, Eigen::VectorXd& out) const {
  p_.equations_.expand(u, out);
}

/// The plate from rest under F_1 = 1 and no force after it, one step per call (CP1's g).
class ImpulseRun {
public:
  ImpulseRun(const LinearStepPolicy& policy, const Impactor& impactor)
      : stepper_(policy, impactor),
        nc_(policy.level(0).newmark), s_{Eigen::VectorXd::Zero(policy.equations()),
                                         Eigen::VectorXd::Zero(policy.equations()),
                                         Eigen::VectorXd::Zero(policy.equations())},
        u_next_(policy.equations()), a_next_(policy.equations()) {}

  /// One step with the contact force `force`, the loop's Newmark update; swᵀu after it.
  double operator()(double force) {
    stepper_.load_step(s_, force, u_next_);
    stepper_.next_acceleration(nc_, s_, u_next_, a_next_);
    s_.v += nc_.c6 * s_.a + nc_.c7 * a_next_;
    s_.u.swap(u_next_);
    s_.a.swap(a_next_);
    return stepper_.contact_deflection(s_.u);
  }

private:
  LinearStepper stepper_;
  NewmarkCoefficients nc_;
  PlateState s_;
  Eigen::VectorXd u_next_, a_next_;
};

std::shared_ptr<const ContactPointResponse>
LinearStepPolicy::contact_point_response(const Impactor& impactor) const {
  const std::lock_guard lock(responses_mutex_);
  for (const PointResponse& r : responses_)
    if (r.x == impactor.x && r.y == impactor.y) return r.response;
  auto run = std::make_shared<ImpulseRun>(*this, impactor);
  auto response = std::make_shared<const ContactPointResponse>([run](double force) { return (*run)(force); });
  responses_.push_back({impactor.x, impactor.y, response});
  return response;
}

std::unique_ptr<PlateStepper> LinearStepPolicy::start(const Impactor& impactor,
                                                      bool contact_point_suffices) const {
  // The contact point alone is exact only where the load does not depend on the indentation, and its
  // energy known only with the trapezoidal rule (contact_point_response.hpp).
  const NewmarkCoefficients& nc = options_.newmark;
  if (contact_point_suffices && options_.load == ContactLoad::point && nc.beta == 0.25 && nc.gamma == 0.5 &&
      equations() != 0)
    return std::make_unique<ContactPointStepper>(contact_point_response(impactor));
  return std::make_unique<LinearStepper>(*this, impactor);
}

} // namespace

std::unique_ptr<StepPolicy> linear_step_policy(const DiscretePlate& model, const StepPolicyOptions& options) {
  return std::make_unique<LinearStepPolicy>(model, options, model.stiffness(), model.mass());
}

} // namespace plyimpact
