#pragma once
// Orthotropic ply material (SPEC §2, thesis chapter 1) and its strengths (SPEC §6).
#include <optional>
#include <string>

namespace plyimpact {

/// Ply strengths in material axes, all positive (compressive values given as magnitudes).
/// Each is optional: a failure criterion that needs a missing strength reports which one.
struct Strengths {
  std::optional<double> Xt;  ///< longitudinal tension [Pa]
  std::optional<double> Xc;  ///< longitudinal compression [Pa]
  std::optional<double> Yt;  ///< transverse tension [Pa]
  std::optional<double> Yc;  ///< transverse compression [Pa]
  std::optional<double> S12; ///< in-plane shear strength S_L [Pa]
  std::optional<double> S23; ///< transverse shear strength S_T (S_i of Choi–Chang) [Pa]
  std::optional<double> Zt;  ///< through-thickness tension [Pa]
  std::optional<double> Da;  ///< Choi–Chang delamination constant (2.43) [-]
  /// α0, the angle of the fracture plane in pure transverse compression (fracture-plane law,
  /// laminate/fracture_plane.hpp); absent = 53° (Puck & Schürmann 1998; Dávila et al. 2005) [rad]
  std::optional<double> fracture_angle;
  friend bool operator==(const Strengths&, const Strengths&) = default;
};

/// Intralaminar fracture toughnesses of the ply, one per Hashin failure mode, for the progressive
/// damage law (laminate/ply_damage.hpp): the energy dissipated per unit crack area when the mode
/// runs to complete failure [J/m²]. Each is optional; the damage law reports which one is missing.
/// Published values and their sources: docs/progressive_damage.md.
struct FractureToughness {
  std::optional<double> G_ft; ///< fibre tension (translaminar, tensile) [J/m²]
  std::optional<double> G_fc; ///< fibre compression (kink band) [J/m²]
  std::optional<double> G_mt; ///< matrix tension (intralaminar, transverse tension / in-plane shear) [J/m²]
  std::optional<double> G_mc; ///< matrix compression (intralaminar, transverse compression) [J/m²]
  /// Intralaminar mode II (in-plane shear) toughness of a matrix crack, the shear end of the fracture-plane
  /// law's mixed-mode toughness (laminate/fracture_plane_law.hpp) [J/m²]
  std::optional<double> G_ms;
  /// η of the Benzeggagh–Kenane mixed-mode toughness of a matrix crack (fracture-plane law) [-]
  std::optional<double> bk_exponent;
  friend bool operator==(const FractureToughness&, const FractureToughness&) = default;
};

/// Transversely isotropic / orthotropic ply material (SI).
struct Material {
  std::string name;
  double E1 = 0.0;   ///< fibre-direction modulus [Pa]
  double E2 = 0.0;   ///< transverse modulus [Pa]
  double G12 = 0.0;  ///< in-plane shear modulus [Pa]
  double G13 = 0.0;  ///< transverse shear modulus, 1–3 plane [Pa]
  double G23 = 0.0;  ///< transverse shear modulus, 2–3 plane [Pa]
  double nu12 = 0.0; ///< major Poisson ratio [-]
  double rho = 0.0;  ///< density [kg/m³]
  Strengths strength{};
  FractureToughness toughness{};

  /// Minor Poisson ratio ν21 = ν12·E2/E1 (1.3).
  [[nodiscard]] double nu21() const { return nu12 * E2 / E1; }
  friend bool operator==(const Material&, const Material&) = default;
};

} // namespace plyimpact
