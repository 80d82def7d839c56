#pragma once
// Navier ply lists built independently from the material constants (0°/90° plies only), so the
// reference solutions do not reuse the project's own laminate code.
#include "plyimpact/laminate/material.hpp"
#include "support/navier.hpp"

#include <vector>

namespace plyimpact::test {

inline std::vector<navier::Ply> navier_cross_ply(const Material& m, const std::vector<double>& angles,
                                                 double t) {
  const double nu21 = m.nu12 * m.E2 / m.E1, d = 1.0 - m.nu12 * nu21;
  std::vector<navier::Ply> plies;
  double z = -0.5 * t * static_cast<double>(angles.size());
  for (const double angle : angles) {
    navier::Ply p;
    p.z_top = z;
    p.z_bottom = z += t;
    const bool zero = angle == 0.0;
    p.Q11 = (zero ? m.E1 : m.E2) / d;
    p.Q22 = (zero ? m.E2 : m.E1) / d;
    p.Q12 = m.nu12 * m.E2 / d;
    p.Q66 = m.G12;
    p.Q44 = zero ? m.G23 : m.G13; // yz
    p.Q55 = zero ? m.G13 : m.G23; // xz
    p.rho = m.rho;
    plies.push_back(p);
  }
  return plies;
}

} // namespace plyimpact::test
