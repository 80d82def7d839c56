// Stress recovery (SPEC §5): ply stresses, exact ply averages, material-axis rotation, interface
// stresses and the equilibrium-based transverse shear, against hand calculation and the Navier series.
#include "plyimpact/analysis/fields/stress_recovery.hpp"
#include "plyimpact/analysis/plate_analyses/static_analysis.hpp"
#include "support/decks.hpp"
#include "support/navier.hpp"
#include "support/navier_plies.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

namespace plyimpact::stress_recovery_tests {
namespace {

namespace nv = test::navier;

GeneralizedStrains some_strains() {
  GeneralizedStrains e;
  e.membrane = Eigen::Vector3d(2e-4, -1e-4, 3e-4);
  e.curvature = Eigen::Vector3d(0.5, -0.2, 0.3);
  e.shear = Eigen::Vector2d(1e-3, -2e-3);
  return e;
}

TEST(StressRecovery, PlyAverageIsTheExactMeanOfTheLinearDistribution) {
  const Laminate lam = test::laminate_of(test::t300_976(), "[30/-45/0/90]", 0.3e-3);
  const GeneralizedStrains e = some_strains();
  for (std::size_t k = 0; k < lam.ply_count(); ++k) {
    Eigen::Vector3d mean = Eigen::Vector3d::Zero(); // midpoint rule with many samples
    const int n = 2000;
    for (int i = 0; i < n; ++i) {
      const double z = lam.z_top(k) + (i + 0.5) / n * (lam.z_bottom(k) - lam.z_top(k));
      mean += ply_stress(lam, k, e, z).in_plane / n;
    }
    EXPECT_LT((ply_average_stress(lam, k, e).in_plane - mean).norm(), 1e-9 * mean.norm()) << k;
  }
}

TEST(StressRecovery, MaterialAxisRotationKeepsTheInvariants) {
  const PlateAxesStress s{Eigen::Vector3d(120e6, -40e6, 25e6), Eigen::Vector2d(7e6, -3e6)};
  for (const double angle : {0.0, 30.0, 45.0, -45.0, 90.0, 117.0}) {
    const PlyStress m = to_material_axes(s, angle);
    EXPECT_NEAR(m.s11 + m.s22, 80e6, 1e-6) << angle;
    EXPECT_NEAR(m.s11 * m.s22 - m.t12 * m.t12, 120e6 * -40e6 - 25e6 * 25e6, 1e4 * 1e6) << angle;
    EXPECT_NEAR(m.t13 * m.t13 + m.t23 * m.t23, 49e12 + 9e12, 1.0) << angle;
  }
  const PlyStress at90 = to_material_axes(s, 90.0);
  EXPECT_DOUBLE_EQ(at90.s11, -40e6); // fibres along y
  EXPECT_DOUBLE_EQ(at90.s22, 120e6);
  EXPECT_DOUBLE_EQ(at90.t13, 7e6); // τ13 = τyz when fibres run along y
}

TEST(StressRecovery, InterfaceStressesAreContinuousInStrainAndJumpInStress) {
  const Laminate lam = test::laminate_of(test::t300_976(), "[0/90]", 0.5e-3);
  const GeneralizedStrains e = some_strains();
  const InterfaceStress i = interface_stress(lam, 0, e);
  // Both sides see the same strain ε0 + z κ at z = 0: ε = ε0.
  const PlyStress upper = to_material_axes({lam.Qbar(0) * e.membrane, lam.Qbar_shear(0) * e.shear}, 0.0);
  const PlyStress lower = to_material_axes({lam.Qbar(1) * e.membrane, lam.Qbar_shear(1) * e.shear}, 90.0);
  EXPECT_DOUBLE_EQ(i.upper.s11, upper.s11);
  EXPECT_DOUBLE_EQ(i.lower.s22, lower.s22);
}

std::vector<nv::Ply> navier_plies(const Material& m, const std::vector<double>& angles, double t) {
  return test::navier_cross_ply(m, angles, t);
}

struct CrossPlyPlate {
  Material m = test::t300_976();
  std::string layup = "[0_2/90_4/0_2]";
  double t = 0.465e-3, a = 0.127, b = 0.0762, q = 1e5;
};

TEST(StressRecovery, CentrePlyStressesConvergeToTheNavierSeries) {
  const CrossPlyPlate c;
  const std::vector<double> angles = parse_layup(c.layup);
  const auto plies = navier_plies(c.m, angles, c.t);
  const nv::StaticField exact =
      nv::static_field(nv::plate_from_plies(c.a, c.b, plies), nv::uniform_load(c.q), c.a / 2, c.b / 2);
  const Laminate lam = test::laminate_of(c.m, c.layup, c.t);
  for (const int n : {4, 8, 16}) {
    const DiscretePlate model(lam, {c.a, c.b}, {n, n, MassMatrix::consistent, ElementFormulation::q9},
                              test::all_edges("ss"));
    StaticLoad load;
    load.pressure = c.q;
    const StaticResult r = solve_static(model, load);
    const auto loc = *model.mesh().locate(c.a / 2, c.b / 2);
    const GeneralizedStrains e = model.element().strains(
        model.mesh().element_coordinates(loc.element), model.element_dofs(r.u, loc.element), loc.xi, loc.eta);
    double worst = 0.0;
    for (std::size_t k = 0; k < lam.ply_count(); ++k)
      for (const double z : {lam.z_top(k), lam.z_bottom(k)}) {
        const Eigen::Vector3d fe = ply_stress(lam, k, e, z).in_plane;
        const Eigen::Vector3d ref = nv::inplane_stress(plies[k], z, exact);
        // Relative to the largest stress through the thickness (the mid-plane value is zero).
        const double scale = nv::inplane_stress(plies[2], lam.z_top(2), exact).cwiseAbs().maxCoeff();
        worst = std::max(worst, (fe - ref).head<2>().cwiseAbs().maxCoeff() / scale);
      }
    std::printf("  centre ply stresses %2dx%-2d: worst relative error of sigma_x, sigma_y %.2e\n", n, n,
                worst);
    if (n == 16) {
      EXPECT_LT(worst, 0.01);
    }
  }
}

TEST(StressRecovery, EquilibriumShearIsTractionFreeCarriesQAndMatchesTheSeries) {
  // Near the edge x = 0, where Qx is largest: τxz(z) recovered from the 16×16 solution versus the
  // equilibrium integral of the Navier series (both FSDT).
  const CrossPlyPlate c;
  const std::vector<double> angles = parse_layup(c.layup);
  const auto plies = navier_plies(c.m, angles, c.t);
  // The first 2×2 (shear) Gauss point of the element next to the edge x = 0 at mid-width: where the
  // constitutive shear strain of the reduced-integrated element is most accurate.
  const double dx = c.a / 16, dy = c.b / 16, g = 0.57735026918962576451;
  const double x = dx * (1 - g) / 2, y = c.b / 2 + dy * (1 - g) / 2;
  nv::SeriesOptions opt;
  opt.max_index = 799;
  const nv::StaticField exact =
      nv::static_field(nv::plate_from_plies(c.a, c.b, plies), nv::uniform_load(c.q), x, y, opt);
  const Laminate lam = test::laminate_of(c.m, c.layup, c.t);
  const DiscretePlate model(lam, {c.a, c.b}, {16, 16, MassMatrix::consistent, ElementFormulation::q9},
                            test::all_edges("ss"));
  StaticLoad load;
  load.pressure = c.q;
  const StaticResult r = solve_static(model, load);
  const auto loc = *model.mesh().locate(x, y);
  const ElementCoordinates xy = model.mesh().element_coordinates(loc.element);
  const ElementVector ue = model.element_dofs(r.u, loc.element);
  const GeneralizedStrains e = model.element().strains(xy, ue, loc.xi, loc.eta);
  const Eigen::Vector2d Q = lam.F() * e.shear; // (Qy, Qx)
  std::vector<double> z;
  for (int i = 0; i <= 80; ++i)
    z.push_back(-lam.thickness() / 2 + lam.thickness() * i / 80.0);
  const auto tau = equilibrium_transverse_shear(lam, strain_gradients(xy, ue, loc.xi, loc.eta), Q, z);
  // Traction-free faces and the resultant.
  EXPECT_NEAR(tau.front()(1), 0.0, 1e-9 * std::abs(Q(1)) / lam.thickness());
  EXPECT_NEAR(tau.back()(1), 0.0, 1e-9 * std::abs(Q(1)) / lam.thickness());
  double integral = 0.0, peak_fe = 0.0, peak_exact = 0.0, shape_error = 0.0;
  for (std::size_t i = 1; i < z.size(); ++i)
    integral += 0.5 * (tau[i](1) + tau[i - 1](1)) * (z[i] - z[i - 1]);
  for (std::size_t i = 0; i < z.size(); ++i) {
    const double ref = nv::equilibrium_transverse_shear(plies, exact, z[i]).tau_xz;
    peak_fe = std::max(peak_fe, std::abs(tau[i](1)));
    peak_exact = std::max(peak_exact, std::abs(ref));
    shape_error = std::max(shape_error, std::abs(tau[i](1) / Q(1) - ref / exact.Qx)); // profile per unit Q
  }
  shape_error *= std::abs(exact.Qx) / peak_exact;
  std::printf(
      "  equilibrium tau_xz near the edge: peak FE %.4f MPa, Navier %.4f MPa (%+.2f %%); Qx FE %.2f N/m, "
      "Navier %.2f N/m; profile shape error %.2e\n",
      peak_fe / 1e6, peak_exact / 1e6, 100 * (peak_fe / peak_exact - 1), Q(1), exact.Qx, shape_error);
  EXPECT_NEAR(integral, Q(1), 2e-3 * std::abs(Q(1))); // trapezoids over 80 slices of a piecewise quadratic
  EXPECT_LT(shape_error, 0.01);                       // the through-thickness profile per unit shear force
  EXPECT_NEAR(peak_fe / peak_exact, 1.0, 0.02);
  // Constitutive shear is piecewise constant and jumps at interfaces; the recovered one does not.
  EXPECT_GT(peak_fe, 1.2 * std::abs(Q(1)) / lam.thickness()); // parabola-like peak above the mean
}

} // namespace
} // namespace plyimpact::stress_recovery_tests
