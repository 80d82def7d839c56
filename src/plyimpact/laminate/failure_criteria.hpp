#pragma once
// Ply failure criteria of thesis chapter 2.5, equations (2.32)–(2.43), with the misprints
// listed in SPEC §6 corrected. Physics only: no I/O, no exceptions during normal evaluation.
// See docs/failure_criteria.md for the formulas, the modes and every convention used here.
#include "plyimpact/laminate/material.hpp"

#include <cmath>
#include <limits>
#include <optional>
#include <string_view>
#include <vector>

namespace plyimpact {

/// Ply stress in the ply's material axes (1 = fibre, 2 = transverse in-plane, 3 = thickness) [Pa].
/// Member order is the Voigt order 11, 22, 33, 23, 13, 12. Every member defaults to 0, so
/// designated initialisers work: `PlyStress{.s22 = 40e6, .t23 = 10e6}`.
/// For the Choi–Chang criteria pass ply-averaged stresses σ̄ (SPEC §5).
struct PlyStress {
  double s11 = 0.0; ///< σ11, fibre direction
  double s22 = 0.0; ///< σ22, transverse in-plane
  double s33 = 0.0; ///< σ33, through thickness (0 in the Mindlin plate model)
  double t23 = 0.0; ///< τ23, transverse shear in the 2–3 plane
  double t13 = 0.0; ///< τ13, transverse shear in the 1–3 plane
  double t12 = 0.0; ///< τ12, in-plane shear

  /// The stress state scaled by λ (proportional loading).
  [[nodiscard]] PlyStress scaled(double lambda) const {
    return {lambda * s11, lambda * s22, lambda * s33, lambda * t23, lambda * t13, lambda * t12};
  }
};

/// Failure modes named by the criteria of chapter 2.5.
enum class FailureMode {
  none,               ///< the failure surface is never reached along this load ray (ratio = +inf)
  fibre_tension,      ///< σ11 ≥ 0 governs (max-stress, max-strain, Hashin; indicative for Tsai-*)
  fibre_compression,  ///< σ11 < 0 governs
  matrix_tension,     ///< σ22 ≥ 0 governs (Hashin: σ22 + σ33 ≥ 0)
  matrix_compression, ///< σ22 < 0 governs (Hashin: σ22 + σ33 < 0)
  in_plane_shear,     ///< τ12 governs (max-stress, max-strain; indicative for Tsai-*)
  fibre_breakage,     ///< Sun et al. (2.39)
  matrix_cracking,    ///< Sun et al. (2.40), Choi–Chang (2.42)
  matrix_crushing,    ///< Sun et al. (2.41)
  delamination,       ///< Choi–Chang (2.43)
};

/// Stable lower-case hyphenated name ("fibre-tension", "matrix-cracking", ...).
[[nodiscard]] std::string_view to_string(FailureMode mode);

/// Result of one criterion at one stress state.
/// - `index`: the criterion's left-hand side as the thesis writes it (`≤ 1` safe); `index ≥ 1`
///   means failure. Quadratic forms are reported as is (not square-rooted), except Choi–Chang,
///   whose index is e_M / e_D (not e²). Criteria with linear terms (Tsai–Wu, Hoffman, Hashin and
///   Sun compression modes) can give a negative index under mild compression: that is safe.
/// - `strength_ratio`: R > 0 such that the state R·σ lies exactly on the failure surface
///   (R ≤ 1 ⇔ failure). +inf when the surface is never reached along the ray (e.g. zero stress).
/// - `mode`: governing mode of a multi-mode criterion = the mode whose own strength ratio is the
///   smallest, i.e. the first mode reached when the load grows proportionally (ties go to the
///   matrix mode). Whenever exactly one mode has index ≥ 1 this is that mode, the max-index mode.
///   Otherwise the two rules can differ: below failure a mode with a linear term (Hashin/Sun
///   matrix compression) can have a lower index yet be reached first. For the single-surface criteria
///   (Tsai–Hill, Hoffman, Tsai–Wu) the mode is indicative: the component with the largest
///   max-stress ratio. `FailureMode::none` exactly when `strength_ratio` is +inf.
/// - for multi-mode criteria `index` is the largest index of the active modes and
///   `strength_ratio` the smallest ratio; both are exact for the governing state: index(R·σ) = 1.
struct FailureResult {
  double index = 0.0;
  FailureMode mode = FailureMode::none;
  double strength_ratio = std::numeric_limits<double>::infinity();

