#include "plyimpact/io/plate_from_deck.hpp"

namespace plyimpact {

PlateModel plate_from_deck(const Deck& deck) {
  return {*deck.laminate, *deck.plate, deck.mesh.value_or(MeshSpec{}), *deck.boundary};
}

} // namespace plyimpact
