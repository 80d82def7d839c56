#pragma once
// Progressive damage of a unidirectional ply at one integration point (issue 18):
//  - initiation: Hashin (1980) in plane stress, four modes, on the effective stress σ̂;
//  - degraded stiffness: Matzenmiller, Lubliner & Taylor (1995), shear damage from all four modes
//    d_s = 1 − (1 − d_ft)(1 − d_fc)(1 − d_mt)(1 − d_mc) (Lapczyk & Hurtado 2007, Abaqus), transverse
//    shear moduli G23, G13 degraded with the matrix damage d_t = 1 − (1 − d_mt)(1 − d_mc);
//  - evolution: linear softening on the equivalent displacement δ_eq = L_c ε_eq of each mode, with
//    crack-band regularisation by the characteristic length L_c so that a mode run to complete
//    failure dissipates its fracture toughness G per unit crack area (Lapczyk & Hurtado 2007);
//  - irreversibility, optional viscous regularisation d_v' = (d − d_v)/η (backward Euler).
// Physics only: material axes, SI. Equations, choices and references: docs/progressive_damage.md.
#include "plyimpact/laminate/material.hpp"

#include <Eigen/Core>

#include <algorithm>
#include <array>
#include <cstddef>
#include <stdexcept>
#include <string>
#include <string_view>

namespace plyimpact {

/// The four failure modes of Hashin's criterion, each with its own damage variable.
enum class DamageMode {
  fibre_tension,      ///< d_ft, active while σ̂11 ≥ 0
  fibre_compression,  ///< d_fc, active while σ̂11 < 0
  matrix_tension,     ///< d_mt, active while σ̂22 ≥ 0
  matrix_compression, ///< d_mc, active while σ̂22 < 0
};

inline constexpr std::array<DamageMode, 4> all_damage_modes{
    DamageMode::fibre_tension, DamageMode::fibre_compression, DamageMode::matrix_tension,
    DamageMode::matrix_compression};

/// "fibre-tension", "fibre-compression", "matrix-tension", "matrix-compression".
[[nodiscard]] std::string_view to_string(DamageMode mode);

/// One T per damage mode, indexed by the mode.
template <class T>
struct ByDamageMode {
  std::array<T, 4> values{};

  [[nodiscard]] T& operator[](DamageMode mode) { return values[static_cast<std::size_t>(mode)]; }
  [[nodiscard]] const T& operator[](DamageMode mode) const { return values[static_cast<std::size_t>(mode)]; }
};

/// One number per damage mode (damage variables, equivalent strains, dissipated energies...).
struct PerDamageMode : ByDamageMode<double> {
  [[nodiscard]] double sum() const { return values[0] + values[1] + values[2] + values[3]; }
};

/// Ply strain in material axes (1 = fibre, 2 = transverse in-plane, 3 = thickness), engineering
/// shear strains. The orders are those of laminate/ply_stiffness.hpp: in-plane (11, 22, 12) as
/// reduced_stiffness(), transverse shear (23, 13) as transverse_shear_stiffness().
struct PlyStrain {
  Eigen::Vector3d in_plane = Eigen::Vector3d::Zero();         ///< ε11, ε22, γ12
  Eigen::Vector2d transverse_shear = Eigen::Vector2d::Zero(); ///< γ23, γ13
};

/// History of one ply at one integration point: a value, copied and committed by the caller once
/// the step has converged. Default-constructed = virgin material.
/// Equivalent displacements are stored per unit characteristic length (equivalent strains
/// ε_eq = δ_eq/L_c), so that the state does not depend on L_c.
struct PlyDamageState {
  PerDamageMode damage;             ///< d_I of the softening law, rate independent, in [0, 1]
  PerDamageMode regularised_damage; ///< d_v,I, viscous; enters the stiffness (= d_I when η = 0)
  PerDamageMode
      max_equivalent_strain; ///< κ_I = largest δ_eq,I/L_c reached, mode I loaded, since it initiated
  PerDamageMode onset_equivalent_strain; ///< δ⁰_eq,I/L_c where mode I initiated; 0 before initiation
  PerDamageMode onset_equivalent_stress; ///< σ⁰_eq,I where mode I initiated [Pa]
  PlyStrain strain;                      ///< the strain of this state (start point of the next increment)

