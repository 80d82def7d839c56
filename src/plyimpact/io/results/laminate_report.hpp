#pragma once
// `plyimpact laminate`: the head of the thesis's Annex 2 (material data, plies, A, B, D, F, inertias).
#include "plyimpact/io/deck/deck.hpp"

#include <string>

namespace plyimpact {

/// Readable summary (engineering units with the unit in every label).
[[nodiscard]] std::string laminate_report_text(const Deck& deck);
/// The same in SI as JSON: thickness, plies, A, B, D, F (yz, xz), inertia, hertz_k (with an impactor), ...
[[nodiscard]] std::string laminate_report_json(const Deck& deck);

/// Hertz constant for the deck: contact.k if given, else the SPEC §4 formula with ply 1's E2.
[[nodiscard]] double contact_stiffness(const Deck& deck);

} // namespace plyimpact
