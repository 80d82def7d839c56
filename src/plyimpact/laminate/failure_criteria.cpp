// Ply failure criteria, thesis chapter 2.5 (2.32)–(2.43), misprints fixed per SPEC §6.
//
// Every mode of every criterion is written as its value along the proportional load ray λ·σ:
//   index(λ) = a·λ² + b·λ      (a: quadratic part, b: linear part; Choi–Chang e: a = 0, b = e)
// so that index = a + b at λ = 1 and the strength ratio is the positive root of a R² + b R = 1.
// Sign conditions (σ11 ≥ 0, ...) do not change along the ray, so this is exact for each mode.
#include "plyimpact/laminate/failure_criteria.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <initializer_list>
#include <span>
#include <stdexcept>
#include <string>

namespace plyimpact {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

/// One failure mode's value along the load ray: index(λ) = a λ² + b λ.
struct ModeValue {
  FailureMode mode;
  double a; ///< quadratic part at λ = 1
  double b; ///< linear part at λ = 1
};

/// Smallest R > 0 with a R² + b R = 1, or +inf if the ray never reaches 1.
/// Written as 2 / (b + √(b² + 4a)) to avoid cancellation; covers a > 0, a = 0 and a < 0.
double ray_ratio(double a, double b) {
  const double disc = b * b + 4.0 * a;
  if (!(disc >= 0.0)) return kInf;
  const double denom = b + std::sqrt(disc);
  if (!(denom > 0.0)) return kInf;
  return 2.0 / denom;
}

/// Governing result of the active modes: index = largest mode index; strength ratio = smallest
/// mode ratio; mode = the mode of that smallest ratio, i.e. the first one reached when the load
/// grows proportionally (the first listed wins ties); FailureMode::none when no mode can be
/// reached. A NaN (missing strength) makes index and ratio NaN.
FailureResult govern(std::initializer_list<ModeValue> modes) {
  FailureResult r{-kInf, FailureMode::none, kInf};
  for (const ModeValue& m : modes) {
    const double index = m.a + m.b;
    if (std::isnan(index)) {
      const double nan = std::numeric_limits<double>::quiet_NaN();
      return {nan, FailureMode::none, nan};
    }
    r.index = std::max(r.index, index);
    const double ratio = ray_ratio(m.a, m.b);
    if (ratio < r.strength_ratio) {
      r.strength_ratio = ratio;
      r.mode = m.mode;
    }
  }
  return r;
}

/// Strengths each criterion reads (see required_strengths()).
std::span<const StrengthId> required_strength_ids(Criterion criterion) {
  using enum StrengthId;
  static constexpr std::array in_plane{Xt, Xc, Yt, Yc, S12};
  static constexpr std::array in_plane_and_s23{Xt, Xc, Yt, Yc, S12, S23};
  static constexpr std::array transverse{Yt, Yc, S23};
  static constexpr std::array delamination{Yt, Yc, S23, Da};
  switch (criterion) {
  case Criterion::max_stress:
  case Criterion::max_strain:
  case Criterion::tsai_hill:
  case Criterion::hoffman:
  case Criterion::tsai_wu:
    return in_plane;
  case Criterion::hashin:
  case Criterion::sun:
    return in_plane_and_s23;
  case Criterion::choi_chang_matrix:
    return transverse;
  case Criterion::choi_chang_delamination:
    return delamination;
  }
  return {};
}

std::optional<double> lookup(const Strengths& st, StrengthId id) {
  switch (id) {
  case StrengthId::Xt:
    return st.Xt;
  case StrengthId::Xc:
    return st.Xc;
  case StrengthId::Yt:
    return st.Yt;
  case StrengthId::Yc:
    return st.Yc;
  case StrengthId::S12:
    return st.S12;
  case StrengthId::S23:
    return st.S23;
  case StrengthId::Zt:
    return st.Zt;
  case StrengthId::Da:
    return st.Da;
  }
  return std::nullopt;
}

/// The strengths a criterion reads, every one NaN if any of them is missing, so that the result
/// of an evaluation with incomplete data is NaN whatever the stress state (never a silent pass).
struct ResolvedStrengths {
  double Xt, Xc, Yt, Yc, S12, S23, Da;
};

ResolvedStrengths resolve(const Strengths& st, Criterion criterion) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (const StrengthId id : required_strength_ids(criterion)) {
    if (!lookup(st, id).has_value()) return {nan, nan, nan, nan, nan, nan, nan};
  }
  return {st.Xt.value_or(nan),  st.Xc.value_or(nan),  st.Yt.value_or(nan), st.Yc.value_or(nan),
          st.S12.value_or(nan), st.S23.value_or(nan), st.Da.value_or(nan)};
}

