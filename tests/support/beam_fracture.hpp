// Beam-theory closed forms of the three delamination specimens, the references the stacked-plate
// delamination model (issue 19) will be checked against: double cantilever beam (DCB, mode I), end
// notched flexure (ENF, mode II) and mixed-mode bending (MMB). Used only by the tests; depends on
// nothing but the C++ standard library.
//
// ----------------------------------------------------------------------------------------------------
// Conventions
// ----------------------------------------------------------------------------------------------------
//   * A unidirectional beam of width b, split at its mid-plane into two arms of thickness h each
//     (the specimen is 2h thick); E11 the axial (flexural) modulus, E22 = E33 transverse, G13 the
//     transverse shear modulus. Forces P are per specimen [N], displacements [m].
//   * a is the crack length: from the loaded end (DCB), from the support at the cracked end (ENF,
//     MMB). L is the half span (ENF, MMB), c the MMB lever length measured from the mid-span saddle.
//   * Energy release rate from the compliance C = δ/P: G = P²/(2b) dC/da (Irwin–Kies).
//
// ----------------------------------------------------------------------------------------------------
// DCB, corrected beam theory (CBT)
// ----------------------------------------------------------------------------------------------------
// Each arm is a cantilever of length a + Δ: the root of the arm is not clamped at the crack tip but
// rotates and shears in the uncracked part. Williams 1989 ("End corrections for orthotropic DCB
// specimens", Compos. Sci. Technol. 35:367) and Hashemi, Kinloch & Williams 1990 (Proc. R. Soc.
// Lond. A 427:173) give Δ = χ h with
//     χ = √( E11/(11 G13) · (3 − 2 (Γ/(1 + Γ))²) ),   Γ = 1.18 √(E11 E22) / G13.
// (This is the χ of ASTM D6671 for the MMB test as well.) Then
//     C = 8 (a + Δ)³ / (E11 b h³),   G_I = 12 P² (a + Δ)² / (E11 b² h³).
// Δ → 0 is Euler–Bernoulli beam theory. Propagation at G_I = G_Ic:
//     P = b √(G_Ic E11 h³/12) / (a + Δ),  and eliminating a:  P(δ) = b √(8 Q³ / (E11 h³ δ)),
//     Q = √(G_Ic E11 h³ / 12),
// independent of Δ: the correction moves the peak along the same propagation curve P ∝ δ^(−1/2).
//
// ----------------------------------------------------------------------------------------------------
// ENF: three-point bending, crack at the mid-plane from one support to a < L
// ----------------------------------------------------------------------------------------------------
// Beam theory (Russell & Street 1985; Carlsson, Gillespie & Pipes 1986, J. Compos. Mater. 20:594),
// with the crack-tip correction a → a + 0.42 χ h of Wang & Williams 1992 (Compos. Sci. Technol.
// 43:251):
//     C = (3 (a + Δ)³ + 2 L³) / (8 E11 b h³) + C_s,   G_II = 9 P² (a + Δ)² / (16 E11 b² h³).
// C_s is the Timoshenko shear compliance of the span, derived here: shear force P/2 over each half,
// shear area k·2bh with k = 5/6 (the arms of the cracked part carry P/4 each on area k·bh: the same
// shear strain, so the crack does not change it):  C_s = L / (2 k G13 · 2bh) = 3 L / (10 G13 b h).
// It does not depend on a and so leaves G_II alone, but it is ≈ 1.2 (E11/G13)(h/L)² of the bending
// compliance (3 % for AS4/PEEK with h/L = 0.03): a Mindlin plate model has it.
// Propagation at G_II = G_IIc: P = 4 b √(E11 h³ G_IIc) / (3 (a + Δ)), δ = C P. In displacement control
// the growth is stable only where δ increases with a:  d/da [(3 a_e³ + K0)/a_e] ≥ 0  ⇔
// a_e³ ≥ K0/6,  K0 = 2 L³ + 8 E11 b h³ C_s;  without C_s and Δ: a ≥ L/∛3 = 0.693 L (Carlsson et al.'s
// "a/L > 0.7"). Shorter cracks snap back: the branch is returned anyway, as a parametric curve of a.
//
// ----------------------------------------------------------------------------------------------------
// MMB (Reeder & Crews 1990, AIAA J. 28:1270; ASTM D6671)
// ----------------------------------------------------------------------------------------------------
// The lever load P at distance c from the saddle is the superposition of a DCB load on the arms' ends
// and an ENF load at mid-span:
//     P_I = P (3c − L) / (4L),   P_II = P (c + L) / L,
//     G_I = DCB G_I(P_I) with a + χh,  G_II = ENF G_II(P_II) with a + 0.42 χh,
//     C = C_DCB (P_I/P)² + C_ENF (P_II/P)²   (the lever-point displacement is work-conjugate to P),
// and the lever for a wanted mode-II fraction m = G_II/G (ASTM D6671):
//     c = L (12 β² + 3α + 8β√(3α)) / (36 β² − 3α),   α = (1 − m)/m,   β = (a + χh)/(a + 0.42 χh).
// Lever weight is neglected. Propagation follows B-K with B = m(a): G_I + G_II = G_c(m).
#pragma once