  [[nodiscard]] bool initiated(DamageMode mode) const { return onset_equivalent_strain[mode] > 0.0; }
  /// No mode has initiated and no stiffness variable has moved: the law answers such a ply below every
  /// Hashin surface with its undamaged stiffness and this state, its strain replaced.
  [[nodiscard]] bool virgin() const {
    return std::all_of(all_damage_modes.begin(), all_damage_modes.end(), [this](DamageMode mode) {
      return !initiated(mode) && regularised_damage[mode] == 0.0;
    });
  }
};

/// Settings of the damage law.
struct PlyDamageOptions {
  /// α, weight of the in-plane shear in Hashin's fibre-tension mode, F_ft = (σ̂11/Xt)² + α(τ̂12/S12)²
  /// and δ_eq,ft = L_c √(⟨ε11⟩² + α γ12²). 1 is Hashin (1980); 0 (default, Hashin–Rotem 1973 for this mode)
  /// keeps in-plane shear from breaking fibres, which with α = 1 it does at τ12 = S12
  /// (docs/progressive_damage.md).
  double alpha = 0.0;
  /// η [s], time constant of the viscous regularisation; 0 = rate independent.
  double viscosity = 0.0;
  friend bool operator==(const PlyDamageOptions&, const PlyDamageOptions&) = default;
};

/// What one increment returns to a structure: the state, stresses and secant stiffnesses, and the
/// energy dissipated; what a plate's internal force and secant need.
struct PlyDamageUpdate {
  PlyDamageState state;                    ///< state at the end of the increment
  Eigen::Vector3d stress;                  ///< σ11, σ22, τ12 [Pa]
  Eigen::Vector2d transverse_shear_stress; ///< τ23, τ13 [Pa]
  Eigen::Matrix3d secant;                  ///< C(d), damaged reduced stiffness (11, 22, 12) [Pa]
  /// diag((1 − d_t)G23, (1 − d_t)G13), order (23, 13), with the matrix damage d_t = 1 − (1 − d_mt)(1 − d_mc)
  /// [Pa]: a matrix crack transfers no transverse shear, whether it is open or closed.
  Eigen::Matrix2d transverse_shear_secant;
  PerDamageMode dissipation; ///< energy dissipated in the increment, per mode [J/m³]

  /// True when no stiffness variable d_v is above 0: the secants are the undamaged ones, bit for bit.
  [[nodiscard]] bool undamaged() const { return state.regularised_damage.values == std::array<double, 4>{}; }
};

/// The increment with its algorithmic tangent (for Newton iterations and the finite-difference check).
struct PlyDamageResponse : PlyDamageUpdate {
  /// Algorithmic tangent ∂σ/∂ε in the order (ε11, ε22, γ12, γ23, γ13) [Pa]: the secant plus the
  /// growth of damage with strain. Not symmetric. In the increment where a mode initiates, the
  /// dependence of its onset point on the strain is left out.
  Eigen::Matrix<double, 5, 5> tangent;
};

/// The secant stiffnesses of a ply at a given damage, without evolution (the lagged step).
struct PlySecant {
  Eigen::Matrix3d in_plane;         ///< C(d), order (11, 22, 12) [Pa]
  Eigen::Matrix2d transverse_shear; ///< diag((1 − d_t)G23, (1 − d_t)G13) [Pa]
  /// The loaded modes the strain chose: bit 0 fibre compression, bit 1 matrix compression.
  unsigned modes = 0;
};

/// Thrown when the characteristic length is too large for linear softening: δ_f ≤ δ_0, i.e.
/// L_c ≥ 2G/(σ⁰_eq ε⁰_eq) (= 2GE/σ_0² in a uniaxial state); the law would snap back and dissipate
/// more than G. The remedy is a finer mesh.
class BandLimitError : public std::runtime_error {
public:
  BandLimitError(std::string_view material, DamageMode mode, double characteristic_length,
                 double max_characteristic_length);
  [[nodiscard]] DamageMode mode() const { return mode_; }
  [[nodiscard]] double characteristic_length() const { return characteristic_length_; }
  [[nodiscard]] double max_characteristic_length() const { return max_characteristic_length_; }

private:
  DamageMode mode_;
  double characteristic_length_;
  double max_characteristic_length_;
};

/// The strengths of `m` lowered so that a point of characteristic length L_c softens without snap-back
/// at every onset of the undamaged ply (Maimí et al. 2007, crack band with elements larger than the band
/// limit): each of Xt, Xc, Yt, Yc, S12 above the limit becomes the largest strength for which the onset's
/// σ⁰ε⁰, bounded with the Poisson coupling of the other direction, stays below margin²·2G/L_c. The modes
/// still dissipate G per unit area, at the price of starting earlier than the measured strengths say.
/// S23 is kept. Precondition: the strengths and toughnesses are present and positive.
[[nodiscard]] Strengths band_limited_strengths(const Material& m, double characteristic_length, double alpha,
                                               double margin = 0.95);

/// Hashin (1980) index of one mode, plane stress, on effective stresses σ̂ = (σ̂11, σ̂22, τ̂12),
/// with the misprints of the thesis fixed (SPEC §6); `alpha` weighs τ̂12 in fibre tension:
///  fibre tension:      (σ̂11/Xt)² + α(τ̂12/S12)²
///  fibre compression:  (σ̂11/Xc)²
///  matrix tension:     (σ̂22/Yt)² + (τ̂12/S12)²
///  matrix compression: (σ̂22/(2S23))² + [(Yc/(2S23))² − 1] σ̂22/Yc + (τ̂12/S12)²
/// The sign conditions (which mode is active) are not applied here. Precondition: the strengths
/// the mode reads are present.
[[nodiscard]] double hashin_plane_stress_index(DamageMode mode, const Eigen::Vector3d& effective_stress,
                                               const Strengths& strengths, double alpha);

/// The continuum damage law of one ply material. Construct once per material (it checks that the
/// strengths Xt, Xc, Yt, Yc, S12, S23 and the toughnesses G_ft, G_fc, G_mt, G_mc are present and
/// positive, and throws std::invalid_argument naming what is missing), then call update() at every
/// integration point and ply, as often as the step iterates: it does not modify its inputs.
class PlyDamageLaw {
public:
  explicit PlyDamageLaw(Material material, PlyDamageOptions options = {});

