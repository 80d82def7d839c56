#pragma once
// The laminate: the cross-section between the plate element and the ply materials (SPEC §2).
// Holds the plies from ply 1 (impacted face, z = −h/2) down and their integrated stiffnesses.
#include "plyimpact/laminate/material.hpp"
#include "plyimpact/laminate/ply_stiffness.hpp"

#include <Eigen/Core>
#include <array>
#include <cstddef>
#include <vector>

namespace plyimpact {

/// One ply: fibre angle θ (degrees, from x towards y), thickness and index of its material.
struct Ply {
  double angle_deg = 0.0;
  double thickness = 0.0;   ///< [m]
  std::size_t material = 0; ///< index into Laminate::materials()
  friend bool operator==(const Ply&, const Ply&) = default;
};

/// In-plane engineering constants of the laminate from A⁻¹·h.
struct EngineeringConstants {
  double Ex, Ey, Gxy, nuxy;
};

class Laminate {
public:
  /// Plies listed from ply 1 (impacted face) down; `shear_correction` is K of F = K Σ Q̄ t (default 5/6).
  Laminate(std::vector<Material> materials, std::vector<Ply> plies, double shear_correction = 5.0 / 6.0,
           ReducedStiffnessModel model = ReducedStiffnessModel::exact);

  [[nodiscard]] const std::vector<Material>& materials() const { return materials_; }
  [[nodiscard]] const std::vector<Ply>& plies() const { return plies_; }
  [[nodiscard]] std::size_t ply_count() const { return plies_.size(); }
  [[nodiscard]] const Material& material_of(std::size_t ply) const {
    return materials_[plies_[ply].material];
  }
  [[nodiscard]] double thickness() const { return thickness_; }
  [[nodiscard]] double shear_correction() const { return shear_correction_; }
  [[nodiscard]] ReducedStiffnessModel stiffness_model() const { return model_; }

  /// z of the upper (impact-side) and lower face of ply k (0-based); z_top < z_bottom (z points down).
  [[nodiscard]] double z_top(std::size_t k) const { return z_[k]; }
  [[nodiscard]] double z_bottom(std::size_t k) const { return z_[k + 1]; }

  /// Ply stiffness in plate axes: Q̄ (x, y, xy) and transverse shear Q̄s (yz, xz), without K.
  [[nodiscard]] const Eigen::Matrix3d& Qbar(std::size_t k) const { return qbar_[k]; }
  [[nodiscard]] const Eigen::Matrix2d& Qbar_shear(std::size_t k) const { return qbar_shear_[k]; }

  /// Laminate stiffnesses (1.24)/(1.25). A [Pa·m], B [Pa·m²], D [Pa·m³], F [Pa·m] in order (yz, xz).
  [[nodiscard]] const Eigen::Matrix3d& A() const { return A_; }
  [[nodiscard]] const Eigen::Matrix3d& B() const { return B_; }
  [[nodiscard]] const Eigen::Matrix3d& D() const { return D_; }
  [[nodiscard]] const Eigen::Matrix2d& F() const { return F_; }
  /// Mass moments I0 [kg/m²], I1 [kg/m], I2 [kg] (2.109).
  [[nodiscard]] const std::array<double, 3>& inertia() const { return inertia_; }

  /// The same materials, plies, shear correction and stiffness model (what the laminate is built from).
  friend bool operator==(const Laminate& a, const Laminate& b) {
    return a.materials_ == b.materials_ && a.plies_ == b.plies_ &&
           a.shear_correction_ == b.shear_correction_ && a.model_ == b.model_;
  }
  [[nodiscard]] EngineeringConstants engineering_constants() const;
  /// B = 0 relative to A·h (a symmetric stacking of identical plies gives exactly 0 up to round-off).
  [[nodiscard]] bool is_symmetric(double rel_tol = 1e-10) const;
  /// A16 = A26 = 0 relative to A11.
  [[nodiscard]] bool is_balanced(double rel_tol = 1e-10) const;

private:
  std::vector<Material> materials_;
  std::vector<Ply> plies_;
  double shear_correction_;
  ReducedStiffnessModel model_;
  double thickness_ = 0.0;
  std::vector<double> z_;
  std::vector<Eigen::Matrix3d> qbar_;
  std::vector<Eigen::Matrix2d> qbar_shear_;
  Eigen::Matrix3d A_, B_, D_;
  Eigen::Matrix2d F_;
  std::array<double, 3> inertia_{};
};

/// Modified Hertz constant k = (4/3)√R / ((1 − νi²)/Ei + 1/E2) [N/m^1.5] (SPEC §4, thesis (2.5)).
[[nodiscard]] double hertz_constant(double radius, double E_impactor, double nu_impactor, double E2_plate);

} // namespace plyimpact
