// Free vibration of the stacked plate (issue 19, "consistency"): with interfaces that hold, the
// sub-laminates tied by the cohesive penalty vibrate as the single laminate — the lowest frequencies
// of a clamped [0/90]s AS4/PEEK plate cut at both orientation changes within the 0.5 %.
#include "plyimpact/analysis/modal_analysis.hpp"
#include "plyimpact/fem/stacked_plate.hpp"
#include "plyimpact/fem/structured_mesh.hpp"
#include "support/as4_peek.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

namespace plyimpact {
namespace {

TEST(StackedPlateModes, WithInterfacesThatHoldTheLowestFrequenciesAreTheSingleLaminates) {
  const double a = 0.1, ply = 0.5e-3; // 100 mm square, 2 mm thick: a/h = 50
  const Laminate lam = test::as4_peek_cross_ply(ply);
  const Mesh mesh = structured_rectangle({a, a}, 8, 8);
  const auto clamped = [](int) {
    return BoundaryConditions::on_edges("clamped", "clamped", "clamped", "clamped");
  };
  const PlateModel single(mesh, PlateSections{{lam}, {}}, {}, clamped(0));
  const StackedPlateModel stack(
      mesh, lam, StackSettings{interfaces_between_orientations(lam), test::as4_peek_interface(ply)}, {},
      clamped);
  ASSERT_EQ(stack.sublaminate_count(), 3);

  const int count = 4;
  const ModalResult one = solve_modal(single, count);
  // The interfaces' elastic stiffness: the tangent of the virgin stack at rest (symmetric, K·I per point).
  const SparseMatrix K = stack.evaluate(Eigen::VectorXd::Zero(stack.size()), stack.virgin_state()).tangent;
  const ModalResult stacked = solve_modal(K, stack.mass(), count);
  for (int i = 0; i < count; ++i) {
    const auto k = static_cast<std::size_t>(i);
    const double ratio = stacked.frequencies_hz[k] / one.frequencies_hz[k];
    std::printf("[ measured ] mode %d: single %.2f Hz, stacked %.2f Hz, ratio %.5f\n", i + 1,
                one.frequencies_hz[k], stacked.frequencies_hz[k], ratio);
    EXPECT_NEAR(ratio, 1.0, 5e-3) << "mode " << i + 1;
  }
  EXPECT_EQ(stacked.zero_energy_modes, 0); // the interfaces leave no sub-laminate free to float
}

} // namespace
} // namespace plyimpact
