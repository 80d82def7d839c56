#pragma once
// The plate of the delamination-threshold checks (docs/delamination_threshold.md): isotropic (E = 70 GPa,
// ν = 0.3, so that D is a number), 8 plies, one interface after the fourth (mid-plane), on the `circular`
// rig, with an optional seed — the deck the seeded-delamination tests build their stacked plate from.
#include "plyimpact/io/deck/deck.hpp"

#include <fmt/format.h>

#include <string>

namespace plyimpact::test {

struct SeededPlate {
  double thickness = 2e-3;                              ///< [m], 8 plies
  double rig_diameter = 0.1;                            ///< [m]
  double size_at_impact = 1e-3, max_size = 2.5e-3;      ///< the graded mesh [m]
  double G_Ic = 300.0, G_IIc = 800.0;                   ///< [J/m²]
  double normal_strength = 30e6, shear_strength = 49e6; ///< [Pa]
  double seed_radius = 0.0;                             ///< [m]; 0: none
};

inline constexpr double seeded_plate_E = 70e9, seeded_plate_nu = 0.3;

inline Deck seeded_plate_deck(const SeededPlate& p) {
  return parse_deck(
      fmt::format(R"([materials.iso]
E1 = 70e9
E2 = 70e9
G12 = 26.923076923076923e9
G13 = 26.923076923076923e9
G23 = 26.923076923076923e9
nu12 = 0.3
rho = 2700.0
[laminate]
material = "iso"
layup = "[0_8]"
ply_thickness = {}
[rig]
preset = "circular"
diameter = {}
[mesh]
size_at_impact = {}
max_size = {}
[impactor]
mass = 1.0
radius = 8e-3
E = 207e9
nu = 0.3
velocity = 1.0
[delamination]
interfaces = [4]
G_Ic = {}
G_IIc = {}
bk_exponent = 2.0
normal_strength = {}
shear_strength = {}
)",
                  p.thickness / 8.0, p.rig_diameter, p.size_at_impact, p.max_size, p.G_Ic, p.G_IIc,
                  p.normal_strength, p.shear_strength) +
          (p.seed_radius > 0.0 ? fmt::format("seed_radius = {}\n", p.seed_radius) : std::string()),
      "seeded.toml");
}

} // namespace plyimpact::test
