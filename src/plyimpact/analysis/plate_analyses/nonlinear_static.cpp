#include "plyimpact/analysis/plate_analyses/nonlinear_static.hpp"

#include "plyimpact/analysis/integrators/newton_solver.hpp"
#include "plyimpact/fem/mechanical_model.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <string>

namespace plyimpact {

namespace {

/// A load step of the von Kármán plate, f_int(u) = λ f from the iterate u (updated in place), by full
/// Newton: the tangent K_T(u) factored before every correction (its analysis reused).
class LoadStep final : public NewtonProblem {
public:
  LoadStep(ModelState& plate, SpdSolver& solver, const Eigen::VectorXd& f_ext, double lambda,
           Eigen::VectorXd& u, const NonlinearSettings& s)
      : plate_(plate), solver_(solver), f_ext_(f_ext), lambda_(lambda), u_(u), s_(s),
        f_norm_(lambda * f_ext.norm()), f_int_(u.size()) {}

  Trial trial(int corrections) override {
    plate_.internal_force(u_, 0.0, f_int_);
    r_ = lambda_ * f_ext_ - f_int_;
    r_norm_ = r_.norm();
    if (!std::isfinite(r_norm_)) {
      set_why_failed("the residual is not finite");
      return Trial::failed;
    }
    return corrections > 0 && r_norm_ <= s_.residual_tolerance * f_norm_ &&
                   du_norm_ <= s_.displacement_tolerance * u_.norm()
               ? Trial::converged
               : Trial::iterate;
  }
  void refactor() override {} // full Newton: correct() factors
  double correct() override {
    try {
      solver_.factorize(plate_.iteration_matrix(u_)); // K_T(u)
    } catch (const NotPositiveDefinite&) {
      set_why_failed("the tangent stiffness is not positive definite (limit point or bifurcation)");
      return NAN;
    }
    const Eigen::VectorXd du = solver_.solve(r_);
    du_norm_ = du.norm();
    if (!std::isfinite(du_norm_)) set_why_failed("the correction is not finite");
    u_ += du;
    return du_norm_;
  }
  /// Why the iterations of `o` stopped: the failure, or the residual left after `max_iterations`.
  [[nodiscard]] std::string why(const NewtonOutcome& o, int max_iterations) const {
    if (o.failed) return o.why;
    return fmt::format("no convergence in {} iterations (residual {:.3g} of the load)", max_iterations,
                       r_norm_ / f_norm_);
  }

private:
  ModelState& plate_;
  SpdSolver& solver_;
  const Eigen::VectorXd& f_ext_;
  const double lambda_;
  Eigen::VectorXd& u_;
  const NonlinearSettings& s_;
  const double f_norm_;
  Eigen::VectorXd f_int_, r_;
  double r_norm_ = INFINITY, du_norm_ = INFINITY;
};

/// The load factors to converge at: the given list, or `load_steps` equal increments.
std::vector<double> load_milestones(const NonlinearSettings& s) {
  if (s.load_factors.empty()) {
    if (s.load_steps < 1) throw std::invalid_argument("non-linear static: load_steps must be at least 1");
    std::vector<double> m(static_cast<std::size_t>(s.load_steps));
    for (int k = 1; k <= s.load_steps; ++k)
      m[static_cast<std::size_t>(k - 1)] = double(k) / s.load_steps;
    return m;
  }
  double previous = 0.0;
  for (const double l : s.load_factors) {
    if (!(l > previous) || l > 1.0)
      throw std::invalid_argument("non-linear static: load_factors must increase within (0, 1]");
    previous = l;
  }
  if (previous != 1.0) throw std::invalid_argument("non-linear static: load_factors must end at 1");
  return s.load_factors;
}

} // namespace

NonlinearStaticResult solve_static_nonlinear(const DiscretePlate& model, const StaticLoad& load,
                                             const NonlinearSettings& s) {
  require_bilateral(model.boundary(), "the non-linear static analysis");
  const std::vector<double> milestones = load_milestones(s);
  (void)factor_stiffness(model, model.stiffness()); // restraint check with advice (InsufficientRestraint)
  const std::unique_ptr<MechanicalModel> plate = von_karman_plate_model(model, s.measure);
  const std::unique_ptr<ModelState> state = plate->virgin_state(); // elastic: no state to commit
  SpdSolver solver;
  const Eigen::VectorXd f = static_load_vector(model, load);
  const Eigen::Vector2d middle = model.mesh().bounds().centre();
  const PointSampler centre = model.sampler(middle.x(), middle.y());

  NonlinearStaticResult r;
  r.load_deflection.push_back({0.0, 0.0});
  Eigen::VectorXd u = Eigen::VectorXd::Zero(model.size());
  if (f.norm() == 0.0) {
    r.load_deflection.push_back({1.0, 0.0});
    r.state = static_result(model, load, u);
    return r;
  }
  double lambda = 0.0;
  for (const double milestone : milestones) {
    const double nominal = milestone - lambda;
    double increment = nominal;
    int cuts_in_a_row = 0;
    while (lambda < milestone) {
      const double target =
          (lambda + increment >= milestone * (1.0 - 1e-12)) ? milestone : lambda + increment;
      Eigen::VectorXd trial = u;
      LoadStep load_step(*state, solver, f, target, trial, s);
      const NewtonOutcome o = solve_newton(load_step, full_newton(s.max_iterations));
      r.newton_iterations += o.corrections;
      if (!o.converged) {
        if (++cuts_in_a_row > s.max_step_cuts)
          throw NewtonFailure(fmt::format(
              "non-linear static: Newton-Raphson failed between load factors {:.6g} and {:.6g} even after {} "
              "step cuts: {}. Try more load steps (nonlinear_load_steps) or check the supports and the load",
              lambda, target, s.max_step_cuts, load_step.why(o, s.max_iterations)));
        increment /= 2.0; // automatic step cutting
        ++r.step_cuts;
        continue;
      }
      r.max_iterations_per_step = std::max(r.max_iterations_per_step, o.corrections);
      u = std::move(trial);
      lambda = target;
      r.load_deflection.push_back({lambda, centre.value(u)});
      cuts_in_a_row = 0;
      increment = std::min(nominal, 2.0 * increment); // recover after a cut
    }
  }
  r.state = static_result(model, load, std::move(u));
  return r;
}

} // namespace plyimpact
