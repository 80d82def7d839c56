#pragma once
// How Newton–Newmark iterates a step (newton_newmark_step.cpp), written once for every model (issue 78):
// the integrator's settings live here, beside the integrator, not in the models' settings of fem/. Their
// defaults go by row of the table of what runs (capabilities.hpp): the model whose force is not linear
// in u decides how hard a step is to converge (the von Kármán tangent moves with u; the secant of ply
// damage needs tighter tolerances to close its energy balance; the softening interfaces take halved
// corrections), and the integrator whether the laws are iterated (implicit) or held (lagged).
#include "plyimpact/analysis/impact/capabilities.hpp"
#include "plyimpact/analysis/integrators/newton_solver.hpp"

#include <optional>
#include <string>

namespace plyimpact {

/// How Newton–Newmark iterates a step.
struct NewtonSettings {
  NewtonControl control;                ///< solves per step, and when a step refactors (newton_solver.hpp)
  double residual_tolerance = 1e-4;     ///< ‖r‖ ≤ tol · (‖f_int‖ + ‖M a‖ + ‖Fc s‖)
  double displacement_tolerance = 1e-6; ///< ‖K̄_diag⁻¹ r‖ ≤ tol · ‖u_{n+1}‖
  /// At most every this many steps, refactor at uₙ after a step that needed more than one solve.
  std::optional<long> refresh_interval;
  /// A correction made with a run's own factor that does not lower the residual is halved up to this many
  /// times (0: never; a law only piecewise smooth, whose full corrections can cycle between its pieces).
  int max_halvings = 0;
  /// A refresh takes the model's low-rank change of the matrix where it gives one (ModelState::
  /// matrix_change: the held stack's interface points, DL8) and updates the factor instead of making it
  /// anew; false: every refresh factors.
  bool update_factor = true;
  /// Refactor before a step once the model's state has drifted by more than this since the last
  /// factorization (ModelState::drift_since_factorization: the largest growth of a ply's damage).
  double refactor_tolerance = 0.05;
  std::string physics = "impact";        ///< the subject of the failure messages ("non-linear impact")
  std::string advice = "reduce time.dt"; ///< what they advise
  friend bool operator==(const NewtonSettings&, const NewtonSettings&) = default;
};

/// Newton–Newmark's settings for the model `m` stepped by `i` (implicit or lagged): the defaults of the
/// model's row of the table of what runs. Throws std::invalid_argument for a model that Newton–Newmark
/// does not step (the linear elastic plate, the rigid target) or an integrator other than those two.
[[nodiscard]] NewtonSettings newton_newmark_defaults(const ModelKind& m, Integrator i);

} // namespace plyimpact
