// A plate on a support it may lift off (analysis/contact/unilateral_support.hpp), checked on the propped
// cantilever of beam theory: a strip clamped at x = 0 and resting on a unilateral support at x = a.
// Pressed onto the support it is the propped cantilever (the support pushes with 3/8 of the load, the
// same answer as a bilateral support); pulled away from it, the support lets go and the strip is a
// plain cantilever (tip deflection q a⁴/(8 E I) per unit width).
#include "plyimpact/analysis/plate_analyses/buckling_analysis.hpp"
#include "plyimpact/analysis/plate_analyses/modal_analysis.hpp"
#include "plyimpact/analysis/plate_analyses/static_analysis.hpp"
#include "support/decks.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>

namespace plyimpact::unilateral_support_tests {
namespace {

// Isotropic strip, ν = 0 so that it bends as a beam; a/h = 100, so shear adds (h/a)² ~ 1e-4.
constexpr double E = 70e9, a = 0.2, b = 0.02, h = 0.002, q = 1.0e3;

DiscretePlate strip(std::string_view prop) {
  BoundaryConditions bc = BoundaryConditions::on_edges("clamped", prop, "free", "free");
  return {test::laminate_of(test::isotropic(E, 0.0, 2700.0), "[0]", h), {a, b}, {40, 2}, std::move(bc)};
}

StaticResult pressed(const DiscretePlate& model, double pressure) {
  StaticLoad load;
  load.pressure = pressure;
  return solve_static(model, load);
}

TEST(UnilateralSupport, PressedOntoThePropItIsTheProppedCantileverWithThreeEighthsOfTheLoadOnIt) {
  const StaticResult one_way = pressed(strip("unilateral"), q);
  const StaticResult both_ways = pressed(strip("ss-soft"), q);
  ASSERT_FALSE(one_way.support_contacts.empty());
  EXPECT_EQ(touching_count(one_way.support_contacts), static_cast<int>(one_way.support_contacts.size()));
  for (const SupportContact& c : one_way.support_contacts)
    EXPECT_LE(c.reaction, 0.0) << "the prop only pushes (against +z) at node " << c.node;
  // Same contact set as the bilateral prop, so the same solution (one solve each, same equations).
  EXPECT_NEAR(one_way.max_abs_deflection, both_ways.max_abs_deflection, 1e-12 * both_ways.max_abs_deflection);
  const double prop_force = -total_reaction(one_way.support_contacts);
  std::printf("  prop force %.6e N, 3 q a b / 8 = %.6e N\n", prop_force, 3.0 / 8.0 * q * a * b);
  EXPECT_NEAR(prop_force / (3.0 / 8.0 * q * a * b), 1.0, 2e-3) << "propped cantilever: R = 3 q a b / 8";
}

TEST(UnilateralSupport, PulledOffThePropItLetsGoAndTheStripIsACantilever) {
  const StaticResult r = pressed(strip("unilateral"), -q);
  EXPECT_EQ(touching_count(r.support_contacts), 0);
  for (const SupportContact& c : r.support_contacts) {
    EXPECT_EQ(c.reaction, 0.0);
    EXPECT_LT(c.w, 0.0) << "the tip lifts off (against +z) at node " << c.node;
  }
  const double I = h * h * h / 12.0; // per unit width
  const double tip = q * a * a * a * a / (8.0 * E * I);
  std::printf("  lift-off %.6e m, q a^4 / (8 E I) = %.6e m, %d solves\n",
              largest_lift_off(r.support_contacts), tip, r.contact_set_solves);
  EXPECT_NEAR(largest_lift_off(r.support_contacts) / tip, 1.0, 2e-3) << "cantilever: w = q a⁴ / (8 E I)";
  EXPECT_GE(r.contact_set_solves, 2) << "it started in contact and had to let go";
}

TEST(UnilateralSupport, TheOtherAnalysesRefuseItAndSayWhatToGiveInstead) {
  const DiscretePlate model = strip("unilateral");
  try {
    (void)solve_modal(model, 3);
    FAIL() << "a modal analysis with a support that may lift off must be refused";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("ss-soft"), std::string::npos) << e.what();
  }
  BucklingSettings compression;
  compression.Nx = -1.0;
  EXPECT_THROW((void)solve_buckling(model, compression), std::invalid_argument);
}

} // namespace
} // namespace plyimpact::unilateral_support_tests
