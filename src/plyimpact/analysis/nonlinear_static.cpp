#include "plyimpact/analysis/nonlinear_static.hpp"

#include "plyimpact/fem/nonlinear_plate_model.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace plyimpact {

namespace {

struct NewtonOutcome {
  bool converged = false;
  int iterations = 0;
  std::string why; ///< when not converged
};

/// Full Newton from u (updated in place) towards f_int(u) = λ f.
NewtonOutcome newton(const NonlinearPlateModel& plate, const Eigen::VectorXd& f_ext, double lambda,
                     Eigen::VectorXd& u, const NonlinearSettings& s) {
  NewtonOutcome out;
  const double f_norm = lambda * f_ext.norm();
  double du_norm = INFINITY;
  for (int it = 0; it <= s.max_iterations; ++it) {
    const Eigen::VectorXd r = lambda * f_ext - plate.internal_force(u);
    const double r_norm = r.norm();
    if (!std::isfinite(r_norm)) {
      out.why = "the residual is not finite";
      return out;
    }
    if (r_norm <= s.residual_tolerance * f_norm && du_norm <= s.displacement_tolerance * u.norm()) {
      out.converged = true;
      return out;
    }
    if (it == s.max_iterations) {
      out.why = fmt::format("no convergence in {} iterations (residual {:.3g} of the load)", s.max_iterations,
                            r_norm / f_norm);
      return out;
    }
    SpdSolver solver;
    try {
      solver.factorize(plate.tangent_stiffness(u));
    } catch (const NotPositiveDefinite&) {
      out.why = "the tangent stiffness is not positive definite (limit point or bifurcation)";
      return out;
    }
    const Eigen::VectorXd du = solver.solve(r);
    du_norm = du.norm();
    u += du;
    ++out.iterations;
  }
  return out;
}

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

NonlinearStaticResult solve_static_nonlinear(const PlateModel& model, const StaticLoad& load,
                                             const NonlinearSettings& s) {
  require_bilateral(model.boundary(), "the non-linear static analysis");
  const std::vector<double> milestones = load_milestones(s);
  (void)factor_stiffness(model, model.stiffness()); // restraint check with advice (InsufficientRestraint)
  const NonlinearPlateModel plate(model, s.measure);
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
      const NewtonOutcome o = newton(plate, f, target, trial, s);
      r.newton_iterations += o.iterations;
      if (!o.converged) {
        if (++cuts_in_a_row > s.max_step_cuts)
          throw NewtonFailure(fmt::format(
              "non-linear static: Newton-Raphson failed between load factors {:.6g} and {:.6g} even after {} "
              "step cuts: {}. Try more load steps (nonlinear_load_steps) or check the supports and the load",
              lambda, target, s.max_step_cuts, o.why));
        increment /= 2.0; // automatic step cutting
        ++r.step_cuts;
        continue;
      }
      r.max_iterations_per_step = std::max(r.max_iterations_per_step, o.iterations);
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
