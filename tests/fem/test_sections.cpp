// Sections per element (issue 15): a plate whose elements carry different laminates. Two regions with
// the same laminate are the one-region plate bit for bit; a strip in cylindrical bending with a
// thickness step at mid-span matches the stepped Timoshenko beam.
#include "plyimpact/analysis/plate_analyses/static_analysis.hpp"
#include "plyimpact/fem/discrete_plate.hpp"
#include "plyimpact/fem/loads.hpp"
#include "plyimpact/fem/regions.hpp"
#include "plyimpact/fem/structured_mesh.hpp"
#include "support/decks.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>

namespace plyimpact::sections_tests {
namespace {

DiscretePlate two_region_plate(const Laminate& left, const Laminate& right, const PlateGeometry& plate,
                               int nx, int ny, const BoundaryConditions& bc) {
  Mesh mesh = structured_rectangle(plate, nx, ny);
  const Region r{"right", 1, plate.a / 2, plate.a, 0.0, plate.b};
  std::vector<int> of_element = element_laminates(mesh, {r});
  return {std::move(mesh), PlateSections{{left, right}, std::move(of_element)},
          Discretization{MassMatrix::lumped, ElementFormulation::q9}, bc};
}

TEST(Sections, RegionsAreAssignedByElementCentre) {
  const Mesh mesh = structured_rectangle({0.2, 0.1}, 4, 2);
  const std::vector<int> s = element_laminates(mesh, {{"pad", 1, 0.1, 0.2, 0.0, 0.05}});
  // Elements numbered along x first: row 0 is y in (0, 0.05), the right half x in (0.1, 0.2).
  EXPECT_EQ(s, (std::vector<int>{0, 0, 1, 1, 0, 0, 0, 0}));
}

TEST(Sections, TwoRegionsWithTheSameLaminateAreTheOneRegionPlateBitForBit) {
  const Laminate lam = test::laminate_of(test::thesis_3_6(), "[45/90/-45/0]3s", 0.19375e-3);
  const PlateGeometry plate{0.127, 0.0762};
  const BoundaryConditions bc = test::all_edges("ss");
  const DiscretePlate one(lam, plate, {15, 11, MassMatrix::lumped, ElementFormulation::q9}, bc);
  const DiscretePlate two = two_region_plate(lam, lam, plate, 15, 11, bc);
  ASSERT_FALSE(two.single_section());
  const auto same = [](const SparseMatrix& a, const SparseMatrix& b) {
    return a.nonZeros() == b.nonZeros() &&
           std::equal(a.valuePtr(), a.valuePtr() + a.nonZeros(), b.valuePtr()) &&
           std::equal(a.innerIndexPtr(), a.innerIndexPtr() + a.nonZeros(), b.innerIndexPtr());
  };
  EXPECT_TRUE(same(one.stiffness(), two.stiffness()));
  EXPECT_TRUE(same(one.mass(), two.mass()));
}

/// The stepped simply supported beam with shear deformation under a uniform load q per unit width:
/// bending stiffness D(x) and shear stiffness S(x) per unit width, D1, S1 for x < L/2 and D2, S2 beyond.
/// Unit-load method (exact for Timoshenko beams): w(ξ) = ∫ M m_ξ / D dx + ∫ V v_ξ / S dx, with
/// M = q x (L − x)/2, V = q (L/2 − x) and m_ξ, v_ξ the moment and shear of a unit force at ξ. The
/// integrands are polynomials of degree ≤ 3 between the breakpoints 0, ξ, L/2, L: 3-point Gauss
/// quadrature on each piece is exact.
double stepped_beam_deflection(double xi, double L, double q, double D1, double S1, double D2, double S2) {
  std::array<double, 4> breaks{0.0, std::min(xi, L / 2), std::max(xi, L / 2), L};
  const double g[3] = {-std::sqrt(0.6), 0.0, std::sqrt(0.6)}, wg[3] = {5.0 / 9.0, 8.0 / 9.0, 5.0 / 9.0};
  double w = 0.0;
  for (std::size_t p = 0; p + 1 < breaks.size(); ++p) {
    const double x0 = breaks[p], x1 = breaks[p + 1];
    for (int k = 0; k < 3; ++k) {
      const double x = 0.5 * (x0 + x1) + 0.5 * (x1 - x0) * g[k], weight = 0.5 * (x1 - x0) * wg[k];
      const double M = q * x * (L - x) / 2, V = q * (L / 2 - x);
      const double m = x <= xi ? x * (L - xi) / L : xi * (L - x) / L;
      const double v = x < xi ? (L - xi) / L : -xi / L;
      const bool left = x < L / 2;
      w += weight * (M * m / (left ? D1 : D2) + V * v / (left ? S1 : S2));
    }
  }
  return w;
}

TEST(Sections, SteppedStripInCylindricalBendingMatchesTheSteppedTimoshenkoBeam) {
  // A 200 × 20 mm cross-ply strip, 1 mm thick ([0/90]s) for x < 100 mm and 2 mm ([0/90]2s) beyond,
  // simply supported at x = 0 and x = L (u held at x = 0 only: B = 0, so it carries no bending),
  // symmetry (v = θy = 0) on the long edges: cylindrical bending, w(x) alone. Per unit width the beam
  // has D = D11 and S = F55 (shear correction included).
  const Laminate thin = test::laminate_of(test::t300_976(), "[0/90]s", 0.25e-3);
  const Laminate thick = test::laminate_of(test::t300_976(), "[0/90]2s", 0.25e-3);
  const double L = 0.2, b = 0.02, q = 1.0e3;
  const BoundaryConditions bc = BoundaryConditions::on_edges("11101", "ss", "01001", "01001");
  const DiscretePlate model = two_region_plate(thin, thick, {L, b}, 20, 2, bc);
  const StaticResult r = solve_static(model, StaticLoad{q, std::nullopt, std::nullopt});
  for (const double xi : {L / 4, L / 2, 3 * L / 4}) {
    const double fe = model.sampler(xi, b / 2).value(r.u);
    const double beam =
        stepped_beam_deflection(xi, L, q, thin.D()(0, 0), thin.F()(1, 1), thick.D()(0, 0), thick.F()(1, 1));
    std::printf("  x = %5.1f mm: plate %.6e m, stepped Timoshenko beam %.6e m (relative difference %.1e)\n",
                xi * 1e3, fe, beam, fe / beam - 1.0);
    // The issue asks 0.5 %; quadratic elements reproduce the stepped beam to round-off (4e-11 measured).
    EXPECT_NEAR(fe / beam, 1.0, 1e-8) << "x = " << xi;
  }
}

} // namespace
} // namespace plyimpact::sections_tests
