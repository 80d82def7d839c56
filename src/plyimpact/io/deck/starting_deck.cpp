#include "plyimpact/io/deck/starting_deck.hpp"

#include "plyimpact/io/deck/material_library.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <stdexcept>

namespace plyimpact {

namespace {

/// [materials.ply] taking the card; a card without a density leaves rho for the user, commented out, so
/// that the deck is refused with the library's message until it is given.
std::string material_table(const std::string& card) {
  const toml::table library = material_library();
  const toml::table* t = library[card].as_table();
  if (t == nullptr)
    throw std::invalid_argument(fmt::format("init: no card '{}' in the material library (cards: {})", card,
                                            fmt::join(material_library_names(), ", ")));
  std::string text =
      fmt::format("[materials.ply]\n"
                  "library = \"{}\"   # `plyimpact materials {}`: its values and source; a key\n"
                  "                    # written here replaces the card's\n",
                  card, card);
  if (!t->contains("rho"))
    text += "# rho = ...        # kg/m^3, EDIT: the card's source gives no density; give yours, with its "
            "source\n";
  return text;
}

/// [rig] and [impactor]: the ASTM rig's energy is the standard's; the AITM rig's is the deck's.
std::string rig_and_impactor(const std::string& rig) {
  if (rig == "astm-d7136")
    return "[rig]\n"
           "preset = \"astm-d7136\"       # 150 x 100 mm coupon on a 125 x 75 mm window, four clamps, 16 mm "
           "nose\n"
           "\n"
           "[impactor]                  # energy: the standard's 6.7 J/mm x h unless `energy` is given\n"
           "mass = 5.5                  # kg, EDIT: your drop weight\n"
           "E = 210e9                   # Pa, steel\n"
           "nu = 0.3\n";
  if (rig == "aitm-1-0010")
    return "[rig]\n"
           "preset = \"aitm-1-0010\"      # 150 x 100 mm coupon on a 125 x 75 mm window, four clamps, 16 mm "
           "nose\n"
           "\n"
           "[impactor]\n"
           "mass = 2.0                  # kg, EDIT: your drop weight (2 kg in the AITM studies)\n"
           "energy = 6.5                # J, EDIT: your test's energy (AITM 1-0010 has no energy rule)\n"
           "E = 210e9                   # Pa, steel\n"
           "nu = 0.3\n";
  throw std::invalid_argument(fmt::format(
      "init: no coupon rig '{}' (rigs: astm-d7136, aitm-1-0010; a circular rig needs its diameter: "
      "docs/mesh.md)",
      rig));
}

} // namespace

std::string starting_deck(const StartingDeckChoice& choice) {
  const std::string material = material_table(choice.material);
  const std::string rig = rig_and_impactor(choice.rig);
  return fmt::format(
      "# A starting deck written by `plyimpact init`: a drop-weight impact on the {rig} rig with the\n"
      "# library's {card} card. Lines marked EDIT are the ones to make yours; docs/deck.md lists every key.\n"
      "#\n"
      "#   plyimpact impact THIS.toml -o results/THIS\n"
      "#\n"
      "# The run is linear and elastic: for a deflection beyond about 0.3 h set nonlinear = true, and for\n"
      "# damage uncomment [damage] and [delamination] below (their keys: docs/progressive_damage.md,\n"
      "# docs/delamination.md).\n"
      "title = \"Drop-weight impact, {rig} rig, {card}\"\n"
      "analysis = \"impact\"\n"
      "\n"
      "{material}"
      "\n"
      "[laminate]\n"
      "material = \"ply\"\n"
      "layup = \"[45/0/-45/90]2s\"     # EDIT: your stacking sequence, first ply on the impacted face\n"
      "ply_thickness = 0.25e-3       # m, EDIT: your cured ply thickness (here h = 4 mm)\n"
      "\n"
      "{rig_tables}"
      "\n"
      "# [damage]\n"
      "# model = \"progressive\"        # ply damage: the card needs strengths and toughnesses\n"
      "#\n"
      "# [delamination]\n"
      "# interfaces = \"orientation-changes\"   # cohesive interfaces where the ply angle changes, with\n"
      "#                                        # G_Ic, G_IIc and the strengths (docs/delamination.md)\n",
      fmt::arg("rig", choice.rig), fmt::arg("card", choice.material), fmt::arg("material", material),
      fmt::arg("rig_tables", rig));
}

} // namespace plyimpact
