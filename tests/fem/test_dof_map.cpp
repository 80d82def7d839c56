// The equation numbering (fem/dof_map.hpp): node_dof inverts equation() on every free DOF of a supported
// plate, and refuses an equation that does not exist (restrained DOFs have none).
#include "plyimpact/fem/discrete_plate.hpp"
#include "support/decks.hpp"

#include <gtest/gtest.h>

#include <stdexcept>

namespace plyimpact::dof_map_tests {
namespace {

TEST(DofMap, NodeDofInvertsTheNumberingOfEveryFreeEquation) {
  const Laminate lam = test::laminate_of(test::t300_976(), "[0/90]s", 0.25e-3);
  const DiscretePlate model(lam, {0.12, 0.08}, {3, 2, MassMatrix::lumped, ElementFormulation::mitc9},
                            test::all_edges("ss"));
  const DofMap& dofs = model.dofs();
  ASSERT_LT(dofs.free_count(), dofs.total_count()); // the supports restrain some DOFs
  for (int e = 0; e < dofs.free_count(); ++e) {
    const auto [node, dof] = dofs.node_dof(e);
    EXPECT_EQ(dofs.equation(node, dof), e);
  }
  EXPECT_THROW((void)dofs.node_dof(-1), std::out_of_range);
  EXPECT_THROW((void)dofs.node_dof(dofs.free_count()), std::out_of_range);
}

} // namespace
} // namespace plyimpact::dof_map_tests
