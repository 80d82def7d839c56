// Bilinear mixed-mode cohesive law (see cohesive_law.hpp and docs/delamination.md).
//
// On a proportional path the equivalent traction–separation curve is a triangle: linear up to the
// onset separation Δ⁰ with slope K, linear softening to zero at Δᶠ. With d the damage,
//   τ = (1 − d) K δ  (opening and sliding),      d = Δᶠ (λ − Δ⁰) / (λ (Δᶠ − Δ⁰))  on the envelope,
// so that (1 − d) K λ falls linearly from K Δ⁰ at λ = Δ⁰ to 0 at λ = Δᶠ. The area of the triangle is
// ½ K Δ⁰ Δᶠ, set equal to the B-K toughness G_c(B): Δᶠ = 2 G_c / (K Δ⁰).
#include "plyimpact/laminate/cohesive_law.hpp"
#include "plyimpact/laminate/macaulay.hpp"

#include <fmt/format.h>

#include <cmath>
#include <stdexcept>
#include <string_view>

namespace plyimpact {

namespace {

void require_positive(std::string_view name, double value, std::string_view unit) {
  if (!(value > 0.0) || !std::isfinite(value)) {
    throw std::invalid_argument(
        fmt::format("cohesive law: {} must be positive and finite (in {}), got {}", name, unit, value));
  }
}

/// Number of mode mixities at which the constructor checks Δ⁰(B) < Δᶠ(B) (B = 0, 1/n, ..., 1).
constexpr int kMixityChecks = 1000;

} // namespace

double turon_penalty_stiffness(double E3, double sublaminate_thickness, double alpha) {
  require_positive("E3", E3, "Pa");
  require_positive("the sub-laminate thickness", sublaminate_thickness, "m");
  require_positive("alpha", alpha, "-");
  return alpha * E3 / sublaminate_thickness;
}

double cohesive_zone_length(double E_transverse, double G_c, double strength, double M) {
  require_positive("E_transverse", E_transverse, "Pa");
  require_positive("G_c", G_c, "J/m²");
  require_positive("the strength", strength, "Pa");
  require_positive("M", M, "-");
  return M * E_transverse * G_c / (strength * strength);
}

CohesiveLaw::CohesiveLaw(const CohesiveParameters& parameters) : p_(parameters) {
  require_positive("penalty_stiffness K", p_.penalty_stiffness, "Pa/m");
  require_positive("normal_strength N", p_.normal_strength, "Pa");
  require_positive("shear_strength S", p_.shear_strength, "Pa");
  require_positive("G_Ic", p_.G_Ic, "J/m²");
  require_positive("G_IIc", p_.G_IIc, "J/m²");
  require_positive("the B-K exponent eta", p_.bk_exponent, "-");
  if (!(p_.cracked_closing_fraction > 0.0 && p_.cracked_closing_fraction <= 1.0))
    throw std::invalid_argument(
        fmt::format("cohesive law: cracked_closing_fraction = {:g} must lie in (0, 1]: "
                    "the closing penalty of a cracked point as a fraction of K",
                    p_.cracked_closing_fraction));
  const double K = p_.penalty_stiffness;
  normal_onset_ = p_.normal_strength / K;
  shear_onset_ = p_.shear_strength / K;

  // The triangle must have its peak before its end: K Δ⁰² < 2 G_c, i.e. for pure modes
  // K > N²/(2 G_Ic) and K > S²/(2 G_IIc). For the B-K onset both sides are linear in B^η, so the pure
  // modes decide; for the quadratic onset the sampled mixities are a practical check.
  const auto check_mode = [&](double K_min, std::string_view mode) {
    if (!(K > K_min)) {
      throw std::invalid_argument(fmt::format(
          "cohesive law: penalty_stiffness K = {:g} Pa/m is too small for {}: the onset separation must "
          "come before the final one, which needs K > {:g} Pa/m",
          K, mode, K_min));
    }
  };
  check_mode(p_.normal_strength * p_.normal_strength / (2.0 * p_.G_Ic), "mode I (K > N²/(2 G_Ic))");
  check_mode(p_.shear_strength * p_.shear_strength / (2.0 * p_.G_IIc), "mode II (K > S²/(2 G_IIc))");
  for (int i = 0; i <= kMixityChecks; ++i) {
    const double B = static_cast<double>(i) / kMixityChecks;
    if (!(onset_separation(B) < final_separation(B))) {
      const double G_c = critical_energy_release_rate(B);
      // a toughness that is not a finite positive number comes from G_Ic and G_IIc, not from K (issue 77:
      // G_Ic = 1e300 cancelled in the B-K blend to 0, and the message blamed the penalty stiffness)
      if (!(G_c > 0.0) || !std::isfinite(G_c) || !std::isfinite(final_separation(B)))
        throw std::invalid_argument(fmt::format(
            "cohesive law: at mode mixity B = {:g} the Benzeggagh-Kenane toughness G_c = G_Ic + (G_IIc - "
            "G_Ic) B^eta = {:g} J/m² (G_Ic = {:g}, G_IIc = {:g} J/m², eta = {:g}) is not a usable "
            "toughness: check G_Ic and G_IIc, in J/m² (published values lie between 20 and 20 000)",
            B, G_c, p_.G_Ic, p_.G_IIc, p_.bk_exponent));
      throw std::invalid_argument(fmt::format(
          "cohesive law: at mode mixity B = {:g} the onset separation {:g} m is not below the final "
          "separation {:g} m; raise the penalty stiffness K = {:g} Pa/m",
          B, onset_separation(B), final_separation(B), K));
    }
  }
}

double CohesiveLaw::equivalent_separation(const Eigen::Vector3d& separation) {
  return std::hypot(separation(0), separation(1), macaulay(separation(2)));
}

double CohesiveLaw::mode_mixity(const Eigen::Vector3d& separation) {
  const double shear2 = separation(0) * separation(0) + separation(1) * separation(1);
  const double normal = macaulay(separation(2));
  const double total = shear2 + normal * normal;
  return total > 0.0 ? shear2 / total : 0.0;
}

// Benzeggagh & Kenane 1996 (Compos. Sci. Technol. 56:439).
double CohesiveLaw::critical_energy_release_rate(double B) const {
  return p_.G_Ic + (p_.G_IIc - p_.G_Ic) * std::pow(B, p_.bk_exponent);
}

double CohesiveLaw::onset_separation(double B) const {
  const double a = normal_onset_;
  const double b = shear_onset_;
  switch (p_.onset) {
  case CohesiveOnset::camanho_quadratic:
    return 1.0 / std::sqrt((1.0 - B) / (a * a) + B / (b * b));
  case CohesiveOnset::turon_bk:
    break;
  }
  return std::sqrt(a * a + (b * b - a * a) * std::pow(B, p_.bk_exponent));
}

double CohesiveLaw::onset_separation_slope(double B) const {
  const double a = normal_onset_;
  const double b = shear_onset_;
  const double onset = onset_separation(B);
  switch (p_.onset) {
  case CohesiveOnset::camanho_quadratic:
    // d(Δ⁰⁻²)/dB = 1/b² − 1/a²  ⇒  dΔ⁰/dB = ½ Δ⁰³ (1/a² − 1/b²).
    return 0.5 * onset * onset * onset * (1.0 / (a * a) - 1.0 / (b * b));
  case CohesiveOnset::turon_bk:
    break;
  }
  // Precondition B > 0 (the caller skips B = 0, where ∂B/∂δ = 0).
  const double eta = p_.bk_exponent;
  return (b * b - a * a) * eta * std::pow(B, eta - 1.0) / (2.0 * onset);
}

double CohesiveLaw::final_separation(double B) const {
  return 2.0 * critical_energy_release_rate(B) / (p_.penalty_stiffness * onset_separation(B));
}

double CohesiveLaw::elastic_limit(double loading_band) const {
  return (1.0 - 1e-12) * (1.0 - std::max(loading_band, 0.0)) * std::min(normal_onset_, shear_onset_);
}

double CohesiveLaw::envelope_damage(double lambda, double B) const {
  const double onset = onset_separation(B);
  const double failure = final_separation(B);
  if (lambda <= onset) return 0.0;
  if (lambda >= failure) return 1.0;
  return failure * (lambda - onset) / (lambda * (failure - onset));
}

double CohesiveLaw::envelope_separation(double d, double B) const {
  const double onset = onset_separation(B);
  const double failure = final_separation(B);
  return onset * failure / (failure - d * (failure - onset));
}

CohesiveResponse CohesiveLaw::at_fixed_damage(const CohesiveState& state,
                                              const Eigen::Vector3d& separation) const {
  const double K = p_.penalty_stiffness, d = state.damage;
  const double normal = separation(2);
  CohesiveResponse r;
  r.state = {d, separation};
  r.traction = (1.0 - d) * K * Eigen::Vector3d(separation(0), separation(1), macaulay(normal));
  r.tangent.diagonal() << (1.0 - d) * K, (1.0 - d) * K, (1.0 - d) * K;
  // Contact penalty K_n(d) (DL10): K, never softened, unless a fraction for cracked faces is asked. At
  // δ_n = 0 exactly the tangent is the opening one, so that an initial crack at rest (d = 1, δ = 0) starts
  // open rather than glued (the traction is 0 either way).
  if (normal < 0.0) {
    const double closing = closing_stiffness(d);
    r.traction(2) = closing * normal;
    r.tangent(2, 2) = closing;
  }
  return r;
}

CohesiveResponse CohesiveLaw::update(const CohesiveState& previous, const Eigen::Vector3d& separation,
                                     double loading_band) const {
  // An undamaged point below the smallest onset over the mixities, min(Δ⁰_I, Δ⁰_II) (both onset rules
  // lie between the two), and below the loading band under it: elastic, the numbers of the path below
  // without the mixity's powers (most points of an impact, every step).
  if (previous.damage == 0.0 && equivalent_separation(separation) < elastic_limit(loading_band))
    return at_fixed_damage(CohesiveState{0.0, separation}, separation);
  const double K = p_.penalty_stiffness;
  const double normal = separation(2);
  // The part of the separation that damage degrades: sliding and opening, not closing.
  const Eigen::Vector3d degradable(separation(0), separation(1), macaulay(normal));
  const double lambda = equivalent_separation(separation);
  const double B = mode_mixity(separation);

  const double trial = envelope_damage(lambda, B);
  const bool damage_grows = trial > previous.damage;
  const double d = damage_grows ? trial : previous.damage;

  CohesiveResponse r = at_fixed_damage(CohesiveState{d, separation}, separation);
  // Within the band just below the envelope the tangent is the loading one (the traction is not).
  const bool near_envelope = loading_band > 0.0 && d < 1.0 && lambda > 0.0 &&
                             lambda >= (1.0 - loading_band) * envelope_separation(d, B);
  if (!damage_grows && !near_envelope) return r; // elastic on the secant (1 − d) K: below the envelope

  const double onset = onset_separation(B);
  const double failure = final_separation(B);
  if (damage_grows) r.dissipated_energy = dissipation(previous, separation, d);
  if (d >= 1.0) return r; // past Δᶠ: d is stuck at 1 and does not vary with δ

  // Softening: τ = (1 − d(λ, B)) K δ̂ ⇒ ∂τ/∂δ = (1 − d) K I − K δ̂ ⊗ ∂d/∂δ.
  const double spread = failure - onset;
  const Eigen::Vector3d dlambda = degradable / lambda;
  Eigen::Vector3d dd = onset * failure / (lambda * lambda * spread) * dlambda;
  if (B > 0.0) {
    // B = sh²/(sh² + n²): ∂B/∂δ_s = 2 δ_s n²/(sh² + n²)², ∂B/∂δ_n = −2 n sh²/(sh² + n²)² (n = ⟨δ_n⟩).
    const double shear2 = separation(0) * separation(0) + separation(1) * separation(1);
    const double n = degradable(2);
    const double total2 = (shear2 + n * n) * (shear2 + n * n);
    const Eigen::Vector3d dB(2.0 * separation(0) * n * n / total2, 2.0 * separation(1) * n * n / total2,
                             -2.0 * n * shear2 / total2);
    const double eta = p_.bk_exponent;
    const double dGc_dB = (p_.G_IIc - p_.G_Ic) * eta * std::pow(B, eta - 1.0);
    const double donset_dB = onset_separation_slope(B);
    const double dfailure_dB =
        2.0 / K * (dGc_dB / onset - critical_energy_release_rate(B) * donset_dB / (onset * onset));
    // d = Δᶠ (λ − Δ⁰) / (λ (Δᶠ − Δ⁰)): partial derivatives in Δ⁰ and Δᶠ.
    const double dd_donset = failure * (lambda - failure) / (lambda * spread * spread);
    const double dd_dfailure = -onset * (lambda - onset) / (lambda * spread * spread);
    dd += (dd_donset * donset_dB + dd_dfailure * dfailure_dB) * dB;
  }
  r.tangent -= K * degradable * dd.transpose();
  // Closed, on a penalty that follows the damage (DL10): ∂(K_n δ_n)/∂δ gains −K (1 − ρ) δ_n ∂d/∂δ.
  if (normal < 0.0 && p_.cracked_closing_fraction < 1.0)
    r.tangent.row(2) -= K * (1.0 - p_.cracked_closing_fraction) * normal * dd.transpose();
  return r;
}

CohesiveResponse CohesiveLaw::step_mean(const CohesiveState& state, const Eigen::Vector3d& separation) const {
  const double K = p_.penalty_stiffness;
  const double opening = (1.0 - state.damage) * K; // of shear and opening at the held damage
  const Eigen::Vector3d& from = state.separation;
  CohesiveResponse r;
  r.state = {state.damage, separation};
  // (DL6) in shear: the mean of the two ends (ψ is quadratic there).
  r.traction = 0.5 * opening * (from + separation);
  r.tangent.diagonal().setConstant(0.5 * opening);
  // Normal: ψ_n(g) = ½ k(g) g², k = (1 − d) K opening, K_n(d) closing (DL10).
  const double closing = closing_stiffness(state.damage);
  const double g0 = from(2), g1 = separation(2);
  if ((g0 >= 0.0 && g1 >= 0.0) || (g0 <= 0.0 && g1 <= 0.0)) { // on one side of the kink
    const double k = g0 + g1 > 0.0 ? opening : closing;
    r.traction(2) = 0.5 * k * (g0 + g1);
    r.tangent(2, 2) = 0.5 * k;
    return r;
  }
  const auto stiffness = [&](double g) { return g > 0.0 ? opening : closing; };
  const double psi0 = 0.5 * stiffness(g0) * g0 * g0, psi1 = 0.5 * stiffness(g1) * g1 * g1;
  r.traction(2) = (psi1 - psi0) / (g1 - g0); // across the kink g1 − g0 ≠ 0
  r.tangent(2, 2) = (stiffness(g1) * g1 - r.traction(2)) / (g1 - g0);
  return r;
}

double CohesiveLaw::dissipation(const CohesiveState& previous, const Eigen::Vector3d& separation,
                                double d) const {
  // On each piece, ∫ ½ K λ² dd along the envelope of the piece's mixity B is linear in the envelope
  // separation: G_c(B) (λ(d₁) − λ(d₀)) / (Δᶠ − Δ⁰). The damage of a piece is capped at the increment's d.
  double damage = previous.damage;
  double dissipated = 0.0;
  for (int k = 1; k <= dissipation_pieces && damage < d; ++k) {
    const double s = static_cast<double>(k) / dissipation_pieces;
    const Eigen::Vector3d at = previous.separation + s * (separation - previous.separation);
    const double B = mode_mixity(at);
    const double reached =
        k == dissipation_pieces ? d : std::min(d, envelope_damage(equivalent_separation(at), B));
    if (reached <= damage) continue;
    dissipated += critical_energy_release_rate(B) *
                  (envelope_separation(reached, B) - envelope_separation(damage, B)) /
                  (final_separation(B) - onset_separation(B));
    // −∂ψ/∂d of the closing part, ½ (1 − ρ) K ⟨−δ_n⟩² (DL10): zero unless closed with ρ < 1.
    const double closed = macaulay(-at(2));
    dissipated += 0.5 * (1.0 - p_.cracked_closing_fraction) * p_.penalty_stiffness * closed * closed *
                  (reached - damage);
    damage = reached;
  }
  return dissipated;
}

double CohesiveLaw::stored_energy(const CohesiveState& state, const Eigen::Vector3d& separation) const {
  const double K = p_.penalty_stiffness;
  const double lambda = equivalent_separation(separation);
  const double closing = macaulay(-separation(2));
  return 0.5 * (1.0 - state.damage) * K * lambda * lambda +
         0.5 * closing_stiffness(state.damage) * closing * closing;
}

} // namespace plyimpact
