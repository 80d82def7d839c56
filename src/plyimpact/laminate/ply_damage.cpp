// Progressive ply damage: Hashin (1980) initiation, Matzenmiller–Lubliner–Taylor (1995) stiffness,
// Lapczyk & Hurtado (2007) linear softening with crack-band regularisation. The equation numbers
// (PD1)–(PD12) refer to docs/progressive_damage.md.
#include "plyimpact/laminate/ply_damage.hpp"
#include "plyimpact/laminate/macaulay.hpp"
#include "plyimpact/laminate/ply_damage_algebra.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <utility>
#include <vector>

namespace plyimpact {

using namespace ply_damage_algebra; // NOLINT(google-build-using-namespace): the laws' shared algebra

std::string_view to_string(DamageMode mode) {
  switch (mode) {
  case DamageMode::fibre_tension:
    return "fibre-tension";
  case DamageMode::fibre_compression:
    return "fibre-compression";
  case DamageMode::matrix_tension:
    return "matrix-tension";
  case DamageMode::matrix_compression:
    return "matrix-compression";
  }
  return "unknown";
}

BandLimitError::BandLimitError(std::string_view material, DamageMode mode, double characteristic_length,
                               double max_characteristic_length)
    : std::runtime_error(fmt::format(
          "progressive damage of material '{}': the characteristic length L_c = {:.4g} mm exceeds the "
          "band limit of mode {}, 2G/(sigma0_eq * eps0_eq) = {:.4g} mm (linear softening would snap back "
          "and dissipate more than G); refine the mesh to a maximum element size (characteristic length) "
          "of {:.4g} mm, check the mode's fracture toughness, or accept lowered strengths in the larger "
          "elements with [damage] oversize = \"reduce-strength\"",
          material, characteristic_length * 1e3, to_string(mode), max_characteristic_length * 1e3,
          max_characteristic_length * 1e3)),
      mode_(mode), characteristic_length_(characteristic_length),
      max_characteristic_length_(max_characteristic_length) {}

namespace {

/// Quadratic and linear parts of a Hashin index, F(λσ̂) = a λ² + b λ.
struct IndexParts {
  double quadratic = 0.0;
  double linear = 0.0;
};

IndexParts hashin_parts(DamageMode mode, const Eigen::Vector3d& s, const Strengths& st, double alpha) {
  const auto sq = [](double x) { return x * x; };
  switch (mode) {
  case DamageMode::fibre_tension:
    return {sq(s(0) / *st.Xt) + alpha * sq(s(2) / *st.S12), 0.0};
  case DamageMode::fibre_compression:
    return {sq(s(0) / *st.Xc), 0.0};
  case DamageMode::matrix_tension:
    return {sq(s(1) / *st.Yt) + sq(s(2) / *st.S12), 0.0};
  case DamageMode::matrix_compression:
    return {sq(s(1) / (2.0 * *st.S23)) + sq(s(2) / *st.S12),
            (sq(*st.Yc / (2.0 * *st.S23)) - 1.0) * s(1) / *st.Yc};
  }
  return {};
}

/// R > 0 with F(R σ̂) = 1: the positive root of a R² + b R − 1 = 0, in the form free of cancellation
/// for either sign of b; +∞ when the ray never reaches the surface.
double onset_ratio(IndexParts p) {
  const double a = p.quadratic, b = p.linear;
  if (a <= 0.0) return b > 0.0 ? 1.0 / b : std::numeric_limits<double>::infinity();
  const double root = std::sqrt(b * b + 4.0 * a);
  return b >= 0.0 ? 2.0 / (b + root) : (root - b) / (2.0 * a);
}

/// The point where a mode initiates: its equivalent strain and stress.
struct Onset {
  double strain = 0.0;
  double stress = 0.0;
};

/// Initiation (PD1): when the effective stress σ̂ of the strain ε meets or has crossed the mode's
/// Hashin surface, the onset point is the crossing of the ray of ε with the surface, R·ε with
/// F(R σ̂) = 1; ε_eq and σ_eq scale with R. None if the surface is not reached or if the mode's
/// equivalent strain is zero (no displacement for it to soften on).
std::optional<Onset> initiation(DamageMode mode, const Eigen::Vector3d& e, const Eigen::Vector3d& s_hat,
                                const Strengths& strengths, double alpha) {
  const double eq = equivalent_strain(mode, e, alpha);
  const IndexParts parts = hashin_parts(mode, s_hat, strengths, alpha);
  if (!(eq > 0.0) || parts.quadratic + parts.linear < 1.0) return std::nullopt;
  const double ratio = onset_ratio(parts);
  return Onset{ratio * eq, ratio * equivalent_stress(mode, e, s_hat, alpha)};
}

std::optional<double> toughness_of(const FractureToughness& g, DamageMode mode) {
  switch (mode) {
  case DamageMode::fibre_tension:
    return g.G_ft;
  case DamageMode::fibre_compression:
    return g.G_fc;
  case DamageMode::matrix_tension:
    return g.G_mt;
  case DamageMode::matrix_compression:
    return g.G_mc;
  }
  return std::nullopt;
}

std::string_view toughness_name(DamageMode mode) {
  switch (mode) {
  case DamageMode::fibre_tension:
    return "G_ft";
  case DamageMode::fibre_compression:
    return "G_fc";
  case DamageMode::matrix_tension:
    return "G_mt";
  case DamageMode::matrix_compression:
    return "G_mc";
  }
  return "G";
}

/// Names of the data the law needs and `m` lacks (or gives as non-positive).
std::vector<std::string> missing_data(const Material& m) {
  std::vector<std::string> missing;
  const std::pair<const char*, std::optional<double>> strengths[] = {
      {"Xt", m.strength.Xt}, {"Xc", m.strength.Xc},   {"Yt", m.strength.Yt},
      {"Yc", m.strength.Yc}, {"S12", m.strength.S12}, {"S23", m.strength.S23}};
  for (const auto& [name, value] : strengths)
    if (!value || !(*value > 0.0)) missing.emplace_back(name);
  for (const DamageMode mode : all_damage_modes) {
    const std::optional<double> g = toughness_of(m.toughness, mode);
    if (!g || !(*g > 0.0)) missing.emplace_back(toughness_name(mode));
  }
  append_missing_moduli(m, missing);
  return missing;
}

} // namespace

double hashin_plane_stress_index(DamageMode mode, const Eigen::Vector3d& effective_stress,
                                 const Strengths& strengths, double alpha) {
  const IndexParts p = hashin_parts(mode, effective_stress, strengths, alpha);
  return p.quadratic + p.linear;
}

Strengths band_limited_strengths(const Material& m, double characteristic_length, double alpha,
                                 double margin) {
  // No snap-back (PD10) ⇔ σ⁰ε⁰ ≤ 2G/L_c at every onset. At an onset of the undamaged ply the product of a
  // fibre mode is σ11ε11 = σ11²/E1 − ν12σ11σ22/E1 ≤ X²/E1 + ν12·X·Ymax/E1; of a matrix mode
  // σ22ε22 + τ12γ12 ≤ max(Y²/E2, S12²/G12) + ν12·Y·Xmax/E1 (Hashin's index = 1 splits σ22² and τ12²).
  // Each strength becomes the largest one for which that bound stays below margin²·2G/L_c.
  const FractureToughness& g = m.toughness;
  const Strengths& deck = m.strength;
  const auto budget = [&](double G) { return margin * margin * 2.0 * G / characteristic_length; };
  // Largest X with X²/E + cross·X ≤ c.
  const auto largest = [](double modulus, double cross, double c) {
    return 0.5 * modulus * (-cross + std::sqrt(cross * cross + 4.0 * c / modulus));
  };
  Strengths s = deck;
  const double y_max = std::max(*deck.Yt, *deck.Yc);
  const double fibre_cross = m.nu12 * y_max / m.E1;
  s.Xt = std::min(*deck.Xt, largest(m.E1, fibre_cross, budget(*g.G_ft)));
  s.Xc = std::min(*deck.Xc, largest(m.E1, fibre_cross, budget(*g.G_fc)));
  const double matrix_cross = m.nu12 * std::max(*s.Xt, *s.Xc) / m.E1;
  s.Yt = std::min(*deck.Yt, largest(m.E2, matrix_cross, budget(*g.G_mt)));
  s.Yc = std::min(*deck.Yc, largest(m.E2, matrix_cross, budget(*g.G_mc)));
  // S12 enters both matrix modes (and fibre tension if α > 0): S12²/G12 ≤ c − cross·Y of each.
  double shear_budget =
      std::min(budget(*g.G_mt) - matrix_cross * *s.Yt, budget(*g.G_mc) - matrix_cross * *s.Yc);
  if (alpha > 0.0) shear_budget = std::min(shear_budget, budget(*g.G_ft) - fibre_cross * *s.Xt);
  s.S12 = std::min(*deck.S12, std::sqrt(m.G12 * std::max(shear_budget, 0.0)));
  return s;
}

PlyDamageLaw::PlyDamageLaw(Material material, PlyDamageOptions options)
    : material_(std::move(material)), options_(options) {
  const std::vector<std::string> missing = missing_data(material_);
  if (!missing.empty())
    throw std::invalid_argument(fmt::format("progressive damage of material '{}' needs positive {}",
                                            material_.name, fmt::join(missing, ", ")));
  check_options(options_);
  for (const DamageMode mode : all_damage_modes)
    toughness_[mode] = *toughness_of(material_.toughness, mode);
  undamaged_stiffness_ = degraded_reduced_stiffness(material_, {});
  undamaged_transverse_shear_ = degraded_transverse_shear(material_, 0.0);
  const Strengths& st = material_.strength;
  const auto inv2 = [](double x) { return 1.0 / (x * x); };
  screen_.ft = inv2(*st.Xt);
  screen_.fc = inv2(*st.Xc);
  screen_.mt = inv2(*st.Yt);
  screen_.shear = inv2(*st.S12);
  screen_.ft_shear = options_.alpha * screen_.shear;
  screen_.mc = inv2(2.0 * *st.S23);
  screen_.mc_linear = (*st.Yc * *st.Yc * screen_.mc - 1.0) / *st.Yc;
}

double PlyDamageLaw::HashinScreen::index(const Eigen::Vector3d& s) const {
  const double t2 = s(2) * s(2);
  const double fibre = s(0) >= 0.0 ? ft * s(0) * s(0) + ft_shear * t2 : fc * s(0) * s(0);
  const double matrix =
      s(1) >= 0.0 ? mt * s(1) * s(1) + shear * t2 : mc * s(1) * s(1) + mc_linear * s(1) + shear * t2;
  return std::max(fibre, matrix);
}

double PlyDamageLaw::onset_bound(const Eigen::Vector3d& s0, const Eigen::Vector3d& s1) const {
  double b = std::max(screen_.index(s0), screen_.index(s1));
  for (const int c : {0, 1})
    if (s0(c) * s1(c) < 0.0) {
      const double f = s0(c) / (s0(c) - s1(c)); // where σ_cc = 0
      const double t = s0(2) + f * (s1(2) - s0(2));
      b = std::max(b, (c == 0 ? screen_.ft_shear : screen_.shear) * t * t);
    }
  return b;
}

PlySecant PlyDamageLaw::secant_at(const PerDamageMode& damage, const PlyStrain& strain) const {
  return secant_of(material_, damage, active_modes(material_, damage, strain.in_plane));
}

double PlyDamageLaw::max_characteristic_length(DamageMode mode) const {
  const Material& m = material_;
  const Strengths& st = m.strength;
  const double G = toughness_[mode];
  const auto band_limit = [G](double modulus, double strength) {
    return 2.0 * G * modulus / (strength * strength);
  };
  const double shear = band_limit(m.G12, *st.S12);
  switch (mode) {
  case DamageMode::fibre_tension:
    return options_.alpha > 0.0 ? std::min(band_limit(m.E1, *st.Xt), shear) : band_limit(m.E1, *st.Xt);
  case DamageMode::fibre_compression:
    return band_limit(m.E1, *st.Xc);
  case DamageMode::matrix_tension:
    return std::min(band_limit(m.E2, *st.Yt), shear);
  case DamageMode::matrix_compression:
    return std::min(band_limit(m.E2, *st.Yc), shear);
  }
  return 0.0;
}

Strengths PlyDamageLaw::band_limited_strengths(double characteristic_length) const {
  return plyimpact::band_limited_strengths(material_, characteristic_length, options_.alpha);
}

double PlyDamageLaw::max_characteristic_length() const {
  double smallest = std::numeric_limits<double>::infinity();
  for (const DamageMode mode : all_damage_modes)
    smallest = std::min(smallest, max_characteristic_length(mode));
  return smallest;
}

PlyDamageResponse PlyDamageLaw::update(const PlyDamageState& previous, const PlyStrain& strain,
                                       double characteristic_length, double dt) const {
  PlyDamageResponse r{advance(previous, strain, characteristic_length, dt), {}};
  r.tangent = algorithmic_tangent(previous, r, strain, characteristic_length, dt);
  return r;
}

Eigen::Matrix<double, 5, 5> PlyDamageLaw::algorithmic_tangent(const PlyDamageState& previous,
                                                              const PlyDamageUpdate& next,
                                                              const PlyStrain& strain,
                                                              double characteristic_length, double dt) const {
  const Material& m = material_;
  const double alpha = options_.alpha;
  const Eigen::Vector3d& e = strain.in_plane;
  const ActiveModes active = active_modes(m, previous.regularised_damage, e);
  const double eta = options_.viscosity;
  const double weight = eta > 0.0 ? dt / (eta + dt) : 1.0;
  Eigen::Matrix<double, 5, 5> tangent = Eigen::Matrix<double, 5, 5>::Zero();
  tangent.topLeftCorner<3, 3>() = next.secant;
  tangent.bottomRightCorner<2, 2>() = next.transverse_shear_secant;
  for (const DamageMode mode : all_damage_modes) {
    // A mode grows with the strain where it had initiated, is loaded beyond its largest strain and
    // lies on the softening branch: ∂d_I/∂κ_I there.
    if (!active.contains(mode) || !previous.initiated(mode)) continue;
    const double eq = equivalent_strain(mode, e, alpha);
    const double kappa = next.state.max_equivalent_strain[mode];
    const double onset = next.state.onset_equivalent_strain[mode];
    const double final_strain = final_equivalent_strain(
        toughness_[mode], next.state.onset_equivalent_stress[mode], characteristic_length);
    if (!(eq > previous.max_equivalent_strain[mode] && kappa > onset && kappa < final_strain)) continue;
    Eigen::Matrix<double, 1, 5> dd = Eigen::Matrix<double, 1, 5>::Zero();
    dd.head<3>() = weight * softening_slope(kappa, onset, final_strain) *
                   equivalent_strain_gradient(mode, e, alpha).transpose();
    tangent += stress_sensitivity(m, next.state.regularised_damage, active, strain, mode) * dd;
  }
  return tangent;
}

PlyDamageUpdate PlyDamageLaw::advance(const PlyDamageState& previous, const PlyStrain& strain,
                                      double characteristic_length, double dt) const {
  check_increment(characteristic_length, dt);

  const Material& m = material_;
  const double alpha = options_.alpha;
  const Eigen::Vector3d& e = strain.in_plane;

  // Loaded modes and effective stress, with the committed damage.
  const ActiveModes active = active_modes(m, previous.regularised_damage, e);
  const Eigen::Vector3d s_hat = effective_stress(m, stiffness_damage(previous.regularised_damage, active), e);

  // Most points of a structure never reach a failure surface: answer them without the damage algebra.
  const auto below_surface = [&](DamageMode mode) {
    return hashin_plane_stress_index(mode, s_hat, m.strength, alpha) < 1.0;
  };
  if (previous.virgin() && below_surface(active.fibre) && below_surface(active.matrix))
    return elastic_update(previous, strain, undamaged_stiffness_, undamaged_transverse_shear_);

  PlyDamageUpdate r;
  r.state = previous;
  r.state.strain = strain;
  for (const DamageMode mode : all_damage_modes) {
    if (!active.contains(mode)) continue;
    const double eq = equivalent_strain(mode, e, alpha);
    if (!r.state.initiated(mode)) {
      const std::optional<Onset> onset = initiation(mode, e, s_hat, m.strength, alpha);
      if (!onset) continue;
      r.state.onset_equivalent_strain[mode] = onset->strain;
      r.state.onset_equivalent_stress[mode] = onset->stress;
    }
    soften(mode, eq, toughness_[mode], characteristic_length, previous, r.state, m.name);
  }

  // Viscous regularisation, backward Euler (PD12).
  r.state.regularised_damage =
      regularised(r.state.damage, previous.regularised_damage, options_.viscosity, dt);

  // Degraded stiffness and stresses (PD3)–(PD5).
  const PerDamageMode& dv = r.state.regularised_damage;
  const StiffnessDamage sd = stiffness_damage(dv, active);
  r.secant = degraded_reduced_stiffness(m, sd);
  r.transverse_shear_secant = degraded_transverse_shear(m, sd.transverse_shear);
  r.stress = r.secant * e;
  r.transverse_shear_stress = r.transverse_shear_secant * strain.transverse_shear;

  // Dissipation of the increment, Y_I at the midpoint times the growth of d_v,I (PD11).
  if (dv.values != previous.regularised_damage.values) {
    const PerDamageMode y = thermodynamic_forces(m, midpoint(previous.regularised_damage, dv), active,
                                                 midpoint(previous.strain, strain));
    for (const DamageMode mode : all_damage_modes)
      r.dissipation[mode] = y[mode] * (dv[mode] - previous.regularised_damage[mode]);
  }

  return r;
}

} // namespace plyimpact
