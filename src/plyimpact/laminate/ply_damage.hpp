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
#include "plyimpact/laminate/ply_law.hpp"

#include <Eigen/Core>

#include <algorithm>
#include <array>
#include <cstddef>
#include <stdexcept>
#include <string>
#include <string_view>

namespace plyimpact {

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
class PlyDamageLaw final : public PlyLaw {
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
                                        double characteristic_length, double dt) const override;

  /// C(d) and the transverse shear secant at the damage variables `damage` (the stiffness variables d_v),
  /// the loaded modes chosen by the signs of the effective stress at `strain` (PD3–PD7); no evolution.
  [[nodiscard]] PlySecant secant_at(const PerDamageMode& damage, const PlyStrain& strain) const override;
  /// Hashin's active indices (fibre, matrix) bounded on the segment: each branch is convex along it and
  /// the stress affine, so the largest active index is at an end or where σ11 (σ22) changes sign, where
  /// both branches reduce to their shear terms.
  [[nodiscard]] double onset_bound(const Eigen::Vector3d& s0, const Eigen::Vector3d& s1) const override;

  /// Largest characteristic length for which mode `mode` softens without snap-back, 2GK/σ_0², in the
  /// uniaxial and pure-shear states that initiate it: fibre tension (Xt, E1) and, if α > 0, pure
  /// shear (S12, G12); fibre compression (Xc, E1); matrix tension (Yt, E2) and pure shear
  /// (S12, G12); matrix compression (Yc, E2) and shear under vanishing compression (S12, G12).
  /// Other stress states are checked at initiation (BandLimitError).
  [[nodiscard]] double max_characteristic_length(DamageMode mode) const;
  [[nodiscard]] double band_limit(DamageMode mode) const override { return max_characteristic_length(mode); }
  /// band_limited_strengths(material(), L_c, α) with the margin 0.95.
  [[nodiscard]] Strengths band_limited_strengths(double characteristic_length) const override;
  /// The smallest of the four: the largest L_c a mesh may have before any point is loaded.
  [[nodiscard]] double max_characteristic_length() const;

  [[nodiscard]] const Material& material() const override { return material_; }
  [[nodiscard]] const PlyDamageOptions& options() const { return options_; }
  /// C(0) = Q (1.3) and diag(G23, G13): the secants of an undamaged point.
  [[nodiscard]] const Eigen::Matrix3d& undamaged_stiffness() const override { return undamaged_stiffness_; }
  [[nodiscard]] const Eigen::Matrix2d& undamaged_transverse_shear() const override {
    return undamaged_transverse_shear_;
  }

private:
  /// C + Σ_I ∂σ/∂d_v,I ⊗ ∂d_v,I/∂ε of the increment `previous` → `next` at `strain`.
  [[nodiscard]] Eigen::Matrix<double, 5, 5>
  algorithmic_tangent(const PlyDamageState& previous, const PlyDamageUpdate& next, const PlyStrain& strain,
                      double characteristic_length, double dt) const;

  /// Hashin's coefficients (PD2) for onset_bound(): 1/Xt², α/S12², 1/Xc², 1/Yt², 1/S12², 1/(2S23)²,
  /// [(Yc/2S23)² − 1]/Yc.
  struct HashinScreen {
    double ft = 0.0, ft_shear = 0.0, fc = 0.0, mt = 0.0, shear = 0.0, mc = 0.0, mc_linear = 0.0;
    /// The active index of the fibre and matrix pairs at stress s (sign conditions applied).
    [[nodiscard]] double index(const Eigen::Vector3d& s) const;
  };

  Material material_;
  PlyDamageOptions options_;
  HashinScreen screen_;
  PerDamageMode toughness_;                    ///< G_I [J/m²]
  Eigen::Matrix3d undamaged_stiffness_;        ///< C(0) = Q (1.3)
  Eigen::Matrix2d undamaged_transverse_shear_; ///< diag(G23, G13)
};

} // namespace plyimpact
