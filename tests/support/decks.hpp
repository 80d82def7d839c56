#pragma once
// Small laminates and plates for tests, written out in full so each test shows its inputs.
#include "plyimpact/fem/discrete_plate.hpp"
#include "plyimpact/laminate/laminate.hpp"
#include "plyimpact/laminate/layup.hpp"

#include <string>

namespace plyimpact::test {

inline Material isotropic(double E, double nu, double rho) {
  Material m;
  m.name = "isotropic";
  m.E1 = m.E2 = E;
  m.G12 = m.G13 = m.G23 = E / (2.0 * (1.0 + nu));
  m.nu12 = nu;
  m.rho = rho;
  return m;
}

inline Material t300_976() {
  Material m;
  m.name = "T300_976";
  m.E1 = 144.8e9;
  m.E2 = 9.65e9;
  m.G12 = m.G13 = 7.10e9;
  m.G23 = 5.92e9;
  m.nu12 = 0.30;
  m.rho = 1389.2;
  return m;
}

/// The data progressive-damage tests add to T300/976: strengths of SPEC §6 (thesis Table 4.2; Xt, Xc
/// as in examples/annex2.toml) and the toughnesses of the docs/progressive_damage.md table.
namespace t300_976_damage {
inline constexpr double Xt = 1.5e9, Xc = 1.2e9, Yt = 55.2e6, Yc = 294.0e6, S12 = 101.1e6, S23 = 32.94e6;
inline constexpr double G_ft = 91.6e3, G_fc = 79.9e3, G_mt = 277.0, G_mc = 788.0;
} // namespace t300_976_damage

/// T300/976 with everything the progressive damage law needs.
inline Material t300_976_with_damage_data() {
  using namespace t300_976_damage;
  Material m = t300_976();
  m.strength.Xt = Xt;
  m.strength.Xc = Xc;
  m.strength.Yt = Yt;
  m.strength.Yc = Yc;
  m.strength.S12 = S12;
  m.strength.S23 = S23;
  m.toughness.G_ft = G_ft;
  m.toughness.G_fc = G_fc;
  m.toughness.G_mt = G_mt;
  m.toughness.G_mc = G_mc;
  return m;
}

/// T700/M21 as Tan, Falzon, Chiu & Price (Composites Part A 71 (2015) 212–226, Table 1) give it for the
/// Rivallant et al. (2013) coupons (issue 79): E3 = E2, ν13 = ν12 (a plate does not use E3, ν13, ν23). The
/// ply's B-K exponent is not in the paper: the interface's 1.45 (the same M21 resin) is taken. The density
/// is not in the paper either; the point-law tests that use this card do not need one (ρ = 0).
inline Material t700_m21_tan2015() {
  Material m;
  m.name = "T700_M21";
  m.E1 = 130.0e9;
  m.E2 = 7.7e9;
  m.G12 = m.G13 = 4.8e9;
  m.G23 = 3.8e9;
  m.nu12 = 0.3;
  m.strength.Xt = 2080e6;
  m.strength.Xc = 1250e6;
  m.strength.Yt = 60e6;
  m.strength.Yc = 290e6;
  m.strength.S12 = 110e6;
  m.toughness.G_ft = 133e3;
  m.toughness.G_fc = 10e3;
  m.toughness.G_mt = 500.0;
  m.toughness.G_mc = 1600.0;
  m.toughness.G_ms = 1600.0;
  m.toughness.bk_exponent = 1.45;
  return m;
}

/// §3.6 material of the thesis (Table 3.1): E1 = 129, E2 = 7.5, G12 = 3.5 GPa, ν12 = 0.33, ρ = 1540.
inline Material thesis_3_6() {
  Material m;
  m.name = "thesis_3_6";
  m.E1 = 129e9;
  m.E2 = 7.5e9;
  m.G12 = m.G13 = m.G23 = 3.5e9;
  m.nu12 = 0.33;
  m.rho = 1540.0;
  return m;
}

inline Laminate laminate_of(const Material& m, const std::string& layup, double ply_thickness) {
  std::vector<Ply> plies;
  for (const double a : parse_layup(layup))
    plies.push_back({a, ply_thickness, 0});
  return Laminate({m}, plies);
}

inline BoundaryConditions all_edges(const std::string& type) {
  return BoundaryConditions::on_edges(type, type, type, type);
}

} // namespace plyimpact::test
