#pragma once
// A deck's model before its run (`plyimpact preview`, docs/preview.md): the mesh, supports, rig and impact
// point the run would build, and its settings resolved as the run resolves them — the same case
// description, mesh and rules as the impact, threshold and plate analyses, without assembling or solving.
#include "plyimpact/io/deck/deck.hpp"
#include "plyimpact/io/results/model_preview.hpp"

namespace plyimpact {

/// The preview of `deck`: for an impact or threshold deck, the impact case's plate (`nonlinear` as
/// --nonlinear), impact point, largest contact circle expected (the rigid-target Hertz estimate) and
/// settings; for a static, modal or buckling deck, the plate and its settings. Throws what the run would
/// throw for the same deck before it starts (DeckError, std::invalid_argument, InsufficientMemory).
[[nodiscard]] ModelPreview deck_preview(const Deck& deck, bool nonlinear = false);

} // namespace plyimpact
