// AS4/PEEK, the material of the delamination tests (Camanho, Dávila & de Moura 2003, as read in
// docs/delamination.md).
#pragma once

#include "plyimpact/laminate/material.hpp"

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

} // namespace plyimpact::test