  [[nodiscard]] bool failed() const { return index >= 1.0; }
};

/// Criterion ids; their names are the deck vocabulary (SPEC §10, `[damage] criteria`).
enum class Criterion {
  max_stress,              ///< "max-stress"              (2.32)
  max_strain,              ///< "max-strain"              (2.33)
  tsai_hill,               ///< "tsai-hill"               (2.35)
  hoffman,                 ///< "hoffman"                 (2.38)
  tsai_wu,                 ///< "tsai-wu"                 (2.36)
  hashin,                  ///< "hashin"                  (2.37), Hashin 1980
  sun,                     ///< "sun"                     (2.39)–(2.41)
  choi_chang_matrix,       ///< "choi-chang-matrix"       (2.42)
  choi_chang_delamination, ///< "choi-chang-delamination" (2.43), an interface criterion
};

[[nodiscard]] std::string_view to_string(Criterion criterion);
/// Exact (case-sensitive) deck name → id; nullopt for an unknown name.
[[nodiscard]] std::optional<Criterion> parse_criterion(std::string_view name);
/// All criteria, in declaration order (for help texts and tests).
[[nodiscard]] std::vector<Criterion> all_criteria();
/// True for criteria evaluated at an interface between two plies (Choi–Chang delamination).
[[nodiscard]] bool is_interface_criterion(Criterion criterion);

/// Names of the members of `Strengths`.
enum class StrengthId { Xt, Xc, Yt, Yc, S12, S23, Zt, Da };
[[nodiscard]] std::string_view to_string(StrengthId id); ///< "Xt", "Xc", ..., "Da" (deck keys)
[[nodiscard]] std::optional<double> strength_value(const Strengths& strengths, StrengthId id);

/// Strengths a criterion reads (max-strain also reads E1, E2, G12, ν12 of the Material, which
/// are always present). The evaluation functions assume these are present (precondition).
[[nodiscard]] std::vector<StrengthId> required_strengths(Criterion criterion);
/// The subset of `required_strengths(criterion)` that `strengths` lacks, e.g. so the deck reader
/// can report "criterion tsai-wu needs Xc for material T300" before a run.
[[nodiscard]] std::vector<StrengthId> missing_strengths(Criterion criterion, const Strengths& strengths);

// --- single-ply criteria ------------------------------------------------------------------------
// Preconditions: the strengths listed by required_strengths() are present and positive.

/// Maximum stress (2.32), plane stress: max(σ11/Xt or |σ11|/Xc, σ22/Yt or |σ22|/Yc, |τ12|/S12).
[[nodiscard]] FailureResult max_stress(const PlyStress& s, const Strengths& st);

/// Strains to failure for the maximum-strain criterion (all positive) [-].
struct StrainAllowables {
  double e1t = 0.0; ///< fibre-direction tension
  double e1c = 0.0; ///< fibre-direction compression (magnitude)
  double e2t = 0.0; ///< transverse tension
  double e2c = 0.0; ///< transverse compression (magnitude)
  double g12 = 0.0; ///< in-plane engineering shear strain γ12
};
/// Allowables from strengths and moduli: e1t = Xt/E1, e1c = Xc/E1, e2t = Yt/E2, e2c = Yc/E2,
/// g12 = S12/G12 (linear-elastic ply up to failure).
[[nodiscard]] StrainAllowables strain_allowables(const Material& m);

/// Maximum strain (2.33) with the allowables of strain_allowables(m). Strains from the
/// plane-stress compliance of the ply (σ33, τ13, τ23 ignored):
/// ε11 = (σ11 − ν12 σ22)/E1, ε22 = σ22/E2 − ν12 σ11/E1, γ12 = τ12/G12.
[[nodiscard]] FailureResult max_strain(const PlyStress& s, const Material& m);
/// Maximum strain (2.33) with explicitly given strains to failure.
[[nodiscard]] FailureResult max_strain(const PlyStress& s, const Material& m, const StrainAllowables& allow);

/// Tsai–Hill (2.35), plane stress: (σ11/X)² − σ11σ22/X² + (σ22/Y)² + (τ12/S12)²,
/// X = Xt if σ11 ≥ 0 else Xc, Y = Yt if σ22 ≥ 0 else Yc (the thesis swaps the Y choice).
[[nodiscard]] FailureResult tsai_hill(const PlyStress& s, const Strengths& st);

/// Hoffman (2.38) reduced to plane stress with transverse isotropy (Z = Y):
/// σ11²/(XtXc) − σ11σ22/(XtXc) + σ22²/(YtYc) + (1/Xt − 1/Xc)σ11 + (1/Yt − 1/Yc)σ22 + τ12²/S12².
[[nodiscard]] FailureResult hoffman(const PlyStress& s, const Strengths& st);

/// Default normalised interaction coefficient F12* of Tsai–Wu: F12 = F12*·√(F11 F22).
inline constexpr double tsai_wu_default_f12_star = -0.5;

/// Tsai–Wu (2.36a), plane stress: F11σ11² + 2F12σ11σ22 + F22σ22² + F66τ12² + F1σ11 + F2σ22,
/// F11 = 1/(XtXc), F22 = 1/(YtYc), F66 = 1/S12², F1 = 1/Xt − 1/Xc, F2 = 1/Yt − 1/Yc,
/// F12 = f12_star·√(F11F22) (closed surface for −1 < f12_star < 1).
[[nodiscard]] FailureResult tsai_wu(const PlyStress& s, const Strengths& st,
                                    double f12_star = tsai_wu_default_f12_star);

/// Hashin 1980 (2.37), 3-D form for a transversely isotropic ply (S12 = S_A, S23 = S_T):
///  fibre tension (σ11 ≥ 0):        (σ11/Xt)² + (τ12² + τ13²)/S12²
///  fibre compression (σ11 < 0):    (σ11/Xc)²
///  matrix tension (σ22+σ33 ≥ 0):   (σ22+σ33)²/Yt² + (τ23² − σ22σ33)/S23² + (τ12² + τ13²)/S12²
///  matrix compression (σ22+σ33<0): [(Yc/(2S23))² − 1](σ22+σ33)/Yc + (σ22+σ33)²/(4S23²)
///                                  + (τ23² − σ22σ33)/S23² + (τ12² + τ13²)/S12²
/// With σ33 = τ13 = τ23 = 0 these are the thesis's plane-stress lines, misprints fixed.
[[nodiscard]] FailureResult hashin(const PlyStress& s, const Strengths& st);

/// Sun et al. (2.39)–(2.41), misprints fixed, S_f = S12 and S_m23 = S23:
///  fibre breakage:                (σ11/X)² + (τ12² + τ13²)/S12², X = Xt if σ11 ≥ 0 else Xc
///  matrix cracking (σ22 ≥ 0):     (σ22/Yt)² + (τ12/S12)² + (τ23/S23)²
///  matrix crushing (σ22 < 0):     ¼(σ22/S12)² + (Yc/(4S12²) − 1/Yc)σ22 + (τ12/S12)²
[[nodiscard]] FailureResult sun(const PlyStress& s, const Strengths& st);

/// Choi–Chang matrix cracking (2.42) on ply-averaged stresses: index e_M with
/// e_M² = (σ̄22/Y)² + (τ̄23/S23)², Y = Yt if σ̄22 ≥ 0 else Yc. Mode matrix_cracking.
/// Inline: it runs at every Gauss point of every ply at every step of an impact.
[[nodiscard]] inline FailureResult choi_chang_matrix_cracking(const PlyStress& avg, const Strengths& st) {
  if (!st.Yt || !st.Yc || !st.S23) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    return {nan, FailureMode::none, nan};
  }
  const double y = avg.s22 / (avg.s22 >= 0.0 ? *st.Yt : *st.Yc);
  const double s = avg.t23 / *st.S23;
  const double e = std::sqrt(y * y + s * s);
  return {e, e > 0.0 ? FailureMode::matrix_cracking : FailureMode::none,
          e > 0.0 ? 1.0 / e : std::numeric_limits<double>::infinity()};
}

