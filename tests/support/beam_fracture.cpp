// Beam-theory closed forms of the DCB, ENF and MMB delamination specimens (see beam_fracture.hpp for
// the formulas and their sources).
#include "support/beam_fracture.hpp"

#include <cmath>
#include <stdexcept>

namespace plyimpact::test::beam_fracture {

namespace {

/// E11 b h³, the bending stiffness of one arm times 12.
double arm_stiffness(const Specimen& s) {
  return s.E11 * s.width * std::pow(s.arm_thickness, 3);
}

void require_positive_crack(double effective_crack) {
  if (!(effective_crack > 0.0))
    throw std::invalid_argument("beam_fracture: the effective crack length must be positive");
}

} // namespace

double williams_chi(const Specimen& s) {
  const double gamma = 1.18 * std::sqrt(s.E11 * s.E22) / s.G13;
  const double ratio = gamma / (1.0 + gamma);
  return std::sqrt(s.E11 / (11.0 * s.G13) * (3.0 - 2.0 * ratio * ratio));
}

double dcb_crack_correction(const Specimen& s) {
  return williams_chi(s) * s.arm_thickness;
}

double enf_crack_correction(const Specimen& s) {
  return 0.42 * williams_chi(s) * s.arm_thickness;
}

// --- DCB ------------------------------------------------------------------------------------------

double compliance(const Dcb& dcb, double a) {
  const double ae = a + dcb.crack_correction;
  require_positive_crack(ae);
  return 8.0 * ae * ae * ae / arm_stiffness(dcb.specimen);
}

double energy_release_rate(const Dcb& dcb, double a, double force) {
  const double ae = a + dcb.crack_correction;
  const double b = dcb.specimen.width;
  return 12.0 * force * force * ae * ae / (arm_stiffness(dcb.specimen) * b);
}

LoadPoint propagation(const Dcb& dcb, double a, double G_Ic) {
  const Specimen& s = dcb.specimen;
  const double ae = a + dcb.crack_correction;
  require_positive_crack(ae);
  const double Q = std::sqrt(G_Ic * s.E11 * std::pow(s.arm_thickness, 3) / 12.0);
  const double P = s.width * Q / ae;
  return {P, compliance(dcb, a) * P, a};
}

double propagation_force(const Dcb& dcb, double opening, double G_Ic) {
  const Specimen& s = dcb.specimen;
  const double h3 = std::pow(s.arm_thickness, 3);
  const double Q = std::sqrt(G_Ic * s.E11 * h3 / 12.0);
  return s.width * std::sqrt(8.0 * Q * Q * Q / (s.E11 * h3 * opening));
}

double force(const Dcb& dcb, double opening, double G_Ic) {
  const LoadPoint peak = propagation(dcb, dcb.initial_crack, G_Ic);
  if (opening <= peak.displacement) return opening / compliance(dcb, dcb.initial_crack);
  return propagation_force(dcb, opening, G_Ic);
}

// --- ENF ------------------------------------------------------------------------------------------

namespace {

/// Timoshenko shear compliance of the span, 3L/(10 G13 b h) (k = 5/6, section 2bh).
double span_shear_compliance(const Enf& enf) {
  if (!enf.transverse_shear) return 0.0;
  const Specimen& s = enf.specimen;
  return 3.0 * enf.half_span / (10.0 * s.G13 * s.width * s.arm_thickness);
}

} // namespace

double compliance(const Enf& enf, double a) {
  const double ae = a + enf.crack_correction;
  require_positive_crack(ae);
  const double L = enf.half_span;
  return (3.0 * ae * ae * ae + 2.0 * L * L * L) / (8.0 * arm_stiffness(enf.specimen)) +
         span_shear_compliance(enf);
}

double energy_release_rate(const Enf& enf, double a, double force) {
  const double ae = a + enf.crack_correction;
  const double b = enf.specimen.width;
  return 9.0 * force * force * ae * ae / (16.0 * arm_stiffness(enf.specimen) * b);
}

LoadPoint propagation(const Enf& enf, double a, double G_IIc) {
  const Specimen& s = enf.specimen;
  const double ae = a + enf.crack_correction;
  require_positive_crack(ae);
  const double P = 4.0 * s.width * std::sqrt(s.E11 * std::pow(s.arm_thickness, 3) * G_IIc) / (3.0 * ae);
  return {P, compliance(enf, a) * P, a};
}

double stable_crack_length(const Enf& enf) {
  const double L = enf.half_span;
  const double K0 = 2.0 * L * L * L + 8.0 * arm_stiffness(enf.specimen) * span_shear_compliance(enf);
  return std::cbrt(K0 / 6.0) - enf.crack_correction;
}

// --- MMB ------------------------------------------------------------------------------------------

namespace {

Dcb dcb_part(const Mmb& mmb) {
  return {mmb.specimen, mmb.initial_crack, mmb.crack_correction_I};
}

Enf enf_part(const Mmb& mmb) {
  return {mmb.specimen, mmb.half_span, mmb.initial_crack, mmb.crack_correction_II, mmb.transverse_shear};
}

} // namespace

double mode_I_force(const Mmb& mmb, double force) {
  const double L = mmb.half_span;
  return force * (3.0 * mmb.lever - L) / (4.0 * L);
}

double mode_II_force(const Mmb& mmb, double force) {
  const double L = mmb.half_span;
  return force * (mmb.lever + L) / L;
}

double energy_release_rate_I(const Mmb& mmb, double a, double force) {
  return energy_release_rate(dcb_part(mmb), a, mode_I_force(mmb, force));
}

double energy_release_rate_II(const Mmb& mmb, double a, double force) {
  return energy_release_rate(enf_part(mmb), a, mode_II_force(mmb, force));
}

double mode_II_fraction(const Mmb& mmb, double a) {
  const double G_I = energy_release_rate_I(mmb, a, 1.0);
  const double G_II = energy_release_rate_II(mmb, a, 1.0);
  return G_II / (G_I + G_II);
}

double lever_for_mode_II_fraction(const Mmb& mmb, double a, double m) {
  if (!(m > 0.0 && m <= 1.0))
    throw std::invalid_argument("beam_fracture: the mode-II fraction must be in (0, 1]");
  const double alpha = (1.0 - m) / m;
  const double beta = (a + mmb.crack_correction_I) / (a + mmb.crack_correction_II);
  const double root = std::sqrt(3.0 * alpha);
  const double denominator = 36.0 * beta * beta - 3.0 * alpha;
  if (!(denominator > 0.0)) {
    throw std::invalid_argument(
        "beam_fracture: no lever gives so small a mode-II fraction (G_I/G_II < 12 β²)");
  }
  return mmb.half_span * (12.0 * beta * beta + 3.0 * alpha + 8.0 * beta * root) / denominator;
}

double compliance(const Mmb& mmb, double a) {
  const double share_I = mode_I_force(mmb, 1.0);
  const double share_II = mode_II_force(mmb, 1.0);
  return compliance(dcb_part(mmb), a) * share_I * share_I +
         compliance(enf_part(mmb), a) * share_II * share_II;
}

LoadPoint propagation(const Mmb& mmb, double a, double G_Ic, double G_IIc, double eta) {
  const double m = mode_II_fraction(mmb, a);
  const double G_c = G_Ic + (G_IIc - G_Ic) * std::pow(m, eta);
  const double G_per_unit_force = energy_release_rate_I(mmb, a, 1.0) + energy_release_rate_II(mmb, a, 1.0);
  const double P = std::sqrt(G_c / G_per_unit_force);
  return {P, compliance(mmb, a) * P, a};
}

} // namespace plyimpact::test::beam_fracture
