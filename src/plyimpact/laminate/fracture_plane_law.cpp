// The fracture-plane ply law (laminate/fracture_plane_law.hpp). Equations (FL1)–(FL5) and (PD3)–(PD12):
// docs/progressive_damage.md.
#include "plyimpact/laminate/fracture_plane_law.hpp"
#include "plyimpact/laminate/macaulay.hpp"
#include "plyimpact/laminate/ply_damage.hpp"
#include "plyimpact/laminate/ply_damage_algebra.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace plyimpact {
namespace {

namespace algebra = ply_damage_algebra;

constexpr double default_fracture_angle = 53.0 * std::numbers::pi / 180.0;

/// The crack's two slots: which one holds its variables (the one that initiated), or none yet.
std::optional<DamageMode> crack_slot(const PlyDamageState& s) {
  if (s.initiated(DamageMode::matrix_tension)) return DamageMode::matrix_tension;
  if (s.initiated(DamageMode::matrix_compression)) return DamageMode::matrix_compression;
  return std::nullopt;
}

/// The damage that acts on the stiffness, in PlyDamageLaw's terms: the fibre modes as they are, the crack
/// (whichever slot holds it) as the open matrix mode, nothing for the closed one — so that the
/// Matzenmiller–Lubliner–Taylor algebra degrades σ22 only while the crack is open (closure) and the shear
/// moduli always.
PerDamageMode acting(const PerDamageMode& d) {
  PerDamageMode a = d;
  a[DamageMode::matrix_tension] = d[DamageMode::matrix_tension] + d[DamageMode::matrix_compression];
  a[DamageMode::matrix_compression] = 0.0;
  return a;
}

std::vector<std::string> missing_fracture_plane_data(const Material& m) {
  std::vector<std::string> missing;
  const std::pair<const char*, std::optional<double>> data[] = {
      {"Xt", m.strength.Xt},      {"Xc", m.strength.Xc},
      {"Yt", m.strength.Yt},      {"Yc", m.strength.Yc},
      {"S12", m.strength.S12},    {"G_ft", m.toughness.G_ft},
      {"G_fc", m.toughness.G_fc}, {"G_mt", m.toughness.G_mt},
      {"G_ms", m.toughness.G_ms}, {"bk_exponent", m.toughness.bk_exponent}};
  for (const auto& [name, value] : data)
    if (!value || !(*value > 0.0)) missing.emplace_back(name);
  algebra::append_missing_moduli(m, missing);
  return missing;
}

} // namespace

FracturePlaneLaw::FracturePlaneLaw(Material material, PlyDamageOptions options)
    : material_(std::move(material)), options_(options) {
  const std::vector<std::string> missing = missing_fracture_plane_data(material_);
  if (!missing.empty())
    throw std::invalid_argument(fmt::format("the fracture-plane ply law of material '{}' needs positive {}",
                                            material_.name, fmt::join(missing, ", ")));
  const double alpha0 = material_.strength.fracture_angle.value_or(default_fracture_angle);
  if (!(alpha0 > 0.25 * std::numbers::pi && alpha0 < 0.5 * std::numbers::pi))
    throw std::invalid_argument(fmt::format(
        "the fracture-plane ply law of material '{}': the fracture angle must lie between 45 and 90 deg, "
        "got {:.4g} deg (about 53 deg for carbon/epoxy)",
        material_.name, alpha0 * 180.0 / std::numbers::pi));
  algebra::check_options(options_);
  plane_ = fracture_plane_strengths(material_.strength, alpha0);
  undamaged_stiffness_ = algebra::degraded_reduced_stiffness(material_, {});
  undamaged_transverse_shear_ = algebra::degraded_transverse_shear(material_, 0.0);
}

double FracturePlaneLaw::crack_toughness(double shear_share) const {
  const FractureToughness& g = material_.toughness;
  return *g.G_mt + (*g.G_ms - *g.G_mt) * std::pow(shear_share, *g.bk_exponent); // (FL1)
}

double FracturePlaneLaw::matrix_index(const Eigen::Vector3d& s_hat) const {
  const double bound = matrix_bound(s_hat); // (FL4): most points are below it, and it costs no search
  return bound < 1.0 ? bound : critical_fracture_plane({s_hat(1), s_hat(2)}, plane_).index;
}

