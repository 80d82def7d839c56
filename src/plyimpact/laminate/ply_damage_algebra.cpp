// The algebra the crack-band ply laws share (laminate/ply_damage_algebra.hpp). The equation numbers
// (PD3)–(PD12) refer to docs/progressive_damage.md.
#include "plyimpact/laminate/ply_damage_algebra.hpp"
#include "plyimpact/laminate/macaulay.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>

namespace plyimpact::ply_damage_algebra {

StiffnessDamage stiffness_damage(const PerDamageMode& d, ActiveModes active) {
  const double matrix_intact =
      (1.0 - d[DamageMode::matrix_tension]) * (1.0 - d[DamageMode::matrix_compression]);
  const double intact =
      (1.0 - d[DamageMode::fibre_tension]) * (1.0 - d[DamageMode::fibre_compression]) * matrix_intact;
  return {d[active.fibre], d[active.matrix], 1.0 - intact, 1.0 - matrix_intact};
}

bool is_matrix(DamageMode mode) {
  return mode == DamageMode::matrix_tension || mode == DamageMode::matrix_compression;
}

/// ∂d_t/∂d_I = 1 − d of the other matrix mode for a matrix mode, 0 for a fibre mode.
double transverse_shear_damage_sensitivity(const PerDamageMode& d, DamageMode mode) {
  if (!is_matrix(mode)) return 0.0;
  const DamageMode other =
      mode == DamageMode::matrix_tension ? DamageMode::matrix_compression : DamageMode::matrix_tension;
  return 1.0 - d[other];
}

/// ∂d_s/∂d_I = Π_{J≠I} (1 − d_J).
double shear_damage_sensitivity(const PerDamageMode& d, DamageMode mode) {
  double product = 1.0;
  for (const DamageMode other : all_damage_modes)
    if (other != mode) product *= 1.0 - d[other];
  return product;
}

/// D = 1 − (1 − d_f)(1 − d_m) ν12 ν21 (PD3).
double poisson_denominator(const Material& m, StiffnessDamage d) {
  return 1.0 - (1.0 - d.fibre) * (1.0 - d.matrix) * m.nu12 * m.nu21();
}

/// Matzenmiller–Lubliner–Taylor degraded reduced stiffness (PD3), the inverse of the compliance
/// S(d) = [[1/((1−d_f)E1), −ν21/E2, 0], [−ν12/E1, 1/((1−d_m)E2), 0], [0, 0, 1/((1−d_s)G12)]].
Eigen::Matrix3d degraded_reduced_stiffness(const Material& m, StiffnessDamage d) {
  const double D = poisson_denominator(m, d);
  Eigen::Matrix3d C = Eigen::Matrix3d::Zero();
  C(0, 0) = (1.0 - d.fibre) * m.E1 / D;
  C(1, 1) = (1.0 - d.matrix) * m.E2 / D;
  C(0, 1) = C(1, 0) = (1.0 - d.fibre) * (1.0 - d.matrix) * m.nu21() * m.E1 / D;
  C(2, 2) = (1.0 - d.shear) * m.G12;
  return C;
}

/// Transverse shear stiffness degraded with the matrix damage d_t (PD5), order (23, 13).
Eigen::Matrix2d degraded_transverse_shear(const Material& m, double transverse_shear_damage) {
  Eigen::Matrix2d G = Eigen::Matrix2d::Zero();
  G(0, 0) = (1.0 - transverse_shear_damage) * m.G23;
  G(1, 1) = (1.0 - transverse_shear_damage) * m.G13;
  return G;
}

/// Effective stress σ̂ = M σ = M C(d) ε, M = diag(1/(1−d_f), 1/(1−d_m), 1/(1−d_s)) (PD6), written
/// out so that it stays finite when a variable reaches 1.
Eigen::Vector3d effective_stress(const Material& m, StiffnessDamage d, const Eigen::Vector3d& e) {
  const double D = poisson_denominator(m, d);
  return {(m.E1 * e(0) + (1.0 - d.matrix) * m.nu21() * m.E1 * e(1)) / D,
          ((1.0 - d.fibre) * m.nu12 * m.E2 * e(0) + m.E2 * e(1)) / D, m.G12 * e(2)};
}

/// The active modes by the signs of σ̂11 and σ̂22 (PD7). sign σ̂11 = sign(ε11 + (1 − d_m)ν21 ε22)
/// depends on which matrix variable is active and sign σ̂22 = sign(ε22 + (1 − d_f)ν12 ε11) on which
/// fibre variable is: the fibre mode is settled first (the ν21 term is small), and where the two
/// matrix variables give it opposite signs, tension is taken if it is self-consistent.
ActiveModes active_modes(const Material& m, const PerDamageMode& d, const Eigen::Vector3d& e) {
  const auto fibre_sign = [&](DamageMode matrix) { return e(0) + (1.0 - d[matrix]) * m.nu21() * e(1); };
  const auto matrix_for = [&](DamageMode fibre) {
    return e(1) + (1.0 - d[fibre]) * m.nu12 * e(0) >= 0.0 ? DamageMode::matrix_tension
                                                          : DamageMode::matrix_compression;
  };
  const bool tension_if_mt = fibre_sign(DamageMode::matrix_tension) >= 0.0;
  const bool tension_if_mc = fibre_sign(DamageMode::matrix_compression) >= 0.0;
  bool fibre_tension = tension_if_mt;
  if (tension_if_mt != tension_if_mc)
    fibre_tension = fibre_sign(matrix_for(DamageMode::fibre_tension)) >= 0.0;
  const DamageMode fibre = fibre_tension ? DamageMode::fibre_tension : DamageMode::fibre_compression;
  return {fibre, matrix_for(fibre)};
}

/// Equivalent strain ε_eq = δ_eq/L_c of a mode (PD8), engineering γ12 so that ½σ_eq ε_eq is the
/// mode's strain energy density.
double equivalent_strain(DamageMode mode, const Eigen::Vector3d& e, double alpha) {
  switch (mode) {
  case DamageMode::fibre_tension:
    return std::sqrt(macaulay(e(0)) * macaulay(e(0)) + alpha * e(2) * e(2));
  case DamageMode::fibre_compression:
    return macaulay(-e(0));
  case DamageMode::matrix_tension:
    return std::sqrt(macaulay(e(1)) * macaulay(e(1)) + e(2) * e(2));
  case DamageMode::matrix_compression:
    return std::sqrt(macaulay(-e(1)) * macaulay(-e(1)) + e(2) * e(2));
  }
  return 0.0;
}

/// ∂ε_eq/∂ε (11, 22, 12) of a mode, where ε_eq > 0.
Eigen::Vector3d equivalent_strain_gradient(DamageMode mode, const Eigen::Vector3d& e, double alpha) {
  const double eq = equivalent_strain(mode, e, alpha);
  switch (mode) {
  case DamageMode::fibre_tension:
    return Eigen::Vector3d(macaulay(e(0)), 0.0, alpha * e(2)) / eq;
  case DamageMode::fibre_compression:
    return {e(0) < 0.0 ? -1.0 : 0.0, 0.0, 0.0};
  case DamageMode::matrix_tension:
    return Eigen::Vector3d(0.0, macaulay(e(1)), e(2)) / eq;
  case DamageMode::matrix_compression:
    return Eigen::Vector3d(0.0, -macaulay(-e(1)), e(2)) / eq;
  }
  return Eigen::Vector3d::Zero();
}

/// Equivalent stress σ_eq of a mode (PD8), the work conjugate of ε_eq, from the stress `s` given
/// (the effective stress at initiation, see docs/progressive_damage.md).
double equivalent_stress(DamageMode mode, const Eigen::Vector3d& e, const Eigen::Vector3d& s, double alpha) {
  const double eq = equivalent_strain(mode, e, alpha);
  switch (mode) {
  case DamageMode::fibre_tension:
    return (macaulay(s(0)) * macaulay(e(0)) + alpha * s(2) * e(2)) / eq;
  case DamageMode::fibre_compression:
    return macaulay(-s(0)) * macaulay(-e(0)) / eq;
  case DamageMode::matrix_tension:
    return (macaulay(s(1)) * macaulay(e(1)) + s(2) * e(2)) / eq;
  case DamageMode::matrix_compression:
    return (macaulay(-s(1)) * macaulay(-e(1)) + s(2) * e(2)) / eq;
  }
  return 0.0;
}

/// Linear softening on the equivalent strain (PD9): d = ε_f(κ − ε_0)/(κ(ε_f − ε_0)), 0 below ε_0, 1
/// beyond ε_f.
double softening_damage(double kappa, double onset, double final_strain) {
  if (kappa <= onset) return 0.0;
  if (kappa >= final_strain) return 1.0;
  return final_strain * (kappa - onset) / (kappa * (final_strain - onset));
}

/// dd/dκ on the softening branch.
double softening_slope(double kappa, double onset, double final_strain) {
  return final_strain * onset / (kappa * kappa * (final_strain - onset));
}

/// ε_f = 2G/(σ⁰_eq L_c) (PD10).
double final_equivalent_strain(double toughness, double onset_stress, double characteristic_length) {
  return 2.0 * toughness / (onset_stress * characteristic_length);
}

/// Thermodynamic force Y_I = −∂ψ/∂d_I of each mode (PD11), ψ = ½εᵀC(d)ε + ½γᵀG(d)γ:
/// −∂ψ/∂d_f = σ̂11²/(2E1), −∂ψ/∂d_m = σ̂22²/(2E2), −∂ψ/∂d_s = ½G12γ12², −∂ψ/∂d_t = ½(G23γ23² + G13γ13²),
/// chained through d_f, d_m (active modes only), d_s and d_t.
PerDamageMode thermodynamic_forces(const Material& m, const PerDamageMode& d, ActiveModes active,
                                   const PlyStrain& strain) {
  const Eigen::Vector3d& e = strain.in_plane;
  const Eigen::Vector2d& g = strain.transverse_shear;
  const Eigen::Vector3d s_hat = effective_stress(m, stiffness_damage(d, active), e);
  const double y_fibre = 0.5 * s_hat(0) * s_hat(0) / m.E1;
  const double y_matrix = 0.5 * s_hat(1) * s_hat(1) / m.E2;
  const double y_shear = 0.5 * m.G12 * e(2) * e(2);
  const double y_transverse_shear = 0.5 * (m.G23 * g(0) * g(0) + m.G13 * g(1) * g(1));
  PerDamageMode y;
  for (const DamageMode mode : all_damage_modes) {
    y[mode] = y_shear * shear_damage_sensitivity(d, mode) +
              y_transverse_shear * transverse_shear_damage_sensitivity(d, mode);
    if (mode == active.fibre) y[mode] += y_fibre;
    if (mode == active.matrix) y[mode] += y_matrix;
  }
  return y;
}

/// ∂σ/∂d_I (5-vector, order σ11, σ22, τ12, τ23, τ13) at fixed strain, for the tangent.
Eigen::Matrix<double, 5, 1> stress_sensitivity(const Material& m, const PerDamageMode& d, ActiveModes active,
                                               const PlyStrain& strain, DamageMode mode) {
  const StiffnessDamage sd = stiffness_damage(d, active);
  const double D = poisson_denominator(m, sd);
  const Eigen::Vector3d s_hat = effective_stress(m, sd, strain.in_plane);
  Eigen::Matrix<double, 5, 1> ds = Eigen::Matrix<double, 5, 1>::Zero();
  if (mode == active.fibre) { // −C (∂S/∂d_f) σ
    ds(0) -= s_hat(0) / D;
    ds(1) -= (1.0 - sd.matrix) * m.nu21() * s_hat(0) / D;
  }
  if (mode == active.matrix) { // −C (∂S/∂d_m) σ
    ds(0) -= (1.0 - sd.fibre) * m.nu12 * s_hat(1) / D;
    ds(1) -= s_hat(1) / D;
  }
  ds(2) -= m.G12 * strain.in_plane(2) * shear_damage_sensitivity(d, mode);
  const double transverse = transverse_shear_damage_sensitivity(d, mode);
  ds(3) -= m.G23 * strain.transverse_shear(0) * transverse;
  ds(4) -= m.G13 * strain.transverse_shear(1) * transverse;
  return ds;
}

PlyStrain midpoint(const PlyStrain& a, const PlyStrain& b) {
  return {0.5 * (a.in_plane + b.in_plane), 0.5 * (a.transverse_shear + b.transverse_shear)};
}

PerDamageMode midpoint(const PerDamageMode& a, const PerDamageMode& b) {
  PerDamageMode mid;
  for (std::size_t i = 0; i < mid.values.size(); ++i)
    mid.values[i] = 0.5 * (a.values[i] + b.values[i]);
  return mid;
}
void soften(DamageMode mode, double equivalent, double toughness, double characteristic_length,
            const PlyDamageState& previous, PlyDamageState& next, std::string_view material) {
  const double onset = next.onset_equivalent_strain[mode];
  const double onset_stress = next.onset_equivalent_stress[mode];
  const double final_strain = final_equivalent_strain(toughness, onset_stress, characteristic_length);
  if (!(final_strain > onset)) // band limit (PD10)
    throw BandLimitError(material, mode, characteristic_length, 2.0 * toughness / (onset_stress * onset));
  const double kappa = std::max(previous.max_equivalent_strain[mode], equivalent);
  next.max_equivalent_strain[mode] = kappa;
  next.damage[mode] = std::max(previous.damage[mode], softening_damage(kappa, onset, final_strain));
}

PlyDamageUpdate elastic_update(const PlyDamageState& previous, const PlyStrain& strain,
                               const Eigen::Matrix3d& stiffness, const Eigen::Matrix2d& transverse_shear) {
  PlyDamageUpdate r;
  r.state = previous;
  r.state.strain = strain;
  r.secant = stiffness;
  r.transverse_shear_secant = transverse_shear;
  r.stress = r.secant * strain.in_plane;
  r.transverse_shear_stress = r.transverse_shear_secant * strain.transverse_shear;
  return r;
}

void append_missing_moduli(const Material& m, std::vector<std::string>& missing) {
  const std::pair<const char*, double> moduli[] = {
      {"E1", m.E1}, {"E2", m.E2}, {"G12", m.G12}, {"G13", m.G13}, {"G23", m.G23}};
  for (const auto& [name, value] : moduli)
    if (!(value > 0.0)) missing.emplace_back(name);
}

void check_options(const PlyDamageOptions& options) {
  if (!(options.alpha >= 0.0 && options.alpha <= 1.0))
    throw std::invalid_argument(
        fmt::format("progressive damage: alpha must lie in [0, 1], got {}", options.alpha));
  if (!(options.viscosity >= 0.0))
    throw std::invalid_argument(
        fmt::format("progressive damage: the viscosity must be >= 0 s, got {}", options.viscosity));
}

void check_increment(double characteristic_length, double dt) {
  if (!(characteristic_length > 0.0))
    throw std::invalid_argument(fmt::format(
        "progressive damage: the characteristic length must be > 0 m, got {}", characteristic_length));
  if (!(dt >= 0.0))
    throw std::invalid_argument(fmt::format("progressive damage: the time step must be >= 0 s, got {}", dt));
}

PerDamageMode regularised(const PerDamageMode& damage, const PerDamageMode& previous_regularised,
                          double viscosity, double dt) {
  PerDamageMode dv;
  for (const DamageMode mode : all_damage_modes) {
    const double d = damage[mode];
    dv[mode] = viscosity > 0.0 ? (viscosity * previous_regularised[mode] + dt * d) / (viscosity + dt) : d;
  }
  return dv;
}

PlySecant secant_of(const Material& m, const PerDamageMode& d, ActiveModes active) {
  const StiffnessDamage sd = stiffness_damage(d, active);
  return {degraded_reduced_stiffness(m, sd), degraded_transverse_shear(m, sd.transverse_shear),
          (active.fibre == DamageMode::fibre_compression ? 1U : 0U) |
              (active.matrix == DamageMode::matrix_compression ? 2U : 0U)};
}
} // namespace plyimpact::ply_damage_algebra
