#pragma once
// The discretized plate a deck describes.
#include "plyimpact/fem/plate_model.hpp"
#include "plyimpact/io/deck.hpp"

namespace plyimpact {

/// Needs [laminate], [plate], [boundary]; [mesh] defaults to 15 × 11, lumped mass, element "auto".
[[nodiscard]] PlateModel plate_from_deck(const Deck& deck);

} // namespace plyimpact
