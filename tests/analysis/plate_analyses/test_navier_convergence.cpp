// Finite-element static, modal and buckling answers converge to the Navier FSDT series
// (tests/support/navier.*) for simply supported symmetric cross-ply and isotropic plates.
#include "plyimpact/analysis/plate_analyses/buckling_analysis.hpp"
#include "plyimpact/analysis/plate_analyses/modal_analysis.hpp"
#include "plyimpact/analysis/plate_analyses/static_analysis.hpp"
#include "support/decks.hpp"
#include "support/navier.hpp"
#include "support/navier_plies.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>

namespace plyimpact::navier_convergence_tests {
namespace {

namespace nv = test::navier;

/// The Navier plate built independently from the material constants (0°/90° plies only).
nv::Plate navier_plate(const Material& m, const std::vector<double>& angles, double t, double a, double b) {
  return nv::plate_from_plies(a, b, test::navier_cross_ply(m, angles, t));
}

struct CrossPlyCase {
  Material material = test::t300_976();
  std::string layup = "[0_2/90_4/0_2]";
  double t = 0.465e-3, a = 0.127, b = 0.0762;
  [[nodiscard]] Laminate laminate() const { return test::laminate_of(material, layup, t); }
  [[nodiscard]] nv::Plate navier() const { return navier_plate(material, parse_layup(layup), t, a, b); }
  [[nodiscard]] DiscretePlate model(int n, ElementFormulation f,
                                    MassMatrix mass = MassMatrix::consistent) const {
    return {laminate(), {a, b}, {n, n, mass, f}, test::all_edges("ss")};
  }
};

double centre_deflection(const DiscretePlate& model, double q) {
  StaticLoad load;
  load.pressure = q;
  return solve_static(model, load).center_deflection;
}

class NavierConvergence : public ::testing::TestWithParam<ElementFormulation> {};

TEST_P(NavierConvergence, UniformPressureCentreDeflectionConvergesToTheSeries) {
  const CrossPlyCase c; // Annex 2 plate, T300/976 [0_2/90_4/0_2], a/h = 34
  const double q = 1e5;
  const double exact = nv::static_field(c.navier(), nv::uniform_load(q), c.a / 2, c.b / 2).w;
  double previous_error = 0.0;
  for (const int n : {2, 4, 8, 16}) {
    const double w = centre_deflection(c.model(n, GetParam()), q);
    const double error = std::abs(w / exact - 1.0);
    if (previous_error > 0.0)
      std::printf("  [%s] uniform pressure %2dx%-2d: w = %.6e m, error %.2e, observed rate %.2f\n",
                  GetParam() == ElementFormulation::q9 ? "q9" : "mitc9", n, n, w, error,
                  std::log2(previous_error / error));
    previous_error = error;
    if (n == 16) {
      EXPECT_LT(error, 0.005) << "16x16 centre deflection " << w << " vs Navier " << exact;
    }
  }
}

TEST_P(NavierConvergence, LowestFiveFrequenciesConvergeWithRotaryInertia) {
  const CrossPlyCase c;
  const auto exact = nv::lowest_frequencies(c.navier(), 5);
  std::vector<double> previous;
  for (const int n : {4, 8, 16}) {
    const ModalResult r = solve_modal(c.model(n, GetParam()), 5);
    ASSERT_EQ(r.frequencies_hz.size(), 5U);
    for (std::size_t k = 0; k < 5; ++k) {
      const double f_exact = exact[k].omega / (2 * std::numbers::pi);
      const double error = std::abs(r.frequencies_hz[k] / f_exact - 1.0);
      if (!previous.empty())
        std::printf("  [%s] mode %zu (m=%d, n=%d) %2dx%-2d: %.3f Hz vs %.3f Hz, error %.2e, rate %.2f\n",
                    GetParam() == ElementFormulation::q9 ? "q9" : "mitc9", k + 1, exact[k].m, exact[k].n, n,
                    n, r.frequencies_hz[k], f_exact, error, std::log2(previous[k] / error));
      if (n == 16) {
        EXPECT_LT(error, 0.005) << "mode " << k + 1;
      }
      if (previous.size() < 5) previous.resize(5);
      previous[k] = error;
    }
  }
}

TEST_P(NavierConvergence, NoShearLockingFromThickToVeryThin) {
  // Square isotropic plate at 8×8 elements: within 1 % of FSDT for a/h from 10 to 10 000, and the
  // Kirchhoff value w = 0.00406235 q a⁴/D is approached as the plate gets thin.
  const double E = 70e9, nu = 0.3, a = 1.0, q = 1.0;
  for (const double ratio : {10.0, 100.0, 1000.0, 10000.0}) {
    const double h = a / ratio;
    const nv::Plate plate = nv::isotropic_plate(a, a, h, E, nu, 2700.0);
    const double exact = nv::static_field(plate, nv::uniform_load(q), a / 2, a / 2).w;
    const Laminate lam = test::laminate_of(test::isotropic(E, nu, 2700.0), "[0]", h);
    const DiscretePlate model(lam, {a, a}, {8, 8, MassMatrix::consistent, GetParam()}, test::all_edges("ss"));
    const double w = centre_deflection(model, q);
    const double D = E * h * h * h / (12 * (1 - nu * nu));
    std::printf("  [%s] a/h = %6.0f: w/w_FSDT - 1 = %+.2e, w/w_Kirchhoff = %.5f\n",
                GetParam() == ElementFormulation::q9 ? "q9" : "mitc9", ratio, w / exact - 1.0,
                w / (0.00406235 * q * a * a * a * a / D));
    EXPECT_LT(std::abs(w / exact - 1.0), 0.01) << "a/h = " << ratio;
    if (ratio >= 1000.0) {
      EXPECT_NEAR(w / (0.00406235 * q * a * a * a * a / D), 1.0, 0.01);
    }
  }
}

TEST_P(NavierConvergence, ThinIsotropicFundamentalFrequencyIsTheKirchhoffValue) {
  const double E = 70e9, nu = 0.3, a = 1.0, h = 0.001, rho = 2700.0;
  const Laminate lam = test::laminate_of(test::isotropic(E, nu, rho), "[0]", h);
  const DiscretePlate model(lam, {a, a}, {16, 16, MassMatrix::consistent, GetParam()}, test::all_edges("ss"));
  const double D = E * h * h * h / (12 * (1 - nu * nu));
  const double omega1 = 2 * std::numbers::pi * std::numbers::pi / (a * a) * std::sqrt(D / (rho * h));
  EXPECT_NEAR(solve_modal(model, 1).frequencies_hz[0] * 2 * std::numbers::pi / omega1, 1.0, 0.005);
}

TEST_P(NavierConvergence, UniaxialBucklingOfAnIsotropicSquarePlate) {
  // N_cr = 4π² D / b² (Timoshenko & Gere), square simply supported plate, a/h = 100.
  const double E = 70e9, nu = 0.3, a = 0.5, h = 0.005;
  const Laminate lam = test::laminate_of(test::isotropic(E, nu, 2700.0), "[0]", h);
  const DiscretePlate model(lam, {a, a}, {12, 12, MassMatrix::consistent, GetParam()}, test::all_edges("ss"));
  BucklingSettings s;
  s.Nx = -1.0;
  s.count = 3;
  const double D = E * h * h * h / (12 * (1 - nu * nu));
  const double Ncr = 4 * std::numbers::pi * std::numbers::pi * D / (a * a);
  EXPECT_NEAR(solve_buckling(model, s).load_factors[0] / Ncr, 1.0, 0.01);
}

TEST_P(NavierConvergence, CrossPlyBiaxialBucklingMatchesTheSeries) {
  const CrossPlyCase c;
  BucklingSettings s;
  s.Nx = -1.0;
  s.Ny = -0.5;
  s.count = 3;
  const auto exact = nv::lowest_buckling_factor(c.navier(), s.Nx, s.Ny);
  const double lambda = solve_buckling(c.model(16, GetParam()), s).load_factors[0];
  std::printf("  [%s] biaxial buckling: FE %.6g, Navier %.6g (m=%d, n=%d)\n",
              GetParam() == ElementFormulation::q9 ? "q9" : "mitc9", lambda, exact.lambda, exact.m, exact.n);
  EXPECT_NEAR(lambda / exact.lambda, 1.0, 0.01);
}

TEST_P(NavierConvergence, FundamentalPeriodIsTheLowestElasticModeWithOrWithoutRigidModes) {
  // The impact's end-of-event rule needs only the lowest elastic period. A supported plate (K positive
  // definite) computes one mode, a free one seven, skipping its rigid-body modes: both must give the
  // lowest elastic frequency of the full modal analysis and, supported, of the Navier series.
  const CrossPlyCase c;
  const DiscretePlate supported = c.model(16, GetParam());
  const double f_navier = nv::lowest_frequencies(c.navier(), 1)[0].omega / (2 * std::numbers::pi);
  const double f_modal = solve_modal(supported, 5).frequencies_hz[0];
  EXPECT_NEAR(1.0 / fundamental_period(supported) / f_modal, 1.0, 1e-10);
  EXPECT_NEAR(1.0 / fundamental_period(supported) / f_navier, 1.0, 0.005);

  const DiscretePlate free{
      c.laminate(), {c.a, c.b}, {8, 6, MassMatrix::lumped, GetParam()}, test::all_edges("free")};
  const ModalResult all = solve_modal(free, 10);
  ASSERT_GE(all.zero_energy_modes, 3); // w, θx, θy rigid motions at least (in-plane ones too)
  const double f_elastic = all.frequencies_hz[static_cast<std::size_t>(all.zero_energy_modes)];
  ASSERT_GT(f_elastic, 0.0);
  EXPECT_NEAR(1.0 / fundamental_period(free) / f_elastic, 1.0, 1e-8);
}

INSTANTIATE_TEST_SUITE_P(Element, NavierConvergence,
                         ::testing::Values(ElementFormulation::q9, ElementFormulation::mitc9),
                         [](const ::testing::TestParamInfo<ElementFormulation>& p) {
                           return std::string(p.param == ElementFormulation::q9 ? "q9" : "mitc9");
                         });

} // namespace
} // namespace plyimpact::navier_convergence_tests
