#pragma once
// The starting deck `plyimpact init` writes (docs/deck.md, "A starting deck"): a drop-weight impact on a
// rig preset with a card of the material library, every value commented, the ones a user must make their
// own marked EDIT. Written from the same names the parser reads (rig presets, library cards), and parsed
// by the tests: a deck from init runs to the end unchanged where its card gives a density.
#include <string>

namespace plyimpact {

struct StartingDeckChoice {
  std::string rig = "aitm-1-0010";   ///< a [rig] preset of a coupon: "astm-d7136" or "aitm-1-0010"
  std::string material = "T300-976"; ///< a card of the material library
};

/// The deck's text. Throws std::invalid_argument naming the choices where `choice` names an unknown rig
/// or card.
[[nodiscard]] std::string starting_deck(const StartingDeckChoice& choice);

} // namespace plyimpact
