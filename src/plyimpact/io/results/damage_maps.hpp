#pragma once
// Damage maps (thesis Fig. 4.19–4.23): for each criterion and ply/interface with failures, the plate
// with its element grid and the failed Gauss points coloured by onset time, drawn by gnuplot
// (Debian's gnuplot-nox) from a generated, self-contained script that is kept next to the images.
#include "plyimpact/analysis/fields/damage_tracker.hpp"
#include "plyimpact/fem/mesh.hpp"
#include "plyimpact/io/mesh/test_rigs.hpp"

#include <filesystem>
#include <string>
#include <vector>

namespace plyimpact {

struct DamageMapFiles {
  std::vector<std::filesystem::path> images;  ///< .svg and .png written
  std::vector<std::filesystem::path> scripts; ///< .gp scripts (always written)
  std::string warning;                        ///< non-empty when gnuplot could not be run
};

/// The subfolder of a results folder that holds the damage maps.
inline constexpr const char* damage_maps_folder = "damage_maps";

/// Writes damage_map_<criterion>_<ply|interface><n>.{gp,svg,png} into `dir` (atomically; created when
/// there is a map to write). An impact run passes RESULTS/damage_maps_folder.
[[nodiscard]] DamageMapFiles write_damage_maps(const std::filesystem::path& dir, const Mesh& mesh,
                                               const std::vector<DamageOnset>& onsets,
                                               const RigOutline& rig = {});

/// The gnuplot script of one map (exposed for tests).
[[nodiscard]] std::string damage_map_script(const Mesh& mesh, const std::vector<DamageOnset>& points,
                                            const std::string& title, const std::string& svg_path,
                                            const std::string& png_path, const RigOutline& rig = {});

} // namespace plyimpact
