#include "plyimpact/analysis/integrators/newton_solver.hpp"

#include <fmt/format.h>

#include <cmath>

namespace plyimpact {

NewtonOutcome solve_newton(NewtonProblem& problem, const NewtonControl& control) {
  double previous_correction = INFINITY;
  bool refresh_at_next_trial = false;
  int corrections = 0;
  for (;;) {
    const NewtonProblem::Trial trial = problem.trial(corrections);
    if (trial == NewtonProblem::Trial::failed) return {false, corrections, true, problem.why_failed()};
    if (trial == NewtonProblem::Trial::converged) return {true, corrections, false, {}};
    if (trial == NewtonProblem::Trial::branch_changed || refresh_at_next_trial) {
      problem.refactor();
      previous_correction = INFINITY;
    }
    refresh_at_next_trial = false;
    if (corrections == control.max_iterations)
      return {false, corrections, false,
              fmt::format("the Newton iterations did not converge after {} solves", control.max_iterations)};
    const double correction = problem.correct();
    if (!std::isfinite(correction)) return {false, corrections, true, problem.why_failed()};
    ++corrections;
    const bool slow = correction > control.refresh_ratio * previous_correction ||
                      corrections > control.refresh_after ||
                      (control.refresh_every > 0 && corrections % control.refresh_every == 0);
    previous_correction = correction;
    if (slow && corrections > 1) {
      if (control.defer_refresh) {
        refresh_at_next_trial = true; // once the next iterate's trial has given its matrix
      } else {
        problem.refactor(); // modified Newton: a new matrix where the iterations slowed down
        previous_correction = INFINITY;
      }
    }
  }
}

} // namespace plyimpact
