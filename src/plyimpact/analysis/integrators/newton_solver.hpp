#pragma once
// Newton's method, written once (issue 49): the iterations of a Newton–Newmark step of any plate model
// (newton_newmark_step.cpp: the von Kármán, damaged and stacked plates and their compositions), of a load
// step of the quasi-static von Kármán path (nonlinear_static.cpp) and of a step of the stacked plate's
// displacement-controlled path (delamination_path.cpp).
//
// The problem owns its unknowns, its residual, its matrix and that matrix's factor; the solver decides
//   - when the iterate is converged (the problem's test) and admitted (a part of the model that the
//     trial left out has not joined it there),
//   - when a new matrix is factored (modified Newton): where the corrections stop contracting by
//     `refresh_ratio`, after `refresh_after` corrections or every `refresh_every`, and after a trial that
//     changed a law's branch; where the problem defers it (the matrix of lagged damage comes from a trial),
//     after the next trial,
//   - and when to give up: `max_iterations` corrections, or a correction that is not finite.
// Full Newton (a new matrix before every correction) is a problem that factors in its own correct(); a
// line search is the problem's too (its trial or its correction keeps the part of a correction that
// lowers the residual).
#include <limits>
#include <string>

namespace plyimpact {

/// What Newton's method asks of the problem it solves.
class NewtonProblem {
public:
  virtual ~NewtonProblem() = default;
  NewtonProblem() = default;
  NewtonProblem(const NewtonProblem&) = delete;
  NewtonProblem& operator=(const NewtonProblem&) = delete;

  enum class Trial { iterate, converged, failed };
  /// Evaluates the residual at the current iterate, `corrections` having been made: converged where the
  /// problem's test holds (a test on the last correction's size asks for corrections > 0); failed where
  /// the residual cannot be used (why_failed()).
  virtual Trial trial(int corrections) = 0;
  /// Once converged: false where the iterate must go on (a part joined the model there).
  virtual bool admit() { return true; }
  /// Factors the matrix at the current iterate.
  virtual void refactor() = 0;
  /// Solves for a correction with the current factor and applies it to the iterate; its norm (not
  /// finite: the step failed, why_failed()).
  virtual double correct() = 0;
  /// True once after a trial that changed which branch of a law holds (a new matrix at once).
  virtual bool take_branch_changed() { return false; }
  /// The solver wants a new matrix: true where the problem defers it to the next trial (whose evaluation
  /// gives the matrix: lagged damage), refactor() then following that trial.
  virtual bool defer_refresh() { return false; }
  /// Why the iterations stopped: no convergence after `max_iterations` corrections; a failed trial or a
  /// correction that is not finite.
  [[nodiscard]] virtual std::string why_not_converged(int max_iterations) const;
  [[nodiscard]] virtual std::string why_failed() const { return "non-finite state"; }
};

/// When the solver refactors and when it gives up.
struct NewtonControl {
  int max_iterations = 30;     ///< corrections (linear solves) at most
  double refresh_ratio = 0.25; ///< refactor when ‖Δu_k‖/‖Δu_{k−1}‖ exceeds this
  int refresh_after = std::numeric_limits<int>::max(); ///< … or after this many corrections
  int refresh_every = 0; ///< … or after every this many corrections (0: never)
  friend bool operator==(const NewtonControl&, const NewtonControl&) = default;
};

/// The control of a problem that factors before every correction itself (full Newton): the solver's
/// refresh rules never fire, only its limit of `max_iterations` corrections.
[[nodiscard]] inline NewtonControl full_newton(int max_iterations) {
  return {max_iterations, std::numeric_limits<double>::infinity(), std::numeric_limits<int>::max(), 0};
}

struct NewtonOutcome {
  bool converged = false;
  int corrections = 0; ///< finite corrections made
  std::string why;     ///< where not converged
};

/// Newton's method on `problem` from its current iterate (module comment).
[[nodiscard]] NewtonOutcome solve_newton(NewtonProblem& problem, const NewtonControl& control);

} // namespace plyimpact