double FracturePlaneLaw::matrix_bound(const Eigen::Vector3d& s) const {
  const auto sq = [](double x) { return x * x; };
  return sq(macaulay(s(1)) / plane_.Yt) + sq(s(1) / (2.0 * plane_.ST)) + sq(s(2) / plane_.SL); // (FL4)
}

void FracturePlaneLaw::initiate_crack(PlyDamageState& state, const Eigen::Vector3d& e,
                                      const Eigen::Vector3d& s_hat) const {
  const double eq = algebra::equivalent_strain(DamageMode::matrix_tension, e, 0.0);
  if (!(eq > 0.0)) return; // nothing to soften on (pure transverse compression)
  // The onset point: the ray R·ε that meets the surface, F(R σ̂) = 1 (FL2). F grows with R on every plane
  // (the compressive branch's denominators grow more slowly than its numerators), so bisect.
  double lo = 0.0, hi = 1.0;
  for (int i = 0; i < 60 && hi - lo > 1e-14; ++i) {
    const double mid = 0.5 * (lo + hi);
    (matrix_index(mid * s_hat) < 1.0 ? lo : hi) = mid;
  }
  const double R = hi;
  const FracturePlane plane = critical_fracture_plane({R * s_hat(1), R * s_hat(2)}, plane_);
  const bool open = tractions_on_plane({R * s_hat(1), R * s_hat(2)}, plane.angle).normal >= 0.0;
  const DamageMode slot = open ? DamageMode::matrix_tension : DamageMode::matrix_compression;
  const double normal_energy = macaulay(s_hat(1)) * macaulay(e(1));
  const double shear_energy = s_hat(2) * e(2);
  state.onset_equivalent_strain[slot] = R * eq;
  state.onset_equivalent_stress[slot] = R * (normal_energy + shear_energy) / eq;
  state.crack_toughness = crack_toughness(shear_energy / (normal_energy + shear_energy));
}

PlyDamageUpdate FracturePlaneLaw::advance(const PlyDamageState& previous, const PlyStrain& strain,
                                          double characteristic_length, double dt) const {
  algebra::check_increment(characteristic_length, dt);
  const Material& m = material_;
  const double alpha = options_.alpha;
  const Eigen::Vector3d& e = strain.in_plane;

  // Loaded modes (open or closed crack) and effective stress, with the committed damage.
  const PerDamageMode acting_before = acting(previous.regularised_damage);
  const algebra::ActiveModes active = algebra::active_modes(m, acting_before, e);
  const Eigen::Vector3d s_hat =
      algebra::effective_stress(m, algebra::stiffness_damage(acting_before, active), e);
  const DamageMode fibre = active.fibre;
  const double fibre_index = hashin_plane_stress_index(fibre, s_hat, m.strength, alpha);

  const bool cracked = crack_slot(previous).has_value();
  const double crack_index = cracked ? 0.0 : matrix_index(s_hat); // once: the elastic test and the onset
  if (previous.virgin() && fibre_index < 1.0 && crack_index < 1.0)
    return algebra::elastic_update(previous, strain, undamaged_stiffness_, undamaged_transverse_shear_);

  PlyDamageUpdate r;
  r.state = previous;
  r.state.strain = strain;

  // The fibre mode that is loaded: Hashin–Rotem onset on the ray (the index is quadratic in σ̂).
  const double fibre_eq = algebra::equivalent_strain(fibre, e, alpha);
  if (!r.state.initiated(fibre) && fibre_index >= 1.0 && fibre_eq > 0.0) {
    const double R = 1.0 / std::sqrt(fibre_index);
    r.state.onset_equivalent_strain[fibre] = R * fibre_eq;
    r.state.onset_equivalent_stress[fibre] = R * algebra::equivalent_stress(fibre, e, s_hat, alpha);
  }
  if (!cracked && crack_index >= 1.0) initiate_crack(r.state, e, s_hat);

  // Softening of each initiated, loaded mode (PD9, PD10): the fibre mode with its toughness, the crack
  // with the one its onset fixed.
  if (r.state.initiated(fibre))
    algebra::soften(fibre, fibre_eq,
                    *(fibre == DamageMode::fibre_tension ? m.toughness.G_ft : m.toughness.G_fc),
                    characteristic_length, previous, r.state, m.name);
  if (const std::optional<DamageMode> slot = crack_slot(r.state))
    algebra::soften(*slot, algebra::equivalent_strain(DamageMode::matrix_tension, e, 0.0),
                    r.state.crack_toughness, characteristic_length, previous, r.state, m.name);

  // Viscous regularisation, backward Euler (PD12).
  r.state.regularised_damage =
      algebra::regularised(r.state.damage, previous.regularised_damage, options_.viscosity, dt);

  // Degraded stiffness and stresses (PD3)–(PD5), with the crack acting as an open or closed matrix mode.
  const PerDamageMode acting_after = acting(r.state.regularised_damage);
  const algebra::StiffnessDamage sd = algebra::stiffness_damage(acting_after, active);
  r.secant = algebra::degraded_reduced_stiffness(m, sd);
  r.transverse_shear_secant = algebra::degraded_transverse_shear(m, sd.transverse_shear);
  r.stress = r.secant * e;
  r.transverse_shear_stress = r.transverse_shear_secant * strain.transverse_shear;

  // Dissipation, Y at the midpoint times the growth of each stiffness variable (PD11); the crack's force is
  // that of the acting open matrix variable, booked to the crack's slot.
  if (r.state.regularised_damage.values != previous.regularised_damage.values) {
    const PerDamageMode y = algebra::thermodynamic_forces(m, algebra::midpoint(acting_before, acting_after),
                                                          active, algebra::midpoint(previous.strain, strain));
    for (const DamageMode mode : all_damage_modes) {
      const double growth = r.state.regularised_damage[mode] - previous.regularised_damage[mode];
      const DamageMode force = algebra::is_matrix(mode) ? DamageMode::matrix_tension : mode;
      r.dissipation[mode] = y[force] * growth;
    }
  }
  return r;
}

