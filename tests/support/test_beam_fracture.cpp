// Tests of the beam-theory references for delamination (tests/support/beam_fracture.hpp): limiting
// cases against textbook beam formulas written out here (Euler–Bernoulli cantilever, three-point
// bending with Timoshenko shear), Irwin–Kies G = P²/(2b) dC/da by finite differences of the coded
// compliance, the energy balance along each propagation branch (work of the load minus the elastic
// energy left = toughness × new crack area), the ENF stability limit, and the ASTM D6671 lever.
#include "support/beam_fracture.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <vector>

namespace beam_fracture_tests {

namespace bf = plyimpact::test::beam_fracture;

namespace {

// AS4/PEEK moduli (Camanho, Dávila & de Moura 2003) on a specimen of typical size: 25 mm wide,
// 2 × 1.56 mm thick, half span 50 mm.
bf::Specimen as4_peek_beam() {
  return {.width = 25e-3, .arm_thickness = 1.56e-3, .E11 = 122.7e9, .E22 = 10.1e9, .G13 = 5.5e9};
}
constexpr double G_Ic = 969.0;
constexpr double G_IIc = 1719.0;
constexpr double eta = 2.284;
constexpr double L = 50e-3;

/// dC/da by central differences with one Richardson step: exact for the cubic compliances here up to
/// round-off (the O(h²) error of a cubic is exactly c·h², which the extrapolation removes).
double compliance_slope(const std::function<double(double)>& C, double a) {
  const double h = 1e-3 * a;
  const auto central = [&](double step) { return (C(a + step) - C(a - step)) / (2.0 * step); };
  return (4.0 * central(0.5 * h) - central(h)) / 3.0;
}

/// Work ∫ P dδ along a polyline of load points (trapezoidal rule; the branches are sampled finely).
double work_along(const std::vector<bf::LoadPoint>& path) {
  double work = 0.0;
  for (std::size_t i = 1; i < path.size(); ++i) {
    work += 0.5 * (path[i].force + path[i - 1].force) * (path[i].displacement - path[i - 1].displacement);
  }
  return work;
}

} // namespace

// =================================================================================================
// Williams' correction
// =================================================================================================

// Hand values: isotropic ν = 0.3 (E/G = 2.6): Γ = 3.068, χ = 0.6635; AS4/PEEK: χ = 1.7091. The
// isotropic value is 3.8 % above Kanninen's beam on an elastic foundation, Δ = h/6^(1/4) = 0.6389 h,
// which leaves out the arm's shear deformation; and a shear-rigid arm (G13 → ∞) needs no correction.
TEST(BeamFractureWilliams, ChiMatchesHandValuesAndLimits) {
  bf::Specimen iso{.width = 1.0, .arm_thickness = 1.0, .E11 = 1.0, .E22 = 1.0, .G13 = 1.0 / 2.6};
  EXPECT_NEAR(bf::williams_chi(iso), 0.66348, 1e-5);
  const double kanninen = 1.0 / std::pow(6.0, 0.25);
  EXPECT_GT(bf::williams_chi(iso), kanninen);
  EXPECT_LT(bf::williams_chi(iso), 1.05 * kanninen);

  EXPECT_NEAR(bf::williams_chi(as4_peek_beam()), 1.70914, 1e-5);

  bf::Specimen rigid = as4_peek_beam();
  rigid.G13 = 1e8 * rigid.E11;
  EXPECT_LT(bf::williams_chi(rigid), 1e-4);
  EXPECT_NEAR(bf::enf_crack_correction(as4_peek_beam()), 0.42 * bf::dcb_crack_correction(as4_peek_beam()),
              1e-18);
}

// =================================================================================================
// DCB
// =================================================================================================

// Δ = 0 is two Euler–Bernoulli cantilevers: opening δ = 2 P a³ / (3 E I), I = b h³/12; and as the arm
// becomes shear-rigid the CBT compliance tends to it.
TEST(BeamFractureDcb, WithoutCorrectionIsTwoEulerBernoulliCantilevers) {
  const bf::Specimen s = as4_peek_beam();
  const double a = 35e-3;
  const double I = s.width * std::pow(s.arm_thickness, 3) / 12.0;
  const double cantilevers = 2.0 * a * a * a / (3.0 * s.E11 * I);
  EXPECT_NEAR(bf::compliance(bf::Dcb{s, a, 0.0}, a), cantilevers, 1e-12 * cantilevers);

  bf::Specimen stiff = s;
  stiff.G13 = 1e8 * s.E11;
  const double corrected = bf::compliance(bf::Dcb{stiff, a, bf::dcb_crack_correction(stiff)}, a);
  EXPECT_NEAR(corrected, cantilevers, 1e-5 * cantilevers);
  // The real correction: (1 + χh/a)³ = 1.24 for this specimen.
  const double cbt = bf::compliance(bf::Dcb{s, a, bf::dcb_crack_correction(s)}, a);
  EXPECT_NEAR(cbt / cantilevers, std::pow(1.0 + 1.70914 * s.arm_thickness / a, 3), 1e-5);
}

// Irwin–Kies: G = P²/(2b) dC/da from the coded compliance equals the coded G_I to 1e-10.
TEST(BeamFractureDcb, EnergyReleaseRateIsComplianceDerivative) {
  const bf::Specimen s = as4_peek_beam();
  for (const double delta : {0.0, bf::dcb_crack_correction(s)}) {
    const bf::Dcb dcb{s, 35e-3, delta};
    for (const double a : {20e-3, 35e-3, 60e-3}) {
      const double P = 50.0;
      const double slope = compliance_slope([&](double x) { return bf::compliance(dcb, x); }, a);
      const double G = P * P / (2.0 * s.width) * slope;
      EXPECT_NEAR(bf::energy_release_rate(dcb, a, P), G, 1e-10 * G);
    }
  }
}

// The propagation branch: at every crack length G_I = G_Ic, the explicit P(δ) agrees with the
// parametric point, the curve is continuous at the peak, and the crack correction moves the peak along
// the same branch (P(δ) does not depend on Δ).
TEST(BeamFractureDcb, PropagationBranchIsConsistent) {
  const bf::Specimen s = as4_peek_beam();
  const bf::Dcb cbt{s, 35e-3, bf::dcb_crack_correction(s)};
  const bf::Dcb euler{s, 35e-3, 0.0};
  for (const double a : {35e-3, 50e-3, 80e-3}) {
    const bf::LoadPoint p = bf::propagation(cbt, a, G_Ic);
    EXPECT_NEAR(bf::energy_release_rate(cbt, a, p.force), G_Ic, 1e-12 * G_Ic);
    EXPECT_NEAR(bf::propagation_force(cbt, p.displacement, G_Ic), p.force, 1e-12 * p.force);
    EXPECT_NEAR(bf::propagation_force(euler, p.displacement, G_Ic), p.force, 1e-12 * p.force);
  }
  const bf::LoadPoint peak = bf::propagation(cbt, cbt.initial_crack, G_Ic);
  EXPECT_NEAR(bf::force(cbt, peak.displacement * (1.0 - 1e-12), G_Ic), peak.force, 1e-9 * peak.force);
  EXPECT_NEAR(bf::force(cbt, peak.displacement * (1.0 + 1e-12), G_Ic), peak.force, 1e-9 * peak.force);
  // CBT lowers the peak force and raises its opening (softer specimen, same branch).
  const bf::LoadPoint euler_peak = bf::propagation(euler, euler.initial_crack, G_Ic);
  EXPECT_LT(peak.force, euler_peak.force);
  EXPECT_GT(peak.displacement, euler_peak.displacement);
}

// Energy balance of the quasi-static test: the work of P along the curve (elastic, then propagation)
// minus the elastic energy ½ P δ left at the end is G_Ic × b × (a − a0), to 1e-8.
TEST(BeamFractureDcb, WorkMinusStoredEnergyIsToughnessTimesNewCrackArea) {
  const bf::Specimen s = as4_peek_beam();
  const bf::Dcb dcb{s, 35e-3, bf::dcb_crack_correction(s)};
  const double a_end = 70e-3;
  std::vector<bf::LoadPoint> path{{0.0, 0.0, dcb.initial_crack}};
  const int n = 20000;
  for (int i = 0; i <= n; ++i) {
    const double a = dcb.initial_crack + (a_end - dcb.initial_crack) * i / n;
    const bf::LoadPoint p = bf::propagation(dcb, a, G_Ic);
    // The branch sampled through the opening, via the explicit P(δ) of the whole curve.
    path.push_back({bf::force(dcb, p.displacement, G_Ic), p.displacement, a});
  }
  const bf::LoadPoint& end = path.back();
  const double dissipated = work_along(path) - 0.5 * end.force * end.displacement;
  const double expected = G_Ic * s.width * (a_end - dcb.initial_crack);
  EXPECT_NEAR(dissipated, expected, 1e-8 * expected);
}

// =================================================================================================
// ENF
// =================================================================================================

// No crack (a → 0, Δ = 0) is three-point bending of the 2h beam over the span 2L:
// δ/P = (2L)³/(48 E I) + (2L)/(4 k G A), I = b (2h)³/12, A = 2bh, k = 5/6 (Timoshenko).
TEST(BeamFractureEnf, UncrackedLimitIsThreePointBending) {
  const bf::Specimen s = as4_peek_beam();
  const double span = 2.0 * L;
  const double I = s.width * std::pow(2.0 * s.arm_thickness, 3) / 12.0;
  const double bending = span * span * span / (48.0 * s.E11 * I);
  const double shear = span / (4.0 * (5.0 / 6.0) * s.G13 * 2.0 * s.width * s.arm_thickness);
  const double a = 1e-9 * L;
  EXPECT_NEAR(bf::compliance(bf::Enf{s, L, a, 0.0, false}, a), bending, 1e-12 * bending);
  EXPECT_NEAR(bf::compliance(bf::Enf{s, L, a, 0.0, true}, a), bending + shear, 1e-12 * bending);
  // The shear term is 2.7 % of the bending one for AS4/PEEK at h/L = 0.031: 1.2 (E11/G13)(h/L)².
  EXPECT_NEAR(shear / bending, 1.2 * s.E11 / s.G13 * std::pow(s.arm_thickness / L, 2), 1e-12);
}

// Irwin–Kies for the ENF, with the crack correction and the span's shear compliance (which does not
// depend on a and so does not enter G_II).
TEST(BeamFractureEnf, EnergyReleaseRateIsComplianceDerivative) {
  const bf::Specimen s = as4_peek_beam();
  for (const bool shear : {false, true}) {
    const bf::Enf enf{s, L, 30e-3, bf::enf_crack_correction(s), shear};
    for (const double a : {15e-3, 30e-3, 45e-3}) {
      const double P = 500.0;
      const double slope = compliance_slope([&](double x) { return bf::compliance(enf, x); }, a);
      const double G = P * P / (2.0 * s.width) * slope;
      EXPECT_NEAR(bf::energy_release_rate(enf, a, P), G, 1e-10 * G);
    }
  }
}

// Under displacement control the ENF crack grows stably only beyond a_e = (K0/6)^(1/3): Euler–Bernoulli
// gives a/L = 3^(−1/3) = 0.6934 (Carlsson et al. 1986: "a/L > 0.7"); on the branch δ(a) has its
// minimum there (snap-back before, stable after), and the limit moves with Δ and the shear term.
TEST(BeamFractureEnf, StabilityLimitIsTheMinimumOfTheBranchOpening) {
  const bf::Specimen s = as4_peek_beam();
  EXPECT_NEAR(bf::stable_crack_length(bf::Enf{s, L, 0.3 * L, 0.0, false}) / L, 0.693361, 1e-6);
  for (const bool shear : {false, true}) {
    const bf::Enf enf{s, L, 0.3 * L, bf::enf_crack_correction(s), shear};
    const double a_star = bf::stable_crack_length(enf);
    const double at = bf::propagation(enf, a_star, G_IIc).displacement;
    EXPECT_GT(bf::propagation(enf, 0.99 * a_star, G_IIc).displacement, at);
    EXPECT_GT(bf::propagation(enf, 1.01 * a_star, G_IIc).displacement, at);
    EXPECT_LT(a_star, 0.6934 * L); // the crack-tip correction shortens it more than shear lengthens it
  }
}

// Energy balance along the ENF branch, through the snap-back (a0/L = 0.4 to 0.9): the work of P along
// the parametric curve minus ½ P δ left is G_IIc × b × (a − a0).
TEST(BeamFractureEnf, WorkMinusStoredEnergyIsToughnessTimesNewCrackAreaThroughSnapBack) {
  const bf::Specimen s = as4_peek_beam();
  const bf::Enf enf{s, L, 0.4 * L, bf::enf_crack_correction(s), true};
  const double a_end = 0.9 * L;
  const bf::LoadPoint peak = bf::propagation(enf, enf.initial_crack, G_IIc);
  std::vector<bf::LoadPoint> path{{0.0, 0.0, enf.initial_crack}};
  const int n = 20000;
  for (int i = 0; i <= n; ++i) {
    path.push_back(bf::propagation(enf, enf.initial_crack + (a_end - enf.initial_crack) * i / n, G_IIc));
  }
  EXPECT_LT(bf::propagation(enf, 0.5 * L, G_IIc).displacement, peak.displacement); // it does snap back
  const bf::LoadPoint& end = path.back();
  const double dissipated = work_along(path) - 0.5 * end.force * end.displacement;
  const double expected = G_IIc * s.width * (a_end - enf.initial_crack);
  EXPECT_NEAR(dissipated, expected, 1e-8 * expected);
}

// =================================================================================================
// MMB
// =================================================================================================

// The ASTM D6671 lever gives the mode-II fraction asked for; c = L/3 is pure mode II; a very long lever
// tends to G_I/G_II = 12 β² (the DCB part dominates but never alone).
TEST(BeamFractureMmb, AstmLeverGivesTheRequestedModeMixity) {
  const bf::Specimen s = as4_peek_beam();
  bf::Mmb mmb{s, L, 0.0, 30e-3, bf::dcb_crack_correction(s), bf::enf_crack_correction(s), true};
  const double a = 30e-3;
  for (const double m : {0.2, 0.5, 0.8, 1.0}) {
    mmb.lever = bf::lever_for_mode_II_fraction(mmb, a, m);
    EXPECT_NEAR(bf::mode_II_fraction(mmb, a), m, 1e-12) << "m = " << m;
  }
  mmb.lever = L / 3.0;
  EXPECT_NEAR(bf::energy_release_rate_I(mmb, a, 100.0), 0.0, 1e-12);
  mmb.lever = 1e7 * L;
  const double beta = (a + mmb.crack_correction_I) / (a + mmb.crack_correction_II);
  const double ratio = bf::energy_release_rate_I(mmb, a, 1.0) / bf::energy_release_rate_II(mmb, a, 1.0);
  EXPECT_NEAR(ratio, 12.0 * beta * beta, 1e-5 * ratio);
}

// Reeder & Crews' closed forms, written out here: G_I = 3P²(3c − L)²(a + χh)²/(4 b² h³ L² E11),
// G_II = 9P²(c + L)²(a + 0.42χh)²/(16 b² h³ L² E11); and G_I + G_II = P²/(2b) dC/da for the lever
// compliance (Irwin–Kies on the superposition).
TEST(BeamFractureMmb, EnergyReleaseRatesMatchReederCrewsAndComplianceDerivative) {
  const bf::Specimen s = as4_peek_beam();
  const double c = 0.6 * L;
  const bf::Mmb mmb{s, L, c, 30e-3, bf::dcb_crack_correction(s), bf::enf_crack_correction(s), true};
  const double b = s.width;
  const double h3 = std::pow(s.arm_thickness, 3);
  const double P = 200.0;
  for (const double a : {25e-3, 30e-3, 40e-3}) {
    const double aI = a + mmb.crack_correction_I;
    const double aII = a + mmb.crack_correction_II;
    const double G_I = 3.0 * P * P * std::pow(3.0 * c - L, 2) * aI * aI / (4.0 * b * b * h3 * L * L * s.E11);
    const double G_II = 9.0 * P * P * std::pow(c + L, 2) * aII * aII / (16.0 * b * b * h3 * L * L * s.E11);
    EXPECT_NEAR(bf::energy_release_rate_I(mmb, a, P), G_I, 1e-12 * G_I);
    EXPECT_NEAR(bf::energy_release_rate_II(mmb, a, P), G_II, 1e-12 * G_II);
    const double slope = compliance_slope([&](double x) { return bf::compliance(mmb, x); }, a);
    EXPECT_NEAR(P * P / (2.0 * b) * slope, G_I + G_II, 1e-10 * (G_I + G_II));
  }
}

// Energy balance along the MMB branch with B-K: the mixity drifts a little as the crack grows (β
// depends on a), so the dissipated energy is b ∫ G_c(m(a)) da, integrated here by Simpson's rule.
TEST(BeamFractureMmb, WorkMinusStoredEnergyIsBKToughnessIntegratedOverNewCrack) {
  const bf::Specimen s = as4_peek_beam();
  bf::Mmb mmb{s, L, 0.0, 30e-3, bf::dcb_crack_correction(s), bf::enf_crack_correction(s), true};
  mmb.lever = bf::lever_for_mode_II_fraction(mmb, mmb.initial_crack, 0.5);
  const double a_end = 45e-3;
  const int n = 20000; // even, for Simpson
  std::vector<bf::LoadPoint> path{{0.0, 0.0, mmb.initial_crack}};
  double toughness_integral = 0.0;
  const double da = (a_end - mmb.initial_crack) / n;
  for (int i = 0; i <= n; ++i) {
    const double a = mmb.initial_crack + da * i;
    path.push_back(bf::propagation(mmb, a, G_Ic, G_IIc, eta));
    const double G_c = G_Ic + (G_IIc - G_Ic) * std::pow(bf::mode_II_fraction(mmb, a), eta);
    EXPECT_NEAR(bf::energy_release_rate_I(mmb, a, path.back().force) +
                    bf::energy_release_rate_II(mmb, a, path.back().force),
                G_c, 1e-12 * G_c);
    const double weight = (i == 0 || i == n) ? 1.0 : (i % 2 == 1 ? 4.0 : 2.0);
    toughness_integral += weight * G_c * da / 3.0;
  }
  // The mixity drifts from 0.5 at a0 (the lever was set there) as the crack grows.
  EXPECT_NE(bf::mode_II_fraction(mmb, a_end), 0.5);
  const bf::LoadPoint& end = path.back();
  const double dissipated = work_along(path) - 0.5 * end.force * end.displacement;
  const double expected = s.width * toughness_integral;
  EXPECT_NEAR(dissipated, expected, 1e-8 * expected);
}

} // namespace beam_fracture_tests