  /// One increment from the committed state `previous` to the total strain `strain`.
  /// `characteristic_length` L_c > 0 [m]: the length of the crack band the point represents;
  /// `dt` ≥ 0 [s]: the time step (used by the viscous regularisation only).
  /// Throws BandLimitError when a mode initiates with L_c above its band limit.
  [[nodiscard]] PlyDamageResponse update(const PlyDamageState& previous, const PlyStrain& strain,
                                         double characteristic_length, double dt) const;
  /// The same increment without the algorithmic tangent, bit for bit the same state, stresses, secants
  /// and dissipation: what an explicit step or a secant iteration needs, at about half the cost.
  [[nodiscard]] PlyDamageUpdate advance(const PlyDamageState& previous, const PlyStrain& strain,
                                        double characteristic_length, double dt) const;

  /// C(d) and the transverse shear secant at the damage variables `damage` (the stiffness variables d_v),
  /// the loaded modes chosen by the signs of the effective stress at `strain` (PD3–PD7); no evolution.
  [[nodiscard]] PlySecant secant_at(const PerDamageMode& damage, const PlyStrain& strain) const;

  /// Largest characteristic length for which mode `mode` softens without snap-back, 2GK/σ_0², in the
  /// uniaxial and pure-shear states that initiate it: fibre tension (Xt, E1) and, if α > 0, pure
  /// shear (S12, G12); fibre compression (Xc, E1); matrix tension (Yt, E2) and pure shear
  /// (S12, G12); matrix compression (Yc, E2) and shear under vanishing compression (S12, G12).
  /// Other stress states are checked at initiation (BandLimitError).
  [[nodiscard]] double max_characteristic_length(DamageMode mode) const;
  /// The smallest of the four: the largest L_c a mesh may have before any point is loaded.
  [[nodiscard]] double max_characteristic_length() const;

  [[nodiscard]] const Material& material() const { return material_; }
  [[nodiscard]] const PlyDamageOptions& options() const { return options_; }
  /// C(0) = Q (1.3) and diag(G23, G13): the secants of an undamaged point.
  [[nodiscard]] const Eigen::Matrix3d& undamaged_stiffness() const { return undamaged_stiffness_; }
  [[nodiscard]] const Eigen::Matrix2d& undamaged_transverse_shear() const {
    return undamaged_transverse_shear_;
  }

private:
  /// The response of a point that has never initiated and does not now: linear elastic.
  [[nodiscard]] PlyDamageUpdate elastic_response(const PlyDamageState& previous,
                                                 const PlyStrain& strain) const;
  /// C + Σ_I ∂σ/∂d_v,I ⊗ ∂d_v,I/∂ε of the increment `previous` → `next` at `strain`.
  [[nodiscard]] Eigen::Matrix<double, 5, 5>
  algorithmic_tangent(const PlyDamageState& previous, const PlyDamageUpdate& next, const PlyStrain& strain,
                      double characteristic_length, double dt) const;

  Material material_;
  PlyDamageOptions options_;
  PerDamageMode toughness_;                    ///< G_I [J/m²]
  Eigen::Matrix3d undamaged_stiffness_;        ///< C(0) = Q (1.3)
  Eigen::Matrix2d undamaged_transverse_shear_; ///< diag(G23, G13)
};

} // namespace plyimpact
