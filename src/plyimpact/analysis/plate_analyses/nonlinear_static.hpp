#pragma once
// Geometrically non-linear static analysis (SPEC §8; thesis (2.44)–(2.103)): incremental load
// stepping with full Newton–Raphson on K_T(u) Δu = λ f − f_int(u), convergence on both the residual
// and the displacement correction, automatic halving of a load step whose iterations fail.
#include "plyimpact/analysis/plate_analyses/static_analysis.hpp"
#include "plyimpact/fem/nonlinear_plate_element.hpp"

#include <array>
#include <stdexcept>
#include <vector>

namespace plyimpact {

struct NonlinearSettings {
  StrainMeasure measure = StrainMeasure::von_karman;
  int load_steps = 10; ///< equal increments of the load factor λ (static)
  /// Load factors to converge at, increasing in (0, 1] and ending at 1; when given they replace the
  /// equal `load_steps` increments (a load–deflection curve at chosen loads in one run).
  std::vector<double> load_factors;
  int max_iterations = 25;              ///< Newton iterations per load step
  double residual_tolerance = 1e-8;     ///< ‖λ f − f_int‖ ≤ tol · ‖λ f‖
  double displacement_tolerance = 1e-8; ///< ‖Δu‖ ≤ tol · ‖u‖
  int max_step_cuts = 12;               ///< halvings of one load increment before giving up
};

/// Newton–Raphson failed even after cutting the load step: the message says where and why.
class NewtonFailure : public std::runtime_error {
public:
  using std::runtime_error::runtime_error;
};

struct NonlinearStaticResult {
  StaticResult state;                                 ///< at load factor 1
  std::vector<std::array<double, 2>> load_deflection; ///< [λ, w(a/2, b/2)], from [0, 0]
  int newton_iterations = 0;                          ///< total over all load steps
  int max_iterations_per_step = 0;
  int step_cuts = 0;
};

/// Throws InsufficientRestraint (as solve_static) and NewtonFailure.
[[nodiscard]] NonlinearStaticResult solve_static_nonlinear(const DiscretePlate& model, const StaticLoad& load,
                                                           const NonlinearSettings& settings = {});

} // namespace plyimpact