double sq(double x) {
  return x * x;
}

/// Linear (degree-1) mode from a signed component and its tension / compression allowables.
ModeValue signed_linear_mode(double value, double tension, double compression, FailureMode tension_mode,
                             FailureMode compression_mode) {
  if (value >= 0.0) return {tension_mode, 0.0, value / tension};
  return {compression_mode, 0.0, -value / compression};
}

/// Indicative mode of the interactive criteria (Tsai–Hill, Hoffman, Tsai–Wu): the component
/// with the largest max-stress ratio.
FailureMode dominant_mode(const PlyStress& s, const Strengths& st) {
  return max_stress(s, st).mode;
}

} // namespace

// --- names ----------------------------------------------------------------------------------

std::string_view to_string(FailureMode mode) {
  switch (mode) {
  case FailureMode::none:
    return "none";
  case FailureMode::fibre_tension:
    return "fibre-tension";
  case FailureMode::fibre_compression:
    return "fibre-compression";
  case FailureMode::matrix_tension:
    return "matrix-tension";
  case FailureMode::matrix_compression:
    return "matrix-compression";
  case FailureMode::in_plane_shear:
    return "in-plane-shear";
  case FailureMode::fibre_breakage:
    return "fibre-breakage";
  case FailureMode::matrix_cracking:
    return "matrix-cracking";
  case FailureMode::matrix_crushing:
    return "matrix-crushing";
  case FailureMode::delamination:
    return "delamination";
  }
  return "unknown";
}

std::string_view to_string(Criterion criterion) {
  switch (criterion) {
  case Criterion::max_stress:
    return "max-stress";
  case Criterion::max_strain:
    return "max-strain";
  case Criterion::tsai_hill:
    return "tsai-hill";
  case Criterion::hoffman:
    return "hoffman";
  case Criterion::tsai_wu:
    return "tsai-wu";
  case Criterion::hashin:
    return "hashin";
  case Criterion::sun:
    return "sun";
  case Criterion::choi_chang_matrix:
    return "choi-chang-matrix";
  case Criterion::choi_chang_delamination:
    return "choi-chang-delamination";
  }
  return "unknown";
}

std::vector<Criterion> all_criteria() {
  return {Criterion::max_stress, Criterion::max_strain,        Criterion::tsai_hill,
          Criterion::hoffman,    Criterion::tsai_wu,           Criterion::hashin,
          Criterion::sun,        Criterion::choi_chang_matrix, Criterion::choi_chang_delamination};
}

std::optional<Criterion> parse_criterion(std::string_view name) {
  for (const Criterion c : all_criteria()) {
    if (to_string(c) == name) return c;
  }
  return std::nullopt;
}

bool is_interface_criterion(Criterion criterion) {
  return criterion == Criterion::choi_chang_delamination;
}

std::string_view to_string(StrengthId id) {
  switch (id) {
  case StrengthId::Xt:
    return "Xt";
  case StrengthId::Xc:
    return "Xc";
  case StrengthId::Yt:
    return "Yt";
  case StrengthId::Yc:
    return "Yc";
  case StrengthId::S12:
    return "S12";
  case StrengthId::S23:
    return "S23";
  case StrengthId::Zt:
    return "Zt";
  case StrengthId::Da:
    return "Da";
  }
  return "unknown";
}

std::optional<double> strength_value(const Strengths& strengths, StrengthId id) {
  return lookup(strengths, id);
}

std::vector<StrengthId> required_strengths(Criterion criterion) {
  const std::span<const StrengthId> ids = required_strength_ids(criterion);
  return {ids.begin(), ids.end()};
}

std::vector<StrengthId> missing_strengths(Criterion criterion, const Strengths& strengths) {
  std::vector<StrengthId> missing;
  for (const StrengthId id : required_strengths(criterion)) {
    if (!strength_value(strengths, id).has_value()) missing.push_back(id);
  }
  return missing;
}

// --- criteria -------------------------------------------------------------------------------

// (2.32), plane stress.
FailureResult max_stress(const PlyStress& s, const Strengths& st) {
  const ResolvedStrengths r = resolve(st, Criterion::max_stress);
  return govern({
      signed_linear_mode(s.s11, r.Xt, r.Xc, FailureMode::fibre_tension, FailureMode::fibre_compression),
      signed_linear_mode(s.s22, r.Yt, r.Yc, FailureMode::matrix_tension, FailureMode::matrix_compression),
      {FailureMode::in_plane_shear, 0.0, std::abs(s.t12) / r.S12},
  });
}

