// The elements a damage run needs (analysis/fields/damage_zone.hpp): with ply damage, the crack band's band
// limit 2 G E / σ₀² of the weakest mode (DZ1); with interfaces, three nodal interface points in the cohesive
// zone E2 G_c / τ² (DZ2), each less the 10 % margin; the zone five laminate thicknesses wide (DZ3). Checked
// against the formulas worked by hand for the T700/M21-like plies of the coupon (bench/decks).
#include "plyimpact/analysis/fields/damage_zone.hpp"
#include "plyimpact/laminate/layup.hpp"

#include <gtest/gtest.h>

namespace plyimpact::damage_zone_tests {
namespace {

Material t700_m21() {
  Material m;
  m.name = "T700_M21";
  m.E1 = 130.0e9;
  m.E2 = 7.7e9;
  m.G12 = 4.8e9;
  m.G13 = 4.8e9;
  m.G23 = 4.8e9;
  m.nu12 = 0.3;
  m.rho = 1580.0;
  m.strength.Xt = 2500e6;
  m.strength.Xc = 1200e6;
  m.strength.Yt = 50e6;
  m.strength.Yc = 200e6;
  m.strength.S12 = 80e6;
  m.strength.S23 = 75.4e6;
  m.toughness.G_ft = 133e3;
  m.toughness.G_fc = 40e3;
  m.toughness.G_mt = 600.0;
  m.toughness.G_mc = 2100.0;
  return m;
}

Laminate coupon() {
  std::vector<Ply> plies;
  for (const double angle : parse_layup("[0_2/45_2/90_2/-45_2]s"))
    plies.push_back({angle, 0.26e-3, 0});
  return {{t700_m21()}, plies};
}

TEST(DamageZone, PlyDamageTakesTheBandLimitOfItsWeakestModeLessTenPercent) {
  // Matrix compression: 2 G_mc E2 / Yc² = 2 · 2100 · 7.7e9 / (200e6)² = 0.8085 mm, below matrix tension's
  // pure shear 2 G_mt G12 / S12² = 0.9 mm and uniaxial 2 G_mt E2 / Yt² = 3.70 mm, and the fibre modes.
  const auto size = damage_element_size(coupon(), ProgressiveDamageSettings{}, std::nullopt);
  ASSERT_TRUE(size.has_value());
  EXPECT_NEAR(size->size, 0.9 * 2.0 * 2100.0 * 7.7e9 / (200e6 * 200e6), 1e-12);
  EXPECT_NE(size->reason.find("matrix-compression of T700_M21"), std::string::npos) << size->reason;
}

TEST(DamageZone, InterfacesTakeThreeNodalPointsInTheirCohesiveZone) {
  // The ply-derived law of the coupon: G_Ic 600, N = 50 MPa gives E2 G_Ic / N² = 1.848 mm; mode II
  // (G_IIc 2100, S = 93.54 MPa) the same by construction (S = N √(G_IIc/G_Ic)). Nodal points are half an
  // element side apart: three in 1.848 mm need sides of 2/3 of it.
  DelaminationSettings interfaces;
  interfaces.stack.interface.G_Ic = 600.0;
  interfaces.stack.interface.G_IIc = 2100.0;
  interfaces.stack.interface.normal_strength = 50e6;
  interfaces.stack.interface.shear_strength = 60e6; // mode II's zone 7.7e9 · 2100 / 60e6² = 4.49 mm
  const auto size = damage_element_size(coupon(), std::nullopt, interfaces);
  ASSERT_TRUE(size.has_value());
  const double zone = 7.7e9 * 600.0 / (50e6 * 50e6);
  EXPECT_NEAR(size->size, 0.9 * 2.0 / 3.0 * zone, 1e-12);
  // With Gauss points a third of a side apart, the side may be the zone itself.
  interfaces.stack.rule = CohesiveQuadrature::gauss;
  EXPECT_NEAR(damage_element_size(coupon(), std::nullopt, interfaces)->size, 0.9 * zone, 1e-12);
  // Both laws: the smaller size, here the plies' band limit.
  EXPECT_NEAR(damage_element_size(coupon(), ProgressiveDamageSettings{}, interfaces)->size,
              0.9 * 2.0 * 2100.0 * 7.7e9 / (200e6 * 200e6), 1e-12);
}

TEST(DamageZone, NoDamageLawNoSizeAndTheZoneIsFiveThicknesses) {
  EXPECT_FALSE(damage_element_size(coupon(), std::nullopt, std::nullopt).has_value());
  EXPECT_NEAR(damage_zone_radius(coupon()), 5.0 * 16 * 0.26e-3, 1e-15);
}

} // namespace
} // namespace plyimpact::damage_zone_tests
