#pragma once
// Matrix cracking on the fracture plane (Puck & Schürmann 1998; LaRC03/04: Dávila, Camanho & Rose 2005,
// Pinho et al. 2012). A matrix crack runs parallel to the fibres on a plane whose normal is turned by an
// angle α about the fibre axis, from the in-plane transverse direction 2 toward the thickness direction 3.
// With σ33 = 0 (a plate's ply) the tractions on that plane are (FP1)
//
//   σn = σ22 cos²α + 2 τ23 sin α cos α
//   τT = −σ22 sin α cos α + τ23 (cos²α − sin²α)
//   τL = τ12 cos α + τ13 sin α
//
// and the plane cracks when the index (FP2), largest over α, reaches 1:
//
//   σn ≥ 0:  F = (σn/Yt)² + (τT/ST)² + (τL/SL)²
//   σn < 0:  F = (τT/(ST − ηT σn))² + (τL/(SL − ηL σn))²
//
// The compressive normal traction raises the shear the plane carries (Mohr–Coulomb friction, ηT and ηL).
// ST, ηT and ηL follow from Yc and the fracture angle α0 of pure transverse compression (about 53° for
// carbon/epoxy), so that uniaxial σ22 = −Yc cracks the plane α0 (FP3–FP5):
//
//   ST = Yc cos α0 (sin α0 + cos α0 / tan 2α0),  ηT = −1/tan 2α0,  ηL = −SL cos 2α0 / (Yc cos²α0)
//
// SL = S12. Equations, choices and references: docs/progressive_damage.md, "The fracture-plane law".
#include "plyimpact/laminate/material.hpp"

namespace plyimpact {

/// The strengths of the fracture plane.
struct FracturePlaneStrengths {
  double Yt = 0.0;     ///< transverse tensile strength [Pa]
  double Yc = 0.0;     ///< transverse compressive strength [Pa]
  double SL = 0.0;     ///< longitudinal (in-plane) shear strength, S12 [Pa]
  double ST = 0.0;     ///< transverse shear strength of the plane (FP3) [Pa]
  double eta_T = 0.0;  ///< transverse friction coefficient (FP4) [-]
  double eta_L = 0.0;  ///< longitudinal friction coefficient (FP5) [-]
  double alpha0 = 0.0; ///< fracture angle of pure transverse compression [rad]
};

/// ST, ηT, ηL from Yt, Yc, S12 and the fracture angle `alpha0` [rad] (FP3–FP5). Precondition: the three
/// strengths are present and positive, 45° < α0 < 90°.
[[nodiscard]] FracturePlaneStrengths fracture_plane_strengths(const Strengths& strengths, double alpha0);

/// The stresses of a ply that load the fracture plane (σ33 = 0), material axes [Pa].
struct MatrixStress {
  double s22 = 0.0;
  double t12 = 0.0;
  double t23 = 0.0;
  double t13 = 0.0;
};

/// Normal and shear tractions on a plane (FP1) [Pa].
struct PlaneTractions {
  double normal = 0.0;       ///< σn
  double transverse = 0.0;   ///< τT
  double longitudinal = 0.0; ///< τL
};

/// The tractions on the plane at angle `alpha` [rad] (FP1).
[[nodiscard]] PlaneTractions tractions_on_plane(const MatrixStress& s, double alpha);

/// The index of one plane (FP2).
[[nodiscard]] double fracture_plane_index(const PlaneTractions& t, const FracturePlaneStrengths& strengths);

/// The plane with the largest index and that index.
struct FracturePlane {
  double angle = 0.0; ///< α [rad], in [−π/2, π/2]; in [0, π/2] when τ23 = τ13 = 0
  double index = 0.0; ///< F (FP2)
};

/// The critical plane: the largest index over α, found on a grid of 3° refined by golden-section search
/// about its best point (to 1e-7 rad). With τ23 = τ13 = 0 the index is even in α and [0, π/2] is searched.
[[nodiscard]] FracturePlane critical_fracture_plane(const MatrixStress& s,
                                                    const FracturePlaneStrengths& strengths);

} // namespace plyimpact