namespace plyimpact::test::beam_fracture {

/// A unidirectional beam split at mid-plane into two equal arms.
struct Specimen {
  double width = 0.0;         ///< b [m]
  double arm_thickness = 0.0; ///< h, each arm; the specimen is 2h thick [m]
  double E11 = 0.0;           ///< axial (flexural) modulus [Pa]
  double E22 = 0.0;           ///< transverse modulus, E33 = E22 [Pa]
  double G13 = 0.0;           ///< transverse shear modulus [Pa]
};

/// Williams' (1989) orthotropic crack-length correction factor χ (Δ = χ h for the DCB).
[[nodiscard]] double williams_chi(const Specimen& s);
/// DCB crack-length correction Δ_I = χ h.
[[nodiscard]] double dcb_crack_correction(const Specimen& s);
/// ENF crack-length correction Δ_II = 0.42 χ h (Wang & Williams 1992).
[[nodiscard]] double enf_crack_correction(const Specimen& s);

/// One point of a force–displacement curve, with the crack length it belongs to.
struct LoadPoint {
  double force = 0.0;        ///< P [N]
  double displacement = 0.0; ///< δ [m]: DCB opening, ENF mid-span deflection, MMB lever-point
  double crack_length = 0.0; ///< a [m]
};

// --- DCB ------------------------------------------------------------------------------------------

struct Dcb {
  Specimen specimen;
  double initial_crack = 0.0;    ///< a0 [m]
  double crack_correction = 0.0; ///< Δ [m]: dcb_crack_correction() for CBT, 0 for Euler–Bernoulli
};

[[nodiscard]] double compliance(const Dcb& dcb, double a);
[[nodiscard]] double energy_release_rate(const Dcb& dcb, double a, double force);
/// Point of the propagation branch (G_I = G_Ic) at crack length a.
[[nodiscard]] LoadPoint propagation(const Dcb& dcb, double a, double G_Ic);
/// Force on the propagation branch at opening δ (a eliminated; independent of Δ).
[[nodiscard]] double propagation_force(const Dcb& dcb, double opening, double G_Ic);
/// The whole quasi-static curve under increasing opening: elastic with a0 up to the peak
/// propagation(a0), then the propagation branch.
[[nodiscard]] double force(const Dcb& dcb, double opening, double G_Ic);

// --- ENF ------------------------------------------------------------------------------------------

struct Enf {
  Specimen specimen;
  double half_span = 0.0;        ///< L [m]
  double initial_crack = 0.0;    ///< a0 < L [m]
  double crack_correction = 0.0; ///< Δ [m]: enf_crack_correction() for CBT, 0 for Euler–Bernoulli
  bool transverse_shear = true;  ///< add the Timoshenko shear compliance 3L/(10 G13 b h) of the span
};

[[nodiscard]] double compliance(const Enf& enf, double a);
[[nodiscard]] double energy_release_rate(const Enf& enf, double a, double force);
/// Point of the propagation branch (G_II = G_IIc) at crack length a (also where it snaps back).
[[nodiscard]] LoadPoint propagation(const Enf& enf, double a, double G_IIc);
/// Crack length from which growth is stable under displacement control (δ increases with a).
[[nodiscard]] double stable_crack_length(const Enf& enf);

// --- MMB ------------------------------------------------------------------------------------------

struct Mmb {
  Specimen specimen;
  double half_span = 0.0;           ///< L [m]
  double lever = 0.0;               ///< c [m], from the saddle (mid-span); c = L/3 is pure mode II
  double initial_crack = 0.0;       ///< a0 [m]
  double crack_correction_I = 0.0;  ///< Δ_I [m] (χh for CBT)
  double crack_correction_II = 0.0; ///< Δ_II [m] (0.42 χh for CBT)
  bool transverse_shear = true;     ///< Timoshenko shear compliance in the ENF part
};

/// The DCB and ENF parts of a lever load P.
[[nodiscard]] double mode_I_force(const Mmb& mmb, double force);
[[nodiscard]] double mode_II_force(const Mmb& mmb, double force);
[[nodiscard]] double energy_release_rate_I(const Mmb& mmb, double a, double force);
[[nodiscard]] double energy_release_rate_II(const Mmb& mmb, double a, double force);
/// Mode-II fraction G_II / (G_I + G_II) at crack length a (independent of the load).
[[nodiscard]] double mode_II_fraction(const Mmb& mmb, double a);
/// ASTM D6671 lever length for mode-II fraction 0 < m ≤ 1 at crack length a (mmb.lever is ignored).
[[nodiscard]] double lever_for_mode_II_fraction(const Mmb& mmb, double a, double m);
/// Lever-point compliance.
[[nodiscard]] double compliance(const Mmb& mmb, double a);
/// Point of the propagation branch at crack length a: G_I + G_II = G_Ic + (G_IIc − G_Ic) m(a)^η.
[[nodiscard]] LoadPoint propagation(const Mmb& mmb, double a, double G_Ic, double G_IIc, double eta);

} // namespace plyimpact::test::beam_fracture