StrainAllowables strain_allowables(const Material& m) {
  const ResolvedStrengths r = resolve(m.strength, Criterion::max_strain);
  return {r.Xt / m.E1, r.Xc / m.E1, r.Yt / m.E2, r.Yc / m.E2, r.S12 / m.G12};
}

FailureResult max_strain(const PlyStress& s, const Material& m) {
  return max_strain(s, m, strain_allowables(m));
}

// (2.33), strains from the plane-stress compliance (ν21/E2 = ν12/E1).
FailureResult max_strain(const PlyStress& s, const Material& m, const StrainAllowables& allow) {
  const double e11 = (s.s11 - m.nu12 * s.s22) / m.E1;
  const double e22 = s.s22 / m.E2 - m.nu12 * s.s11 / m.E1;
  const double g12 = s.t12 / m.G12;
  return govern({
      signed_linear_mode(e11, allow.e1t, allow.e1c, FailureMode::fibre_tension,
                         FailureMode::fibre_compression),
      signed_linear_mode(e22, allow.e2t, allow.e2c, FailureMode::matrix_tension,
                         FailureMode::matrix_compression),
      {FailureMode::in_plane_shear, 0.0, std::abs(g12) / allow.g12},
  });
}

// (2.35), X and Y chosen by the signs of σ11 and σ22 (thesis's Y choice swapped: misprint).
FailureResult tsai_hill(const PlyStress& s, const Strengths& st) {
  const ResolvedStrengths r = resolve(st, Criterion::tsai_hill);
  const double X = s.s11 >= 0.0 ? r.Xt : r.Xc;
  const double Y = s.s22 >= 0.0 ? r.Yt : r.Yc;
  const double a = sq(s.s11 / X) - s.s11 * s.s22 / (X * X) + sq(s.s22 / Y) + sq(s.t12 / r.S12);
  return govern({{dominant_mode(s, st), a, 0.0}});
}

// (2.38) in plane stress, transversely isotropic (Zt = Yt, Zc = Yc):
// C2 + C3 = 1/(XtXc), C1 + C3 = 1/(YtYc), 2 C3 = 1/(XtXc), C4 = 1/Xt − 1/Xc, C5 = 1/Yt − 1/Yc, C9 = 1/S12².
FailureResult hoffman(const PlyStress& s, const Strengths& st) {
  const ResolvedStrengths r = resolve(st, Criterion::hoffman);
  const double XX = r.Xt * r.Xc;
  const double YY = r.Yt * r.Yc;
  const double a = (s.s11 * s.s11 - s.s11 * s.s22) / XX + s.s22 * s.s22 / YY + sq(s.t12 / r.S12);
  const double b = (1.0 / r.Xt - 1.0 / r.Xc) * s.s11 + (1.0 / r.Yt - 1.0 / r.Yc) * s.s22;
  return govern({{dominant_mode(s, st), a, b}});
}

// (2.36a) with the corrected coefficients (2.36b) of SPEC §6.
FailureResult tsai_wu(const PlyStress& s, const Strengths& st, double f12_star) {
  const ResolvedStrengths r = resolve(st, Criterion::tsai_wu);
  const double F11 = 1.0 / (r.Xt * r.Xc);
  const double F22 = 1.0 / (r.Yt * r.Yc);
  const double F66 = 1.0 / (r.S12 * r.S12);
  const double F1 = 1.0 / r.Xt - 1.0 / r.Xc;
  const double F2 = 1.0 / r.Yt - 1.0 / r.Yc;
  const double F12 = f12_star * std::sqrt(F11 * F22);
  const double a =
      F11 * s.s11 * s.s11 + 2.0 * F12 * s.s11 * s.s22 + F22 * s.s22 * s.s22 + F66 * s.t12 * s.t12;
  const double b = F1 * s.s11 + F2 * s.s22;
  return govern({{dominant_mode(s, st), a, b}});
}

// (2.37), Hashin 1980 3-D form; conditions σ11 ≥ 0, σ22 + σ33 ≥ 0 (thesis's "≤ 1", "≥ 1": misprints).
FailureResult hashin(const PlyStress& s, const Strengths& st) {
  const ResolvedStrengths r = resolve(st, Criterion::hashin);
  const double axial_shear = (s.t12 * s.t12 + s.t13 * s.t13) / (r.S12 * r.S12);
  const double sm = s.s22 + s.s33;
  const double transverse_shear = (s.t23 * s.t23 - s.s22 * s.s33) / (r.S23 * r.S23);

  const ModeValue fibre = s.s11 >= 0.0
                              ? ModeValue{FailureMode::fibre_tension, sq(s.s11 / r.Xt) + axial_shear, 0.0}
                              : ModeValue{FailureMode::fibre_compression, sq(s.s11 / r.Xc), 0.0};
  const ModeValue matrix =
      sm >= 0.0 ? ModeValue{FailureMode::matrix_tension, sq(sm / r.Yt) + transverse_shear + axial_shear, 0.0}
                : ModeValue{FailureMode::matrix_compression,
                            sq(sm / (2.0 * r.S23)) + transverse_shear + axial_shear,
                            (sq(r.Yc / (2.0 * r.S23)) - 1.0) * sm / r.Yc};
  return govern({matrix, fibre}); // matrix first: it wins a tie (pure τ12 = S12 is a matrix failure)
}

