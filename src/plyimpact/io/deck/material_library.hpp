#pragma once
// The material library: ply cards with their sources, usable by name from a deck
// ([materials.NAME] library = "T700-M21", docs/deck.md "Material library") and listed by
// `plyimpact materials`. A card is a table of the keys of [materials.NAME] in SI units (fracture_angle in
// degrees), with `source` (where every value was read) and `note` (what the source does not give, and
// what was taken instead). A card holds only values its source gives: a key it lacks — the density of the
// Tan et al. cards, say — the deck must give, with its own source.
#include <toml++/toml.h>

#include <string>
#include <string_view>
#include <vector>

namespace plyimpact {

/// The library as TOML text, one table per card (what `plyimpact materials --toml` prints).
[[nodiscard]] std::string_view material_library_toml();

/// The library parsed: one table per card.
[[nodiscard]] toml::table material_library();

/// The cards' names, in the library's order.
[[nodiscard]] std::vector<std::string> material_library_names();

/// The SI unit of a material key of [materials.NAME] ("Pa", "-", "kg/m^3", "J/m^2", "deg"); empty for a key
/// that is not one.
[[nodiscard]] std::string_view material_key_unit(std::string_view key);

/// The keys of a card that are not material constants.
inline constexpr std::string_view library_source_key = "source";
inline constexpr std::string_view library_note_key = "note";

} // namespace plyimpact
