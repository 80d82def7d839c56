#include "plyimpact/analysis/thresholds/delamination_path.hpp"

#include "plyimpact/analysis/integrators/newton_solver.hpp"

#include <Eigen/UmfPackSupport>
#include <fmt/format.h>

#include <cmath>
#include <limits>
#include <optional>
#include <stdexcept>
#include <utility>

namespace plyimpact {

namespace {

/// The loading's parametrization u = t Δ + T y: y holds the free DOFs, then the rig's coordinates.
class Parametrization {
public:
  Parametrization(int size, const ControlledDisplacement& control)
      : control_(control), index_(static_cast<std::size_t>(size), 0) {
    for (const auto& [eq, c] : control.dofs)
      index_[static_cast<std::size_t>(eq)] = -1;
    for (const RigDof& r : control.rig)
      index_[static_cast<std::size_t>(r.equation)] = -1;
    for (int& i : index_)
      if (i == 0) i = free_++;
  }
  /// Unknowns: the free DOFs and the rig's coordinates.
  [[nodiscard]] int count() const { return free_ + control_.rig_coordinates; }

  /// u = t Δ + T y.
  [[nodiscard]] Eigen::VectorXd displacement(const Eigen::VectorXd& y, double delta) const {
    Eigen::VectorXd u(static_cast<Eigen::Index>(index_.size()));
    for (std::size_t i = 0; i < index_.size(); ++i)
      if (index_[i] >= 0) u(static_cast<Eigen::Index>(i)) = y(index_[i]);
    for (const auto& [eq, c] : control_.dofs)
      u(eq) = c * delta;
    for (const RigDof& r : control_.rig)
      u(r.equation) = r.delta_coefficient * delta + r.coordinate_coefficient * y(free_ + r.coordinate);
    return u;
  }
  /// Tᵀ f.
  [[nodiscard]] Eigen::VectorXd reduce(const Eigen::VectorXd& f) const {
    Eigen::VectorXd r = Eigen::VectorXd::Zero(count());
    for (std::size_t i = 0; i < index_.size(); ++i)
      if (index_[i] >= 0) r(index_[i]) = f(static_cast<Eigen::Index>(i));
    for (const RigDof& d : control_.rig)
      r(free_ + d.coordinate) += d.coordinate_coefficient * f(d.equation);
    return r;
  }
  /// Tᵀ K T.
  [[nodiscard]] SparseMatrix reduce(const SparseMatrix& K) const {
    std::vector<std::vector<std::pair<int, double>>> rig_of(index_.size());
    for (const RigDof& d : control_.rig)
      rig_of[static_cast<std::size_t>(d.equation)].emplace_back(free_ + d.coordinate,
                                                                d.coordinate_coefficient);
    const auto columns = [&](Eigen::Index i, const auto& each) {
      const auto k = static_cast<std::size_t>(i);
      if (index_[k] >= 0) each(index_[k], 1.0);
      for (const auto& [c, a] : rig_of[k])
        each(c, a);
    };
    std::vector<Eigen::Triplet<double>> t;
    t.reserve(static_cast<std::size_t>(K.nonZeros()));
    for (int c = 0; c < K.outerSize(); ++c)
      for (SparseMatrix::InnerIterator it(K, c); it; ++it)
        columns(it.row(), [&](int i, double wi) {
          columns(it.col(), [&](int j, double wj) { t.emplace_back(i, j, wi * wj * it.value()); });
        });
    SparseMatrix r(count(), count());
    r.setFromTriplets(t.begin(), t.end()); // sums the duplicates of the rig's coordinates
    return r;
  }
  /// P = tᵀ f.
  [[nodiscard]] double conjugate_force(const Eigen::VectorXd& f) const {
    double P = 0.0;
    for (const auto& [eq, c] : control_.dofs)
      P += c * f(eq);
    for (const RigDof& r : control_.rig)
      P += r.delta_coefficient * f(r.equation);
    return P;
  }

private:
  const ControlledDisplacement& control_;
  std::vector<int> index_; ///< index in y of a free DOF, −1 for a controlled or rig DOF
  int free_ = 0;
};

struct StepSolution {
  Eigen::VectorXd y;
  Eigen::VectorXd u;
  StackedPlateEvaluation evaluation;
  int iterations = 0;
};

/// The residual Tᵀ f at (y, Δ), the displacement and the evaluation it came from.
struct Residual {
  Eigen::VectorXd u;
  StackedPlateEvaluation evaluation;
  Eigen::VectorXd free;
};

Residual residual_at(const StackedPlate& model, const Parametrization& loading,
                     const StackedPlateState& committed, const Eigen::VectorXd& y, double delta) {
  Eigen::VectorXd u = loading.displacement(y, delta);
  StackedPlateEvaluation e = model.evaluate(u, committed);
  Eigen::VectorXd r = loading.reduce(e.force);
  return {std::move(u), std::move(e), std::move(r)};
}

/// A step of the path: Newton's method on the free DOFs at control displacement `delta`, from the guess
/// y, full Newton with the LU of the reduced tangent (unsymmetric in mixed mode) and a backtracking line
/// search on ‖r‖: the law is only piecewise smooth (a point leaves or rejoins its softening envelope), and
/// full Newton steps can cycle between the pieces. When no step length down to 1/64 lowers ‖r‖ the
/// shortest is taken.
class PathStep final : public NewtonProblem {
public:
  PathStep(const StackedPlate& model, const Parametrization& loading, const StackedPlateState& committed,
           Eigen::VectorXd y, double delta, double tolerance)
      : model_(model), loading_(loading), committed_(committed), y_(std::move(y)), delta_(delta),
        tolerance_(tolerance), r_(residual_at(model, loading, committed, y_, delta)) {
    lu_.umfpackControl()(UMFPACK_IRSTEP) = 0; // Newton's next residual corrects the solve
    lu_.umfpackControl()(UMFPACK_STRATEGY) = UMFPACK_STRATEGY_SYMMETRIC; // AMD on A + Aᵀ: FE patterns
  }

