// The layered section between the plate element and the ply law (fem/layered_section.hpp): the undamaged
// section is the laminate's ABD and F of (1.24)/(1.25) (two Gauss points per ply integrate z² exactly),
// the Hashin screen bounds every undamaged ply point's index from above (so a point it lets through
// cannot initiate), and a held evaluation records the loaded modes the strain chooses.
#include "plyimpact/fem/layered_section.hpp"
#include "plyimpact/laminate/ply_stiffness.hpp"
#include "support/decks.hpp"
#include "support/hashin_index.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

namespace plyimpact::layered_section_tests {
namespace {

constexpr double ply_thickness = 0.125e-3;

Laminate quasi_isotropic() {
  std::vector<Ply> plies;
  for (const double angle : {0.0, 45.0, 90.0, -45.0, -45.0, 90.0, 45.0, 0.0})
    plies.push_back({angle, ply_thickness, 0});
  return Laminate({test::t300_976_with_damage_data()}, plies);
}

/// The ply strain in material axes by rotating the strain tensor (not the code's T_ε).
Eigen::Vector3d material_strain(const Eigen::Vector3d& plate, double angle_deg) {
  const double t = angle_deg * std::acos(-1.0) / 180.0;
  Eigen::Matrix2d R;
  R << std::cos(t), std::sin(t), -std::sin(t), std::cos(t);
  Eigen::Matrix2d eps;
  eps << plate(0), 0.5 * plate(2), 0.5 * plate(2), plate(1);
  const Eigen::Matrix2d m = R * eps * R.transpose();
  return {m(0, 0), m(1, 1), 2.0 * m(0, 1)};
}

/// The active Hashin index (fibre or matrix, by the signs of σ11 and σ22) of an undamaged ply at z.
double active_index(const Laminate& lam, std::size_t k, double z, const GeneralizedStrain& e) {
  const Material& m = lam.materials()[lam.plies()[k].material];
  const Eigen::Vector3d plate = e.head<3>() + z * e.segment<3>(3);
  return test::active_hashin_index(reduced_stiffness(m) * material_strain(plate, lam.plies()[k].angle_deg),
                                   m.strength);
}

TEST(LayeredSection, UndamagedSectionIsTheLaminatesStiffness) {
  const Laminate lam = quasi_isotropic();
  const LayeredSection section(lam, lam.materials(), {});
  std::vector<PlyDamageState> committed(section.states_per_point()), trial(committed.size());
  std::vector<double> scratch(section.group_count());
  GeneralizedStrain e;
  e << 1e-5, -2e-5, 3e-5, 0.4, -0.2, 0.1, 1e-5, -1e-5; // far below every surface
  PerDamageMode dissipated;
  const LayeredSection::Increment r =
      section.advance(committed, trial, e, 1e-3, 0.0, 1.0, dissipated, scratch);
  const SectionStiffness exact = section_stiffness(lam);
  EXPECT_FALSE(r.initiated);
  EXPECT_EQ(dissipated.sum(), 0.0);
  EXPECT_LE((r.secant.C_mb - exact.C_mb).norm(), 1e-12 * exact.C_mb.norm());
  EXPECT_LE((r.secant.F - exact.F).norm(), 1e-12 * exact.F.norm());
}

TEST(LayeredSection, HashinScreenBoundsEveryUndamagedPlyPointFromAbove) {
  const Laminate lam = quasi_isotropic();
  const LayeredSection section(lam, lam.materials(), {});
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> strain(-8e-3, 8e-3), curvature(-8.0, 8.0);
  int initiating = 0;
  for (int trial_no = 0; trial_no < 300; ++trial_no) {
    GeneralizedStrain e = GeneralizedStrain::Zero();
    for (int i = 0; i < 3; ++i) {
      e(i) = strain(rng);
      e(3 + i) = curvature(rng);
    }
    const double bound = section.onset_bound(e.head<6>());
    double largest = 0.0; // over each ply's faces, middle and Gauss points
    for (std::size_t k = 0; k < lam.ply_count(); ++k) {
      const double top = lam.z_top(k), bottom = lam.z_bottom(k), t = bottom - top;
      for (const double z :
           {top, bottom, 0.5 * (top + bottom), 0.5 * (top + bottom) - t / (2.0 * std::sqrt(3.0)),
            0.5 * (top + bottom) + t / (2.0 * std::sqrt(3.0))})
        largest = std::max(largest, active_index(lam, k, z, e));
    }
    EXPECT_GE(bound, largest * (1.0 - 1e-12)) << "strain " << e.transpose();
    std::vector<PlyDamageState> committed(section.states_per_point()), next(committed.size());
    std::vector<double> scratch(section.group_count());
    PerDamageMode dissipated;
    const bool initiated = section.advance(committed, next, e, 1e-5, 0.0, 1.0, dissipated, scratch).initiated;
    if (initiated) ++initiating;
    if (bound < 1.0) {
      EXPECT_FALSE(initiated) << "the screen let an initiating point through";
    }
  }
  EXPECT_GT(initiating, 30); // the strains reach the surfaces often enough for the check to mean something
}

TEST(LayeredSection, HeldEvaluationRecordsTheLoadedModesTheStrainChooses) {
  const Laminate lam = quasi_isotropic();
  const LayeredSection section(lam, lam.materials(), {});
  const std::vector<PlyDamageState> committed(section.states_per_point());
  std::vector<unsigned char> modes(committed.size(), 0);
  GeneralizedStrain tension = GeneralizedStrain::Zero();
  tension << 1e-4, 1e-4, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0; // every ply in biaxial tension
  EXPECT_FALSE(section.held(committed, modes, tension).modes_changed);
  const GeneralizedStrain compression = -tension;
  const LayeredSection::Held h = section.held(committed, modes, compression);
  EXPECT_TRUE(h.modes_changed);
  EXPECT_TRUE(std::all_of(modes.begin(), modes.end(), [](unsigned char m) { return m == 3; }));
  EXPECT_FALSE(section.held(committed, modes, compression).modes_changed);
  // With virgin states the held secant is the undamaged section whatever the modes.
  const SectionStiffness exact = section_stiffness(lam);
  EXPECT_LE((h.secant.C_mb - exact.C_mb).norm(), 1e-12 * exact.C_mb.norm());
}

} // namespace
} // namespace plyimpact::layered_section_tests
