#pragma once
// Pieces of the gnuplot scripts that draw a plate (io/results/damage_maps.hpp, io/results/model_preview.hpp):
// its element sides and the outline of its rig, in mm.
#include "plyimpact/fem/mesh.hpp"
#include "plyimpact/io/mesh/test_rigs.hpp"

#include <string>
#include <utility>

namespace plyimpact {

/// The element sides (corner to corner, once each) as gnuplot arrows, in mm.
[[nodiscard]] std::string element_outlines(const Mesh& mesh);

/// The rig's window edge (dashed) and clamp tips (open circles, clamp_tip_note in the key) as a
/// datablock and its plot clauses (each beginning ", "); empty without a rig.
[[nodiscard]] std::pair<std::string, std::string> rig_outline_layers(const RigOutline& rig);

} // namespace plyimpact
