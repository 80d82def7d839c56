#include "plyimpact/analysis/delamination_path.hpp"

#include <Eigen/SparseLU>
#include <fmt/format.h>

#include <cmath>
#include <optional>
#include <stdexcept>

namespace plyimpact {

namespace {

/// The DOFs that are not controlled: their numbering, and the restriction of vectors and matrices.
class FreePart {
public:
  FreePart(int size, const ControlledDisplacement& control) : index_(static_cast<std::size_t>(size), 0) {
    for (const auto& [eq, c] : control.dofs)
      index_[static_cast<std::size_t>(eq)] = -1;
    for (int& i : index_)
      if (i == 0) i = count_++;
  }
  [[nodiscard]] int count() const { return count_; }
  [[nodiscard]] Eigen::VectorXd restrict(const Eigen::VectorXd& v) const {
    Eigen::VectorXd r(count_);
    for (std::size_t i = 0; i < index_.size(); ++i)
      if (index_[i] >= 0) r(index_[i]) = v(static_cast<Eigen::Index>(i));
    return r;
  }
  void add(Eigen::VectorXd& u, const Eigen::VectorXd& du) const {
    for (std::size_t i = 0; i < index_.size(); ++i)
      if (index_[i] >= 0) u(static_cast<Eigen::Index>(i)) += du(index_[i]);
  }
  [[nodiscard]] SparseMatrix restrict(const SparseMatrix& K) const {
    std::vector<Eigen::Triplet<double>> t;
    t.reserve(static_cast<std::size_t>(K.nonZeros()));
    for (int c = 0; c < K.outerSize(); ++c)
      for (SparseMatrix::InnerIterator it(K, c); it; ++it) {
        const int i = index_[static_cast<std::size_t>(it.row())];
        const int j = index_[static_cast<std::size_t>(it.col())];
        if (i >= 0 && j >= 0) t.emplace_back(i, j, it.value());
      }
    SparseMatrix r(count_, count_);
    r.setFromTriplets(t.begin(), t.end());
    return r;
  }

private:
  std::vector<int> index_; ///< reduced index, −1 for a controlled DOF
  int count_ = 0;
};

double conjugate_force(const ControlledDisplacement& control, const Eigen::VectorXd& f) {
  double P = 0.0;
  for (const auto& [eq, c] : control.dofs)
    P += c * f(eq);
  return P;
}

void impose(const ControlledDisplacement& control, double delta, Eigen::VectorXd& u) {
  for (const auto& [eq, c] : control.dofs)
    u(eq) = c * delta;
}

struct StepSolution {
  Eigen::VectorXd u;
  StackedPlateEvaluation evaluation;
  int iterations = 0;
};

/// The residual on the free DOFs at u and the evaluation it came from.
struct Residual {
  StackedPlateEvaluation evaluation;
  Eigen::VectorXd free;
};

Residual residual_at(const StackedPlateModel& model, const FreePart& free, const StackedPlateState& committed,
                     const Eigen::VectorXd& u) {
  StackedPlateEvaluation e = model.evaluate(u, committed);
  Eigen::VectorXd r = free.restrict(e.force);
  return {std::move(e), std::move(r)};
}

/// Newton's method on the free DOFs at control displacement `delta`, from the guess `u`, with a
/// backtracking line search on ‖r‖: the law is only piecewise smooth (a point leaves or rejoins its
/// softening envelope), and full Newton steps can cycle between the pieces. When no step length down to
/// 1/64 lowers ‖r‖ the shortest is taken; an attempt that has not converged after max_iterations is
/// given up, and the caller halves the step.
std::optional<StepSolution> solve_step(const StackedPlateModel& model, const ControlledDisplacement& control,
                                       const FreePart& free, const StackedPlateState& committed,
                                       Eigen::VectorXd u, double delta,
                                       const DisplacementPathSettings& settings, int& iterations) {
  impose(control, delta, u);
  Eigen::SparseLU<SparseMatrix> lu;
  Residual r = residual_at(model, free, committed, u);
  for (int k = 0; k < settings.max_iterations; ++k) {
    const double scale =
        std::max(std::abs(conjugate_force(control, r.evaluation.force)), r.evaluation.force.norm());
    if (r.free.norm() <= settings.tolerance * std::max(scale, 1e-300))
      return StepSolution{std::move(u), std::move(r.evaluation), k};
    lu.compute(free.restrict(r.evaluation.tangent));
    if (lu.info() != Eigen::Success) return std::nullopt;
    const Eigen::VectorXd minus_r = -r.free;
    const Eigen::VectorXd du = lu.solve(minus_r);
    if (!du.allFinite()) return std::nullopt;
    ++iterations;
    for (double alpha = 1.0;; alpha *= 0.5) {
      Eigen::VectorXd trial = u;
      free.add(trial, alpha * du);
      Residual next = residual_at(model, free, committed, trial);
      if (next.free.norm() < (1.0 - 1e-4 * alpha) * r.free.norm() || alpha < 1.0 / 64.0) {
        u = std::move(trial);
        r = std::move(next);
        break;
      }
    }
  }
  return std::nullopt;
}

} // namespace

DisplacementPath follow_displacement_path(const StackedPlateModel& model,
                                          const ControlledDisplacement& control, StackedPlateState state,
                                          const DisplacementPathSettings& settings,
                                          const PathObserver& observe) {
  const FreePart free(model.size(), control);
  DisplacementPath path;
  path.u = Eigen::VectorXd::Zero(model.size());
  PathPoint point;
  path.points.push_back(point);
  const double step = settings.final_displacement / settings.steps;
  double delta = 0.0;
  Eigen::VectorXd previous_increment = Eigen::VectorXd::Zero(model.size());
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
      Eigen::VectorXd guess = path.u;
      if (scale > 0.0) guess += previous_increment * (increment / scale);
      solution = solve_step(model, control, free, state, guess, delta + increment, settings, iterations);
    }
    if (!solution)
      throw std::runtime_error(
          fmt::format("stacked plate: no equilibrium found at control displacement {:.6g} m "
                      "after {} halvings of the step",
                      delta + 2.0 * increment, settings.max_cuts));
    increment *= 2.0; // undo the last halving of the loop
    previous_increment = solution->u - path.u;
    path.u = std::move(solution->u);
    state = std::move(solution->evaluation.trial);
    const double P = conjugate_force(control, solution->evaluation.force);
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
