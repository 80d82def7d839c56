// Free vibration of the stacked plate (issue 19, "consistency"): with interfaces that hold, the
// sub-laminates tied by the cohesive penalty vibrate as the single laminate — the lowest frequencies
// of a clamped [0/90]s plate cut at both orientation changes within the 0.5 % where both models
// assume the same shear distribution.
#include "plyimpact/analysis/plate_analyses/modal_analysis.hpp"
#include "plyimpact/fem/stacked_plate.hpp"
#include "plyimpact/fem/structured_mesh.hpp"
#include "support/as4_peek.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

namespace plyimpact::stacked_plate_modes_tests {
namespace {

/// Ratios stacked/single of the `count` lowest frequencies of the clamped 100 mm square plate `lam` cut at
/// its orientation changes, interfaces that hold.
std::vector<double> frequency_ratios(const Laminate& lam, double ply, int count) {
  const double a = 0.1;
  const Mesh mesh = structured_rectangle({a, a}, 8, 8);
  const auto clamped = [](int) {
    return BoundaryConditions::on_edges("clamped", "clamped", "clamped", "clamped");
  };
  const DiscretePlate single(mesh, PlateSections{{lam}, {}}, {}, clamped(0));
  const StackedPlate stack(mesh, lam,
                           StackSettings{interfaces_between_orientations(lam), test::as4_peek_interface(ply)},
                           {}, clamped);
  EXPECT_EQ(stack.sublaminate_count(), 3);

  const ModalResult one = solve_modal(single, count);
  // The interfaces' elastic stiffness: the tangent of the virgin stack at rest (symmetric, K·I per point).
  const SparseMatrix K = stack.evaluate(Eigen::VectorXd::Zero(stack.size()), stack.virgin_state()).tangent;
  const ModalResult stacked = solve_modal(K, stack.mass(), count);
  std::vector<double> ratios;
  for (int i = 0; i < count; ++i) {
    const auto k = static_cast<std::size_t>(i);
    ratios.push_back(stacked.frequencies_hz[k] / one.frequencies_hz[k]);
    std::printf("[ measured ] mode %d: single %.2f Hz, stacked %.2f Hz, ratio %.5f\n", i + 1,
                one.frequencies_hz[k], stacked.frequencies_hz[k], ratios.back());
  }
  EXPECT_EQ(stacked.zero_energy_modes, 0); // the interfaces leave no sub-laminate free to float
  return ratios;
}

TEST(StackedPlateModes, WithInterfacesThatHoldTheLowestFrequenciesAreTheSingleLaminates) {
  // Plies whose transverse shear moduli are equal (G23 = G13): the single laminate's parabolic shear
  // behind 5/6 is the one the sub-laminates' corrections (DL0) assume, and the two models agree.
  const double ply = 0.5e-3; // 2 mm thick: a/h = 50
  Material m = test::as4_peek();
  m.G23 = m.G13;
  std::vector<Ply> plies;
  for (const double angle : {0.0, 90.0, 90.0, 0.0})
    plies.push_back({angle, ply, 0});
  for (const double ratio : frequency_ratios(Laminate({m}, plies), ply, 4))
    EXPECT_NEAR(ratio, 1.0, 5e-3);
}

TEST(StackedPlateModes, AStackWithSofterMiddlePliesIsSofterThanTheSingleLaminatesFiveSixths) {
  // AS4/PEEK [0/90]s: in the x–z plane the middle 90° plies shear with G23 = 3.5 GPa, the outer 0° plies
  // with G13 = 5.5 GPa. The middle carries most of the shear force, so the single laminate's 5/6 on the
  // averaged modulus overestimates the shear stiffness; the stack, whose sub-laminates shear each with
  // their own modulus, is softer in every mode (docs/delamination.md, "Consistency": by 0.18–0.56 %).
  const double ply = 0.5e-3;
  for (const double ratio : frequency_ratios(test::as4_peek_cross_ply(ply), ply, 4)) {
    EXPECT_LT(ratio, 1.0);
    EXPECT_GT(ratio, 0.99);
  }
}

} // namespace
} // namespace plyimpact::stacked_plate_modes_tests
