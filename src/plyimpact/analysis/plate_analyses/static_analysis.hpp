#pragma once
// Linear static analysis: K u = f for point, patch and pressure loads (SPEC §8).
#include "plyimpact/analysis/contact/unilateral_support.hpp"
#include "plyimpact/fem/discrete_plate.hpp"
#include "plyimpact/fem/loads.hpp"
#include "plyimpact/fem/spd_solver.hpp"

#include <stdexcept>

namespace plyimpact {

/// The plate cannot carry the load: rigid-body motions or mechanisms are left free. The message
/// names them and what to restrain.
class InsufficientRestraint : public std::runtime_error {
public:
  using std::runtime_error::runtime_error;
};

struct StaticResult {
  Eigen::VectorXd u;                  ///< free DOFs
  double center_deflection = 0.0;     ///< w at the centre of the plate (a/2, b/2) [m]
  double load_point_deflection = 0.0; ///< w under the point (or patch centre) load [m]; centre if none
  double max_abs_deflection = 0.0;    ///< max |w| over the nodes [m]
  /// The nodes of unilateral supports (empty without): touching or lifted off, and the support's force.
  std::vector<SupportContact> support_contacts;
  int contact_set_solves = 0; ///< solves of the active-set iteration (0 without unilateral supports)
};

/// Factors K and checks it; throws InsufficientRestraint with advice when it is singular.
[[nodiscard]] SpdSolver factor_stiffness(const DiscretePlate& model, const SparseMatrix& K,
                                         SparseSolverKind kind = SparseSolverKind::simplicial_ldlt);

/// K u = f, or the contact problem of solve_unilateral_static when the model has unilateral supports.
[[nodiscard]] StaticResult solve_static(const DiscretePlate& model, const StaticLoad& load);

/// The result quantities of a plate state u (free DOFs) under `load`: centre, load-point and largest
/// deflections (shared by the linear and the non-linear static analyses).
[[nodiscard]] StaticResult static_result(const DiscretePlate& model, const StaticLoad& load,
                                         Eigen::VectorXd u);

} // namespace plyimpact
