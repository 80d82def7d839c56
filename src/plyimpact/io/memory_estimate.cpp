#include "plyimpact/io/memory_estimate.hpp"

#include "plyimpact/analysis/guards.hpp"
#include "plyimpact/io/system_memory.hpp"

#include <fmt/format.h>

#include <optional>

namespace plyimpact {

void check_memory_before_assembly(const Deck& deck) {
  if (!deck.mesh || deck.mesh->grading || (deck.plate && deck.plate->rigid)) return;
  const std::optional<double> available = available_memory_bytes();
  if (!available) return;
  const MeshMemoryEstimate e = estimate_mesh_memory(deck.mesh->nx, deck.mesh->ny);
  if (e.bytes > *available)
    throw InsufficientMemory(fmt::format(
        "{}: {}", deck.source, memory_refusal_message(deck.mesh->nx, deck.mesh->ny, e, *available)));
}

} // namespace plyimpact
