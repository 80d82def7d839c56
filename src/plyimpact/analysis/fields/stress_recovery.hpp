#pragma once
// Ply and interface stresses from the generalized strains (SPEC §5; thesis 4.3–4.4, 4.7, Annex 3).
//
//   in-plane   ε(z) = ε0 + z κ,  σ = Q̄_k ε(z)                       (plate axes x, y, xy)
//   shear      (τyz, τxz) = Q̄s_k (γyz, γxz)                          (constitutive, constant per ply)
//   averaged   σ̄_k = Q̄_k (ε0 + z̄_k κ), z̄_k the ply mid-plane          (exact mean of the linear field)
//   material   σ11 = c²σx + s²σy + 2cs τxy, σ22 = s²σx + c²σy − 2cs τxy,
//              τ12 = −cs σx + cs σy + (c² − s²) τxy, τ13 = c τxz + s τyz, τ23 = −s τxz + c τyz
#include "plyimpact/fem/plate_element.hpp"
#include "plyimpact/laminate/failure_criteria.hpp"
#include "plyimpact/laminate/laminate.hpp"

#include <Eigen/Core>
#include <vector>

namespace plyimpact {

/// Stresses in plate axes: in-plane (σx, σy, τxy) and transverse shear (τyz, τxz).
struct PlateAxesStress {
  Eigen::Vector3d in_plane = Eigen::Vector3d::Zero();
  Eigen::Vector2d shear = Eigen::Vector2d::Zero(); ///< (τyz, τxz)
};

/// σ at height z inside ply k (z is clamped to the ply).
[[nodiscard]] PlateAxesStress ply_stress(const Laminate& lam, std::size_t k, const GeneralizedStrains& e,
                                         double z);
/// Exact ply average σ̄ of ply k (SPEC §5: the thesis averaged six samples; the field is linear).
[[nodiscard]] PlateAxesStress ply_average_stress(const Laminate& lam, std::size_t k,
                                                 const GeneralizedStrains& e);
/// Rotation to the ply's material axes (1 = fibre) for a ply at `angle_deg`.
[[nodiscard]] PlyStress to_material_axes(const PlateAxesStress& s, double angle_deg);

/// Interface k (between plies k and k+1, 0-based k): the stresses at the interface from each side.
struct InterfaceStress {
  PlyStress upper; ///< in ply k's material axes, at its lower face
  PlyStress lower; ///< in ply k+1's material axes, at its upper face
};
[[nodiscard]] InterfaceStress interface_stress(const Laminate& lam, std::size_t k,
                                               const GeneralizedStrains& e);

/// Derivatives of the generalized strains at a point, for the equilibrium recovery.
struct StrainGradients {
  Eigen::Vector3d membrane_dx, membrane_dy;   ///< ∂ε0/∂x, ∂ε0/∂y
  Eigen::Vector3d curvature_dx, curvature_dy; ///< ∂κ/∂x, ∂κ/∂y
};

/// Equilibrium-based transverse shear τxz(z), τyz(z) (SPEC §5): integrate ∂σx/∂x + ∂τxy/∂y + ∂τxz/∂z = 0
/// (and its y twin) from the top face, remove the linear part that the discrete membrane equilibrium
/// leaves at the bottom face, and scale to the constitutive resultants Q = F γ. The result is
/// continuous across interfaces, zero on both faces and integrates to Q. Returns (τyz, τxz) at each z.
[[nodiscard]] std::vector<Eigen::Vector2d> equilibrium_transverse_shear(const Laminate& lam,
                                                                        const StrainGradients& g,
                                                                        const Eigen::Vector2d& Q,
                                                                        const std::vector<double>& z);

/// ∂ε0/∂x, ∂κ/∂x, ... at (ξ, η) of an axis-aligned rectangular element (the structured meshes).
[[nodiscard]] StrainGradients strain_gradients(const ElementCoordinates& xy, const ElementVector& ue,
                                               double xi, double eta);

} // namespace plyimpact
