#pragma once
// A quasi-static loading path of a stacked plate under displacement control (issue 19): the test
// specimens of delamination (DCB, ENF, MMB) are loaded by a prescribed displacement, under which the
// propagation branch of a crack is stable where a prescribed force would run away.
//
// A set of DOFs moves with one control displacement Δ: u_i = c_i Δ; a loading rig may tie others to Δ
// and to its own coordinates y (u_i = c_i Δ + a_i y_j). The rest carry no load. With y' = (free DOFs, y)
// and u = t Δ + T y', each step solves Tᵀ f(u) = 0 by Newton's method with the tangent Tᵀ K T of the stacked
// model (unsymmetric under mixed mode: UMFPACK's LU with its symmetric strategy, 3× faster than Eigen's
// SparseLU on a plate of 15 000 equations and 5× on 58 000, within 12 % of it on the DCB, ENF and MMB
// strips), the interface damage evaluated from the state of the last converged step. The conjugate force
// is P = tᵀ f(u) (virtual work: P dΔ = fᵀ du = fᵀ (t dΔ + T dy') and Tᵀ f = 0). A step whose iterations do
// not converge is halved, up to `max_cuts` times.
//
// The energy of the path: the work W = ∫ P dΔ (trapezoidal rule), the stored energy of the model and
// the energy its interfaces dissipated; W = stored + dissipated is the balance a test checks.
#include "plyimpact/fem/stacked_plate.hpp"

#include <Eigen/Core>
#include <functional>
#include <utility>
#include <vector>

namespace plyimpact {

/// A DOF moved by a loading rig: u_i = c_i Δ + a_i y_j, with y_j one of the rig's own coordinates, which
/// are unknowns like the free DOFs (e.g. the MMB lever: the hinge and the saddle follow the lever, whose
/// load point is at Δ; the lever's rotation is y).
struct RigDof {
  int equation = 0;                  ///< stacked equation i
  double delta_coefficient = 0.0;    ///< c_i
  int coordinate = 0;                ///< j, 0 ≤ j < ControlledDisplacement::rig_coordinates
  double coordinate_coefficient = 0; ///< a_i
};

/// u_i = c_i Δ for each (stacked equation i, coefficient c_i) in `dofs`, and the rig's DOFs.
struct ControlledDisplacement {
  std::vector<std::pair<int, double>> dofs;
  std::vector<RigDof> rig;
  int rig_coordinates = 0;
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
[[nodiscard]] DisplacementPath follow_displacement_path(const StackedPlate& model,
                                                        const ControlledDisplacement& control,
                                                        StackedPlateState state,
                                                        const DisplacementPathSettings& settings,
                                                        const PathObserver& observe = {});

} // namespace plyimpact
