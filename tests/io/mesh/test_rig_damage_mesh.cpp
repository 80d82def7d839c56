// A rig struck with progressive ply damage or delamination is meshed for its damage (io/deck/deck_plate.cpp,
// size_rig_for_damage; analysis/fields/damage_zone.hpp): within five laminate thicknesses of the impact point
// no element's √area exceeds 90 % of the plies' smallest band limit, 2 G_mc E2 / Yc² for these plies (DZ1),
// so that neither the band-limit error nor lowered strengths meet the damage there; a deck that sizes the
// rig's mesh itself keeps it.
#include "plyimpact/io/deck/deck.hpp"

#include <gtest/gtest.h>

#include <fmt/format.h>

#include <cmath>
#include <string>

namespace plyimpact::rig_damage_mesh_tests {
namespace {

/// The T700/M21-like plies of bench/decks/coupon-threads.toml, 8 plies of 0.125 mm (h = 1 mm) on the
/// ASTM rig, 2 kg at 1 J, with `rest` appended.
Deck coupon(const std::string& rest) {
  return parse_deck(fmt::format(R"(nonlinear = true
[materials.T700_M21]
E1 = 130.0e9
E2 = 7.7e9
G12 = 4.8e9
nu12 = 0.3
rho = 1580.0
Xt = 2500.0e6
Xc = 1200.0e6
Yt = 50.0e6
Yc = 200.0e6
S12 = 80.0e6
S23 = 75.4e6
G_ft = 133.0e3
G_fc = 40.0e3
G_mt = 600.0
G_mc = 2100.0
[laminate]
material = "T700_M21"
layup = "[0/45/90/-45]s"
ply_thickness = 0.125e-3
[rig]
preset = "astm-d7136"
[impactor]
mass = 2.0
E = 207e9
nu = 0.3
energy = 1.0
{})",
                                rest),
                    "coupon.toml");
}

const std::string progressive = "[damage]\nmodel = \"progressive\"\nintegration = \"explicit\"\n";

/// The largest √area of the elements whose centre lies within `radius` of the coupon's centre [m].
double largest_side_within(const Mesh& mesh, double radius) {
  double largest = 0.0;
  for (int e = 0; e < mesh.element_count(); ++e)
    if ((mesh.map(e, 0.0, 0.0) - Eigen::Vector2d(0.075, 0.05)).norm() <= radius)
      largest = std::max(largest, std::sqrt(mesh.element_area(e)));
  return largest;
}

TEST(RigDamageMesh, TheZoneUnderTheImpactorMeetsTheBandLimitOfThePlies) {
  const Deck plain = coupon("");
  const Deck damaged = coupon(progressive);
  const double band_limit = 2.0 * 2100.0 * 7.7e9 / (200e6 * 200e6); // matrix compression, 0.8085 mm
  const double size = 0.9 * band_limit, zone = 5.0 * 1e-3;
  const double largest = largest_side_within(*damaged.file_mesh, zone - size);
  std::printf("[ measured ] %d elements (%d without damage); largest sqrt(area) within %.3g mm: %.4g mm "
              "(rule %.4g mm); the rig's own mesh there: %.4g mm\n",
              damaged.file_mesh->element_count(), plain.file_mesh->element_count(), (zone - size) * 1e3,
              largest * 1e3, size * 1e3, largest_side_within(*plain.file_mesh, zone - size) * 1e3);
  EXPECT_LE(largest, size);
  EXPECT_GT(largest, 0.7 * size);                                            // not finer than it needs
  EXPECT_GT(largest_side_within(*plain.file_mesh, zone - size), band_limit); // what it replaces
  EXPECT_NE(damaged.rig_description.find("for the damage: the band limit of matrix-compression of T700_M21"),
            std::string::npos)
      << damaged.rig_description;
  EXPECT_NE(
      damaged.rig_description.find(fmt::format("; {} elements, at most", damaged.file_mesh->element_count())),
      std::string::npos)
      << damaged.rig_description;
  // Away from the zone the rig's grading takes over: its largest elements are the rig's 5 mm cap.
  EXPECT_GT(largest_side_within(*damaged.file_mesh, 1.0), 4e-3);
}

TEST(RigDamageMesh, ADeckThatSizesTheRigsMeshKeepsIt) {
  const Deck plain = coupon("");
  const Deck sized = coupon(progressive + "[mesh]\nsize_at_impact = 2.0e-3\nmax_size = 5.0e-3\n");
  EXPECT_TRUE(*sized.file_mesh == *plain.file_mesh); // the rig's own sizes, given
  EXPECT_EQ(sized.rig_description.find("for the damage"), std::string::npos);
}

TEST(RigDamageMesh, DelaminationAloneMeshesForThreePointsInTheCohesiveZone) {
  // The interfaces' law from the plies: G_Ic = G_mt = 600 J/m², N = Yt = 50 MPa, S = N √(G_IIc/G_Ic):
  // both modes' zones E2 G_c / τ² = 1.848 mm; three nodal points need sides of 2/3 of it, 1.232 mm.
  const Deck d = coupon("[delamination]\nintegration = \"explicit\"\n");
  const double size = 0.9 * 2.0 / 3.0 * 7.7e9 * 600.0 / (50e6 * 50e6);
  EXPECT_LE(largest_side_within(*d.file_mesh, 5e-3 - size), size);
  EXPECT_NE(d.rig_description.find("three interface points in the cohesive zone (1.85 mm)"),
            std::string::npos)
      << d.rig_description;
}

} // namespace
} // namespace plyimpact::rig_damage_mesh_tests