// (2.39)–(2.41), misprints fixed: (σ12²/S12)² → (σ12/S12)²; S_f = S12, S_m23 = S23.
FailureResult sun(const PlyStress& s, const Strengths& st) {
  const ResolvedStrengths r = resolve(st, Criterion::sun);
  const double X = s.s11 >= 0.0 ? r.Xt : r.Xc;
  const ModeValue fibre{FailureMode::fibre_breakage, sq(s.s11 / X) + sq(s.t12 / r.S12) + sq(s.t13 / r.S12),
                        0.0};
  const ModeValue matrix =
      s.s22 >= 0.0 ? ModeValue{FailureMode::matrix_cracking,
                               sq(s.s22 / r.Yt) + sq(s.t12 / r.S12) + sq(s.t23 / r.S23), 0.0}
                   : ModeValue{FailureMode::matrix_crushing, 0.25 * sq(s.s22 / r.S12) + sq(s.t12 / r.S12),
                               (r.Yc / (4.0 * r.S12 * r.S12) - 1.0 / r.Yc) * s.s22};
  return govern({matrix, fibre});
}

// (2.42): index e_M (degree 1 in the stresses).

// (2.43): index e_D (degree 1 in the stresses).
FailureResult choi_chang_delamination(const PlyStress& upper_avg, const Strengths& upper,
                                      const PlyStress& lower_avg, const Strengths& lower,
                                      DelaminationPlyN ply_n) {
  const bool upper_is_n = ply_n == DelaminationPlyN::upper;
  const PlyStress& sn = upper_is_n ? upper_avg : lower_avg;
  const PlyStress& sn1 = upper_is_n ? lower_avg : upper_avg;
  const Strengths& rn = upper_is_n ? upper : lower;
  const Strengths& rn1 = upper_is_n ? lower : upper;
  // The strengths read directly (this runs at every cracked interface of every tracked step); the
  // result is govern({{delamination, 0, e}})'s, NaN when a strength is missing.
  if (!rn.Yt || !rn.Yc || !rn.S23 || !rn.Da || !rn1.Yt || !rn1.Yc || !rn1.S23 || !rn1.Da) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    return {nan, FailureMode::none, nan};
  }
  const double Da = 0.5 * (*rn.Da + *rn1.Da);
  const double Y1 = sn1.s22 >= 0.0 ? *rn1.Yt : *rn1.Yc;
  const double e = std::sqrt(Da * (sq(sn.t23 / *rn.S23) + sq(sn1.t13 / *rn1.S23) + sq(sn1.s22 / Y1)));
  if (std::isnan(e)) return {e, FailureMode::none, e};
  const double ratio = ray_ratio(0.0, e);
  return {e, ratio < kInf ? FailureMode::delamination : FailureMode::none, ratio};
}

// --- dispatch -------------------------------------------------------------------------------

FailureResult evaluate(Criterion c, const PlyStress& s, const Material& m, const CriterionOptions& options) {
  switch (c) {
  case Criterion::max_stress:
    return max_stress(s, m.strength);
  case Criterion::max_strain:
    return max_strain(s, m);
  case Criterion::tsai_hill:
    return tsai_hill(s, m.strength);
  case Criterion::hoffman:
    return hoffman(s, m.strength);
  case Criterion::tsai_wu:
    return tsai_wu(s, m.strength, options.tsai_wu_f12_star);
  case Criterion::hashin:
    return hashin(s, m.strength);
  case Criterion::sun:
    return sun(s, m.strength);
  case Criterion::choi_chang_matrix:
    return choi_chang_matrix_cracking(s, m.strength);
  case Criterion::choi_chang_delamination:
    break;
  }
  throw std::invalid_argument("failure criterion '" + std::string(to_string(c)) +
                              "' is an interface criterion: use choi_chang_delamination()");
}

bool FailureLatch::update(const FailureResult& r) {
  peak_index = std::max(peak_index, r.index);
  if (failed || !r.failed()) return false;
  failed = true;
  first_mode = r.mode;
  return true;
}

} // namespace plyimpact