PlySecant FracturePlaneLaw::secant_at(const PerDamageMode& damage, const PlyStrain& strain) const {
  const PerDamageMode d = acting(damage);
  return algebra::secant_of(material_, d, algebra::active_modes(material_, d, strain.in_plane));
}

double FracturePlaneLaw::onset_bound(const Eigen::Vector3d& s0, const Eigen::Vector3d& s1) const {
  const Strengths& st = material_.strength;
  const auto sq = [](double x) { return x * x; };
  const auto bound = [&](const Eigen::Vector3d& s) {
    const double fibre = sq(s(0) / (s(0) >= 0.0 ? *st.Xt : *st.Xc)) + options_.alpha * sq(s(2) / plane_.SL);
    return std::max(fibre, matrix_bound(s));
  };
  return std::max(bound(s0), bound(s1));
}

double FracturePlaneLaw::band_limit(DamageMode mode) const {
  const Material& m = material_;
  const auto limit = [](double modulus, double toughness, double strength) {
    return 2.0 * modulus * toughness / (strength * strength); // (FL5)
  };
  const double shear = limit(m.G12, *m.toughness.G_ms, *m.strength.S12);
  switch (mode) {
  case DamageMode::fibre_tension:
    return limit(m.E1, *m.toughness.G_ft, *m.strength.Xt);
  case DamageMode::fibre_compression:
    return limit(m.E1, *m.toughness.G_fc, *m.strength.Xc);
  case DamageMode::matrix_tension:
    return std::min(limit(m.E2, *m.toughness.G_mt, *m.strength.Yt), shear);
  case DamageMode::matrix_compression:
    return shear;
  }
  return 0.0;
}

Strengths FracturePlaneLaw::band_limited_strengths(double characteristic_length) const {
  Material shear_as_compression = material_;
  shear_as_compression.toughness.G_mc = material_.toughness.G_ms;
  Strengths s =
      plyimpact::band_limited_strengths(shear_as_compression, characteristic_length, options_.alpha);
  s.Yc = material_.strength.Yc;
  return s;
}

} // namespace plyimpact
