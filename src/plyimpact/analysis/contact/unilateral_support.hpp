#pragma once
// A plate resting on a support it may lift off (a drop-weight rig's window frame): the static solution
// with the contact set found by active-set iterations.
//
// The support only pushes: at a node of a unilateral set, either the plate touches it (w = 0 and the
// support's force on the plate R ≤ 0, i.e. against the impact direction +z of SPEC §1) or it has lifted
// off (w < 0 and R = 0). Start with every node in contact; solve with the touching nodes held in w;
// release the nodes the support would have to pull (R > 0), take back the lifted-off nodes that would
// sink into it (w > 0); repeat until the set stops changing. The problem is a linear complementarity
// problem with a positive-definite matrix, so the solution is unique; the iteration finds it in a few
// passes on the plates we meet (a cap stops it otherwise, with a message).
#include "plyimpact/fem/discrete_plate.hpp"
#include "plyimpact/fem/loads.hpp"

#include <Eigen/Core>
#include <vector>

namespace plyimpact {

/// One node of a unilateral support at the solution.
struct SupportContact {
  int node = -1;
  bool touching = true;
  double reaction = 0.0; ///< the support's force on the plate along z [N]; ≤ 0 where it touches
  double w = 0.0;        ///< deflection [m]; 0 where it touches, < 0 where the plate has lifted off
};

struct UnilateralSolution {
  Eigen::VectorXd u; ///< free DOFs of the model (the unilateral nodes' w among them)
  std::vector<SupportContact> contacts;
  int iterations = 0; ///< solves made
};

[[nodiscard]] int touching_count(const std::vector<SupportContact>& contacts);
/// max of −w over the support's nodes [m] (0 when nothing lifts off).
[[nodiscard]] double largest_lift_off(const std::vector<SupportContact>& contacts);
/// Σ R, the support's total force on the plate along z [N].
[[nodiscard]] double total_reaction(const std::vector<SupportContact>& contacts);

/// The static solution of `model` under `load` with its unilateral sets (BoundaryConditions) in contact
/// where they push. Throws InsufficientRestraint when the plate lifts off everything that held it.
[[nodiscard]] UnilateralSolution solve_unilateral_static(const DiscretePlate& model, const StaticLoad& load);

} // namespace plyimpact
