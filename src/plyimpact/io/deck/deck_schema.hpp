#pragma once
// The JSON Schema of a deck (docs/schemas.md), generated from the table of the deck's keys that the parser
// checks every table against (io/deck/deck_keys.hpp): editors that read JSON Schema for TOML (Even Better
// TOML / Taplo, VS Code, JetBrains) complete the keys, show their types and flag a misspelt key. The parser
// stays the judge of values (ranges, units, choices, what goes with what).
#include <nlohmann/json.hpp>

namespace plyimpact {

/// The JSON Schema (draft-07) of a deck: one definition per table of deck_key_tables(), no key outside them.
[[nodiscard]] nlohmann::json deck_json_schema();

} // namespace plyimpact
