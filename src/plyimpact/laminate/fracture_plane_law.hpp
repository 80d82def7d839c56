#pragma once
// A ply law whose matrix cracks form on Puck's fracture plane and close under compression (issue 79, first
// stage). Where it differs from PlyDamageLaw (laminate/ply_damage.hpp, Hashin's four modes):
//  - one matrix crack per point, initiated where the fracture-plane index (laminate/fracture_plane.hpp,
//    LaRC04: Pinho et al. 2012) reaches 1; its variables sit in the slot of the mode the plane's normal
//    traction gave at onset (matrix-tension: open, matrix-compression: closed);
//  - crack closure (Maimí et al. 2007): the crack degrades σ22 only while it is open, the shear moduli
//    always; compressive σ22 never softens, so the 0.29 mm band limit of softening it (2E2G/Yc²) does not
//    exist;
//  - the crack softens (crack band, linear) on ε_eq = √(⟨ε22⟩² + γ12²) with the mixed-mode toughness of
//    Benzeggagh & Kenane, G_c = G_mt + (G_ms − G_mt) B^η, B the shear share of the crack's energy at onset
//    (FL1), fixed then;
//  - fibre tension and compression as PlyDamageLaw's (Hashin–Rotem with α; crack band).
// Not yet (the next stage of issue 79, which needs the section to carry inelastic strains): Coulomb
// friction on a closed crack (here the compression raises the onset only, so the band limit of a crack
// sheared under compression is below 2G12G_ms/S12²), the card's non-linear shear with its inelastic strain,
// and τ23, τ13 in the fracture plane's tractions (the section's screen bounds the in-plane stresses).
// Equations and references: docs/progressive_damage.md, "The fracture-plane law".
#include "plyimpact/laminate/fracture_plane.hpp"
#include "plyimpact/laminate/material.hpp"
#include "plyimpact/laminate/ply_law.hpp"

#include <Eigen/Core>

namespace plyimpact {

class FracturePlaneLaw final : public PlyLaw {
public:
  /// Checks that the moduli, Xt, Xc, Yt, Yc, S12, G_ft, G_fc, G_mt, G_ms and bk_exponent are present and
  /// positive and that the fracture angle (53° when absent) lies in (45°, 90°); throws
  /// std::invalid_argument naming what is missing.
  explicit FracturePlaneLaw(Material material, PlyDamageOptions options = {});

  [[nodiscard]] PlyDamageUpdate advance(const PlyDamageState& previous, const PlyStrain& strain,
                                        double characteristic_length, double dt) const override;
  [[nodiscard]] PlySecant secant_at(const PerDamageMode& damage, const PlyStrain& strain) const override;
  /// max of the fibre index and B(σ) = (⟨σ22⟩/Yt)² + (σ22/(2ST))² + (τ12/SL)² at the segment's ends: B
  /// bounds the fracture-plane index on every plane (FL4) and, like the fibre index, is convex.
  [[nodiscard]] double onset_bound(const Eigen::Vector3d& s0, const Eigen::Vector3d& s1) const override;
  /// 2EG/X² of the modes' uniaxial and pure-shear onsets (FL5): fibre tension (E1, G_ft, Xt), fibre
  /// compression (E1, G_fc, Xc), an open crack min(E2 G_mt/Yt², G12 G_ms/S12²)·2, a closed one
  /// 2 G12 G_ms/S12² (compression that raises the onset is checked at onset).
  [[nodiscard]] double band_limit(DamageMode mode) const override;
  /// Xt, Xc, Yt and S12 lowered as band_limited_strengths() (ply_damage.hpp) does with G_ms for the shear;
  /// Yc is kept: it starts no softening.
  [[nodiscard]] Strengths band_limited_strengths(double characteristic_length) const override;

  [[nodiscard]] const Material& material() const override { return material_; }
  [[nodiscard]] const Eigen::Matrix3d& undamaged_stiffness() const override { return undamaged_stiffness_; }
  [[nodiscard]] const Eigen::Matrix2d& undamaged_transverse_shear() const override {
    return undamaged_transverse_shear_;
  }
  /// ST, ηT, ηL of the material's fracture plane.
  [[nodiscard]] const FracturePlaneStrengths& plane_strengths() const { return plane_; }
  /// G_c(B) = G_mt + (G_ms − G_mt) B^η (FL1) [J/m²].
  [[nodiscard]] double crack_toughness(double shear_share) const;

private:
  /// The fracture-plane index F (FP2) where the bound (FL4) reaches 1, the bound below: compared with 1,
  /// the same answer at less cost.
  [[nodiscard]] double matrix_index(const Eigen::Vector3d& effective_stress) const;
  /// B(σ) = (⟨σ22⟩/Yt)² + (σ22/(2ST))² + (τ12/SL)² ≥ F on every plane (FL4).
  [[nodiscard]] double matrix_bound(const Eigen::Vector3d& stress) const;
  /// Initiates the crack in `state`, whose effective stress has reached the fracture-plane surface, where
  /// it has an opening or a shear to soften on.
  void initiate_crack(PlyDamageState& state, const Eigen::Vector3d& e, const Eigen::Vector3d& s_hat) const;

  Material material_;
  PlyDamageOptions options_;
  FracturePlaneStrengths plane_;
  Eigen::Matrix3d undamaged_stiffness_;
  Eigen::Matrix2d undamaged_transverse_shear_;
};

} // namespace plyimpact
