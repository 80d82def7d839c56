#pragma once
// The algebra the crack-band ply laws share (PlyDamageLaw, laminate/ply_damage.hpp; FracturePlaneLaw,
// laminate/fracture_plane_law.hpp): the Matzenmiller–Lubliner–Taylor stiffness of a damaged ply, its
// effective stress, which modes are loaded, the equivalent strains and stresses of a mode, linear softening
// by crack band and the energy a damage increment dissipates. Each law decides when a mode initiates and
// with which toughness it softens; this is what they compute alike. Equations (PD3)–(PD12):
// docs/progressive_damage.md.
#include "plyimpact/laminate/material.hpp"
#include "plyimpact/laminate/ply_law.hpp"

#include <Eigen/Core>

#include <string>
#include <string_view>
#include <vector>

namespace plyimpact::ply_damage_algebra {

/// Which fibre and which matrix mode is loaded: the other two keep their damage but do not act on
/// the stiffness and do not grow (Matzenmiller et al. 1995; Lapczyk & Hurtado 2007).
struct ActiveModes {
  DamageMode fibre = DamageMode::fibre_tension;
  DamageMode matrix = DamageMode::matrix_tension;

  [[nodiscard]] bool contains(DamageMode mode) const { return mode == fibre || mode == matrix; }
};

/// The variables that enter the stiffness: d_f, d_m of the active modes, the shear damage
/// d_s = 1 − (1 − d_ft)(1 − d_fc)(1 − d_mt)(1 − d_mc) (PD4) and the transverse shear damage
/// d_t = 1 − (1 − d_mt)(1 − d_mc) (PD5). The two shear variables do not depend on the active modes,
/// so that no shear modulus jumps when a normal stress changes sign.
struct StiffnessDamage {
  double fibre = 0.0;
  double matrix = 0.0;
  double shear = 0.0;
  double transverse_shear = 0.0;
};
/// The stiffness variables of the damage `d` with the loaded modes `active` (PD4, PD5).
[[nodiscard]] StiffnessDamage stiffness_damage(const PerDamageMode& d, ActiveModes active);
[[nodiscard]] bool is_matrix(DamageMode mode);
/// ∂d_t/∂d_I = 1 − d of the other matrix mode for a matrix mode, 0 for a fibre mode.
[[nodiscard]] double transverse_shear_damage_sensitivity(const PerDamageMode& d, DamageMode mode);
/// ∂d_s/∂d_I = Π_{J≠I} (1 − d_J).
[[nodiscard]] double shear_damage_sensitivity(const PerDamageMode& d, DamageMode mode);
/// D = 1 − (1 − d_f)(1 − d_m) ν12 ν21 (PD3).
[[nodiscard]] double poisson_denominator(const Material& m, StiffnessDamage d);
/// The degraded reduced stiffness C(d) (PD3), order (11, 22, 12).
[[nodiscard]] Eigen::Matrix3d degraded_reduced_stiffness(const Material& m, StiffnessDamage d);
/// diag((1 − d_t)G23, (1 − d_t)G13) (PD5), order (23, 13).
[[nodiscard]] Eigen::Matrix2d degraded_transverse_shear(const Material& m, double transverse_shear_damage);
/// The effective stress σ̂ of the strain `e` (PD6), finite when a variable reaches 1.
[[nodiscard]] Eigen::Vector3d effective_stress(const Material& m, StiffnessDamage d,
                                               const Eigen::Vector3d& e);
/// The loaded fibre and matrix modes by the signs of σ̂11 and σ̂22 (PD7).
[[nodiscard]] ActiveModes active_modes(const Material& m, const PerDamageMode& d, const Eigen::Vector3d& e);
/// ε_eq = δ_eq/L_c of a mode (PD8); `alpha` weighs γ12 in fibre tension.
[[nodiscard]] double equivalent_strain(DamageMode mode, const Eigen::Vector3d& e, double alpha);
/// ∂ε_eq/∂ε (11, 22, 12) of a mode, where ε_eq > 0.
[[nodiscard]] Eigen::Vector3d equivalent_strain_gradient(DamageMode mode, const Eigen::Vector3d& e,
                                                         double alpha);
/// σ_eq of a mode (PD8), the work conjugate of ε_eq, from the stress `s`.
[[nodiscard]] double equivalent_stress(DamageMode mode, const Eigen::Vector3d& e, const Eigen::Vector3d& s,
                                       double alpha);
/// Linear softening (PD9): d = ε_f(κ − ε_0)/(κ(ε_f − ε_0)), 0 below ε_0, 1 beyond ε_f.
[[nodiscard]] double softening_damage(double kappa, double onset, double final_strain);
/// dd/dκ on the softening branch.
[[nodiscard]] double softening_slope(double kappa, double onset, double final_strain);
/// ε_f = 2G/(σ⁰_eq L_c) (PD10).
[[nodiscard]] double final_equivalent_strain(double toughness, double onset_stress,
                                             double characteristic_length);
/// One initiated, loaded mode's softening in an increment (PD9, PD10): κ = max(κ_n, ε_eq), d = max(d_n,
/// linear softening from the state's onset to ε_f of `toughness` over L_c), into `next`. Throws
/// BandLimitError (naming `material`) where ε_f ≤ ε_0.
void soften(DamageMode mode, double equivalent, double toughness, double characteristic_length,
            const PlyDamageState& previous, PlyDamageState& next, std::string_view material);
/// The response of a point below every onset surface: `previous` at `strain`, the undamaged secants.
[[nodiscard]] PlyDamageUpdate elastic_update(const PlyDamageState& previous, const PlyStrain& strain,
                                             const Eigen::Matrix3d& stiffness,
                                             const Eigen::Matrix2d& transverse_shear);
/// Y_I = −∂ψ/∂d_I of each mode (PD11).
[[nodiscard]] PerDamageMode thermodynamic_forces(const Material& m, const PerDamageMode& d,
                                                 ActiveModes active, const PlyStrain& strain);
/// ∂σ/∂d_I (σ11, σ22, τ12, τ23, τ13) at fixed strain.
[[nodiscard]] Eigen::Matrix<double, 5, 1> stress_sensitivity(const Material& m, const PerDamageMode& d,
                                                             ActiveModes active, const PlyStrain& strain,
                                                             DamageMode mode);
/// Appends to `missing` the names of the moduli E1, E2, G12, G13, G23 of `m` that are not positive.
void append_missing_moduli(const Material& m, std::vector<std::string>& missing);
/// Throws std::invalid_argument unless 0 ≤ α ≤ 1 and η ≥ 0.
void check_options(const PlyDamageOptions& options);
/// Throws std::invalid_argument unless L_c > 0 and dt ≥ 0: the arguments of an increment.
void check_increment(double characteristic_length, double dt);
/// The viscous regularisation, backward Euler (PD12): d_v = (η d_v,n + Δt d)/(η + Δt), d_v = d when η = 0.
[[nodiscard]] PerDamageMode regularised(const PerDamageMode& damage,
                                        const PerDamageMode& previous_regularised, double viscosity,
                                        double dt);
/// The secants of the damage `d` with the loaded modes `active` (PD3–PD5), and those modes as PlySecant's
/// bits.
[[nodiscard]] PlySecant secant_of(const Material& m, const PerDamageMode& d, ActiveModes active);
[[nodiscard]] PlyStrain midpoint(const PlyStrain& a, const PlyStrain& b);
[[nodiscard]] PerDamageMode midpoint(const PerDamageMode& a, const PerDamageMode& b);

} // namespace plyimpact::ply_damage_algebra
