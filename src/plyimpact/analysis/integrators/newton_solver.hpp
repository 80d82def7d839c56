#pragma once
// Newton's method, written once (issue 49): the iterations of a Newton–Newmark step of any plate model
// (newton_newmark_step.cpp: the von Kármán, damaged and stacked plates and their compositions), of a load
// step of the quasi-static von Kármán path (nonlinear_static.cpp) and of a step of the stacked plate's
// displacement-controlled path (delamination_path.cpp).
//
// The problem owns its unknowns, its residual, its matrix and that matrix's factor, and says when its
// iterate is converged (its test) and admitted (a part of the model that the trial left out has not
// joined it there); the solver decides
//   - when a new matrix is factored (modified Newton): where the corrections stop contracting by
//     `refresh_ratio`, after `refresh_after` corrections or every `refresh_every`, and after a trial that
//     changed a law's branch; where the control defers it (the matrix of lagged damage comes from a
//     trial), after the next trial,
//   - and when to give up: `max_iterations` corrections, or a correction that is not finite.
// Full Newton (a new matrix before every correction) is a problem that factors in its own correct(); a
// line search is the problem's too (its trial or its correction keeps the part of a correction that
// lowers the residual).
#include <limits>
#include <string>
#include <utility>

namespace plyimpact {

/// What Newton's method asks of the problem it solves: three functions; the rest is data.
class NewtonProblem {
public:
  virtual ~NewtonProblem() = default;
  NewtonProblem() = default;
  NewtonProblem(const NewtonProblem&) = delete;
  NewtonProblem& operator=(const NewtonProblem&) = delete;

  enum class Trial {
    iterate,        ///< not converged: a correction follows
    branch_changed, ///< not converged, and the trial changed which branch of a law holds (a crack opened
                    ///< or closed under held damage): a new matrix before the correction
    converged,      ///< the problem's test holds and the iterate is admitted
    failed,         ///< the residual cannot be used (why_failed())
  };
  /// Evaluates the residual at the current iterate, `corrections` having been made (a test on the last
  /// correction's size asks for corrections > 0). Converged only once the iterate is admitted: where a
  /// part of the model that the trial left out joins there (an element whose plies reach a failure
  /// surface), the problem evaluates again with it before it answers.
  virtual Trial trial(int corrections) = 0;
  /// Factors the matrix at the current iterate.
  virtual void refactor() = 0;
  /// Solves for a correction with the current factor and applies it to the iterate; its norm (not
  /// finite: the step failed, why_failed()).
  virtual double correct() = 0;

  /// Why the last trial failed or the last correction is not finite.
  [[nodiscard]] const std::string& why_failed() const { return why_failed_; }

protected:
  /// The reason why_failed() gives, said by the problem where it knows it.
  void set_why_failed(std::string why) { why_failed_ = std::move(why); }

private:
  std::string why_failed_ = "non-finite state";
};

/// When the solver refactors and when it gives up.
struct NewtonControl {
  int max_iterations = 30;     ///< corrections (linear solves) at most
  double refresh_ratio = 0.25; ///< refactor when ‖Δu_k‖/‖Δu_{k−1}‖ exceeds this
  int refresh_after = std::numeric_limits<int>::max(); ///< … or after this many corrections
  int refresh_every = 0; ///< … or after every this many corrections (0: never)
  /// A refresh waits for the trial at the next iterate, refactor() following it: the problem's matrix is
  /// that of its last trial (held damage), and where a trial costs little against a factorization (the
  /// stacked plate) the next iterate may converge without one.
  bool defer_refresh = false;
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
  bool failed = false; ///< stopped on a failed trial or a correction that is not finite (else at the limit)
  std::string why;     ///< where not converged
};

/// Newton's method on `problem` from its current iterate (module comment).
[[nodiscard]] NewtonOutcome solve_newton(NewtonProblem& problem, const NewtonControl& control);

} // namespace plyimpact