/// Which ply adjacent to an interface plays "n" in (2.43) (the other plays "n+1").
/// SPEC §1 numbering: interface k lies between ply k (upper, impact side) and ply k+1 (lower).
enum class DelaminationPlyN {
  upper, ///< default: ply k is "n" (Choi & Chang 1992: n, n+1 = upper, lower ply of interface n)
  lower, ///< ply k+1 is "n" (the thesis's wording: "plis inférieur et supérieur")
};

/// Choi–Chang delamination (2.43) at the interface between `upper` and `lower` plies, from their
/// ply-averaged stresses and strengths: index e_D with
/// e_D² = Da [ (τ̄23⁽ⁿ⁾/S23⁽ⁿ⁾)² + (τ̄13⁽ⁿ⁺¹⁾/S23⁽ⁿ⁺¹⁾)² + (σ̄22⁽ⁿ⁺¹⁾/Y⁽ⁿ⁺¹⁾)² ],
/// Y⁽ⁿ⁺¹⁾ = Yt or Yc of ply n+1 by the sign of σ̄22⁽ⁿ⁺¹⁾, Da = mean of the two plies' Da.
/// Mode delamination. Whether ply n or n+1 is matrix-cracked is the caller's business.
[[nodiscard]] FailureResult choi_chang_delamination(const PlyStress& upper_avg, const Strengths& upper,
                                                    const PlyStress& lower_avg, const Strengths& lower,
                                                    DelaminationPlyN ply_n = DelaminationPlyN::upper);

// --- dispatch -------------------------------------------------------------------------------

/// Per-criterion settings.
struct CriterionOptions {
  double tsai_wu_f12_star = tsai_wu_default_f12_star;
  DelaminationPlyN delamination_ply_n = DelaminationPlyN::upper;
};

/// Evaluate a single-ply criterion on a ply of material `m`.
/// Precondition: !is_interface_criterion(c) (throws std::invalid_argument otherwise: a
/// programming error, never a normal evaluation outcome).
[[nodiscard]] FailureResult evaluate(Criterion c, const PlyStress& s, const Material& m,
                                     const CriterionOptions& options = {});

// --- irreversibility helper ---------------------------------------------------------------------

/// "Once failed, stays failed" latch for one evaluation point: remembers the first failure's mode
/// and the peak index seen (starting from 0). The damage tracker owns one per (criterion, point).
struct FailureLatch {
  bool failed = false;
  FailureMode first_mode = FailureMode::none;
  double peak_index = 0.0;

  /// Feed the latest result; returns true exactly once, when failure is first reached.
  bool update(const FailureResult& r);
};

} // namespace plyimpact
