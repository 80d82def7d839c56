// AS4/PEEK, the material of the delamination tests (Camanho, Dávila & de Moura 2003, as read in
// docs/delamination.md): the ply, its interface and a cross-ply laminate.
#pragma once

#include "plyimpact/laminate/cohesive_law.hpp"
#include "plyimpact/laminate/laminate.hpp"
#include "plyimpact/laminate/material.hpp"

#include <vector>

namespace plyimpact::test {

inline Material as4_peek() {
  Material m;
  m.name = "AS4_PEEK";
  m.E1 = 122.7e9;
  m.E2 = 10.1e9;
  m.G12 = 5.5e9;
  m.G13 = 5.5e9;
  m.G23 = 10.1e9 / (2.0 * 1.45);
  m.nu12 = 0.25;
  m.rho = 1600.0;
  return m;
}

/// The interface next to a sub-laminate of the given thickness: Turon's penalty (α = 50), the tabulated
/// strengths N = 80 MPa and S = 100 MPa unless given, G_Ic = 969, G_IIc = 1719 J/m², η = 2.284.
inline CohesiveParameters as4_peek_interface(double sublaminate_thickness, double N = 80e6,
                                             double S = 100e6) {
  CohesiveParameters p;
  p.penalty_stiffness = turon_penalty_stiffness(10.1e9, sublaminate_thickness);
  p.normal_strength = N;
  p.shear_strength = S;
  p.G_Ic = 969.0;
  p.G_IIc = 1719.0;
  p.bk_exponent = 2.284;
  return p;
}

/// [0/90/90/0] of plies of thickness `ply`.
inline Laminate as4_peek_cross_ply(double ply) {
  std::vector<Ply> plies;
  for (const double angle : {0.0, 90.0, 90.0, 0.0})
    plies.push_back({angle, ply, 0});
  return Laminate({as4_peek()}, plies);
}

} // namespace plyimpact::test