  /// The residual at y was evaluated where y was set (here or by the line search).
  Trial trial(int /*corrections*/) override {
    const double scale =
        std::max(std::abs(loading_.conjugate_force(r_.evaluation.force)), r_.evaluation.force.norm());
    return r_.free.norm() <= tolerance_ * std::max(scale, 1e-300) ? Trial::converged : Trial::iterate;
  }
  void refactor() override {} // full Newton: correct() factors
  double correct() override {
    K_ = loading_.reduce(r_.evaluation.tangent); // UMFPACK's solve reads the matrix it factored
    lu_.compute(K_);
    if (lu_.info() != Eigen::Success) return NAN;
    const Eigen::VectorXd minus_r = -r_.free;
    const Eigen::VectorXd dy = lu_.solve(minus_r);
    if (!dy.allFinite()) return NAN;
    for (double alpha = 1.0;; alpha *= 0.5) {
      const Eigen::VectorXd trial = y_ + alpha * dy;
      Residual next = residual_at(model_, loading_, committed_, trial, delta_);
      if (next.free.norm() < (1.0 - 1e-4 * alpha) * r_.free.norm() || alpha < 1.0 / 64.0) {
        y_ = trial;
        r_ = std::move(next);
        return alpha * dy.norm();
      }
    }
  }
  [[nodiscard]] StepSolution solution(int corrections) && {
    return StepSolution{std::move(y_), std::move(r_.u), std::move(r_.evaluation), corrections};
  }

private:
  const StackedPlate& model_;
  const Parametrization& loading_;
  const StackedPlateState& committed_;
  Eigen::VectorXd y_;
  const double delta_, tolerance_;
  Residual r_;
  SparseMatrix K_;
  Eigen::UmfPackLU<SparseMatrix> lu_;
};

/// The step to `delta` from the guess `y`; empty where the attempt has not converged after
/// settings.max_iterations corrections (the caller halves the step). `iterations` counts the corrections.
std::optional<StepSolution> solve_step(const StackedPlate& model, const Parametrization& loading,
                                       const StackedPlateState& committed, Eigen::VectorXd y, double delta,
                                       const DisplacementPathSettings& settings, int& iterations) {
  PathStep step(model, loading, committed, std::move(y), delta, settings.tolerance);
  const NewtonOutcome o = solve_newton(step, full_newton(settings.max_iterations));
  iterations += o.corrections;
  if (!o.converged) return std::nullopt;
  return std::move(step).solution(o.corrections);
}

} // namespace

DisplacementPath follow_displacement_path(const StackedPlate& model, const ControlledDisplacement& control,
                                          StackedPlateState state, const DisplacementPathSettings& settings,
                                          const PathObserver& observe) {
  const Parametrization loading(model.size(), control);
  DisplacementPath path;
  path.u = Eigen::VectorXd::Zero(model.size());
  Eigen::VectorXd y = Eigen::VectorXd::Zero(loading.count());
  PathPoint point;
  path.points.push_back(point);
  const double step = settings.final_displacement / settings.steps;
  double delta = 0.0;
  Eigen::VectorXd previous_increment = Eigen::VectorXd::Zero(loading.count());
  while (std::abs(delta) < std::abs(settings.final_displacement) * (1.0 - 1e-12)) {
    double increment = step;
    if (std::abs(delta + increment) > std::abs(settings.final_displacement))
      increment = settings.final_displacement - delta;
    std::optional<StepSolution> solution;
    int iterations = 0;
    for (int cut = 0; cut <= settings.max_cuts && !solution; ++cut, increment *= 0.5) {
      // Predictor: the previous step's increment, scaled to this one.
      const double scale =
          std::abs(point.displacement -
                   (path.points.size() > 1 ? path.points[path.points.size() - 2].displacement : 0.0));
      Eigen::VectorXd guess = y;
      if (scale > 0.0) guess += previous_increment * (increment / scale);
      solution = solve_step(model, loading, state, guess, delta + increment, settings, iterations);
    }
    if (!solution)
      throw std::runtime_error(
          fmt::format("stacked plate: no equilibrium found at control displacement {:.6g} m "
                      "after {} halvings of the step",
                      delta + 2.0 * increment, settings.max_cuts));
    increment *= 2.0; // undo the last halving of the loop
    previous_increment = solution->y - y;
    y = std::move(solution->y);
    path.u = std::move(solution->u);
    state = std::move(solution->evaluation.trial);
    const double P = loading.conjugate_force(solution->evaluation.force);
    point.work += 0.5 * (point.force + P) * increment;
    delta += increment;
    point.displacement = delta;
    point.force = P;
    point.dissipated += solution->evaluation.dissipated;
    point.stored = model.stored_energy(path.u, state);
    point.iterations = iterations;
    path.points.push_back(point);
    if (observe) observe(point, path.u, state);
  }
  path.state = std::move(state);
  return path;
}

} // namespace plyimpact
