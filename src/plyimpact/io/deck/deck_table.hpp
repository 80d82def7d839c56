#pragma once
// The deck parser's entry point for an already parsed TOML table (used by parameter sweeps, which
// edit the table before validating it). Kept out of deck.hpp so that toml++ stays private to io/.
#include "plyimpact/io/deck/deck.hpp"

#include <toml++/toml.h>

#include <string>
#include <string_view>

namespace plyimpact {

/// Validates `root` exactly as parse_deck validates a file; `text` is recorded as Deck::text and
/// `source` names the deck in messages. Throws DeckError. The [sweep] table is accepted and ignored.
[[nodiscard]] Deck parse_deck_table(const toml::table& root, std::string_view text,
                                    const std::string& source);

} // namespace plyimpact
