#pragma once
// A quasi-static loading path of a stacked plate under displacement control (issue 19): the test
// specimens of delamination (DCB, ENF, MMB) are loaded by a prescribed displacement, under which the
// propagation branch of a crack is stable where a prescribed force would run away.
//
// A set of DOFs moves with one control displacement Δ: u_i = c_i Δ. The other DOFs carry no load, so
// each step solves f_F(u) = 0 on them by Newton's method with the consistent tangent of the stacked
// model (unsymmetric under mixed mode: Eigen's sparse LU, 3× faster than UMFPACK on the DCB strip), the
// interface damage evaluated from the state of the last converged step. The conjugate force is P = Σ_i c_i
// f_i(u) (virtual work: P dΔ = Σ f_i c_i dΔ). A step whose iterations do not converge is halved, up to
// `max_cuts` times.
//
// The energy of the path: the work W = ∫ P dΔ (trapezoidal rule), the stored energy of the model and
// the energy its interfaces dissipated; W = stored + dissipated is the balance a test checks.
#include "plyimpact/fem/stacked_plate.hpp"

#include <Eigen/Core>
#include <functional>
#include <utility>
#include <vector>

namespace plyimpact {

/// u_i = c_i Δ for each (stacked equation i, coefficient c_i).
struct ControlledDisplacement {
  std::vector<std::pair<int, double>> dofs;
};

struct DisplacementPathSettings {
  double final_displacement = 0.0; ///< Δ at the end of the path [m]
  int steps = 100;                 ///< equal increments of Δ
  int max_iterations = 12;         ///< Newton iterations per attempt of a step
  double tolerance = 1e-5;         ///< ‖f_F‖ ≤ tolerance · max(|P|, ‖f‖)
  int max_cuts = 10;               ///< halvings of a step that does not converge
};

/// One converged point of the path.
struct PathPoint {
  double displacement = 0.0; ///< Δ [m]
  double force = 0.0;        ///< P [N]
  double work = 0.0;         ///< ∫ P dΔ [J]
  double stored = 0.0;       ///< elastic energy of plates and interfaces [J]
  double dissipated = 0.0;   ///< energy dissipated by the interfaces [J]
  int iterations = 0;        ///< Newton iterations (all attempts)
};

struct DisplacementPath {
  std::vector<PathPoint> points; ///< Δ = 0 first
  Eigen::VectorXd u;             ///< at the last point
  StackedPlateState state;       ///< at the last point
};

/// Called after each converged step with the point, the displacement and the committed state.
using PathObserver = std::function<void(const PathPoint&, const Eigen::VectorXd&, const StackedPlateState&)>;

/// Follows the path from Δ = 0 in `state`. Throws std::runtime_error when a step does not converge
/// after max_cuts halvings (the message gives Δ and the residual).
[[nodiscard]] DisplacementPath follow_displacement_path(const StackedPlateModel& model,
                                                        const ControlledDisplacement& control,
                                                        StackedPlateState state,
                                                        const DisplacementPathSettings& settings,
                                                        const PathObserver& observe = {});

} // namespace plyimpact
