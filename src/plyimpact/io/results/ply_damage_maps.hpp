#pragma once
// The plies' damage at the end of a progressive-damage run, as a file and as pictures:
//
//   damage_elements.csv   one row per element and ply (every element of the mesh, so the file alone
//                         redraws the plate): element (1-based), ply (1-based, 1 = impacted face),
//                         angle_deg, x_m, y_m (element centre), d_ft, d_fc, d_mt, d_mc (the largest of
//                         each damage variable over the element's integration points in that ply), and
//                         the element's corners x1_m, y1_m … x4_m, y4_m (counter-clockwise).
//   plots/damage_map_plyNN, plots/damage_map_projected   (`plyimpact plot DIR`): per ply the largest
//                         of its four damage variables per element, and the projected map (largest over
//                         the plies: what a C-scan sees), on a 0..1 colour scale over the element grid,
//                         with the impact point of DIR/deck.toml marked.
//
// The interfaces of a stacked plate (docs/delamination.md) in the same way:
//
//   delamination_elements.csv   one row per element: element (1-based), x_m, y_m (centre) and
//                         d_after_ply_P for each interface (the largest cohesive damage of the element's
//                         interface points, 0 intact, 1 delaminated; P the ply above the interface).
//   delamination_points.csv   one row per interface point (every interface has the same points): point
//                         (1-based), x_m, y_m (centre of its cell), area_m2 (the area it stands for),
//                         d_after_ply_P for each interface, and the corners x1_m, y1_m … x4_m, y4_m of
//                         the part of its element it stands for (its tributary cell, counter-clockwise).
//   plots/delamination_map_after_plyPP, plots/delamination_map_projected   per interface the damage of
//                         every point drawn over its cell, and the largest over the interfaces (what a
//                         C-scan of the delaminations shows); the titles give the delaminated (d = 1) and
//                         softening areas, the sums of the cells' areas, equal to summary.json's.
//   plots/delamination_cscan   each point in the colour of the shallowest interface delaminated there (a
//                         C-scan from the impacted face: shallowest_delaminated, io/results/svg_plot.hpp).
#include "plyimpact/analysis/impact/impact_result.hpp"
#include "plyimpact/fem/discrete_plate.hpp"
#include "plyimpact/io/mesh/test_rigs.hpp"
#include "plyimpact/io/results/plots.hpp"
#include "plyimpact/io/results/ply_damage_table.hpp"

#include <Eigen/Core>

#include <array>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace plyimpact {

/// The file name of the per-element damage in a results folder.
inline constexpr const char* damage_elements_file = "damage_elements.csv";

/// The file name of the interfaces' per-element damage in a results folder.
inline constexpr const char* delamination_elements_file = "delamination_elements.csv";
/// The file name of the interfaces' per-point damage in a results folder.
inline constexpr const char* delamination_points_file = "delamination_points.csv";

/// One row of damage_elements.csv.
struct DamageElementRow {
  int element = 0; ///< 1-based
  int ply = 0;     ///< 1-based
  double angle_deg = 0.0;
  Eigen::Vector2d centre = Eigen::Vector2d::Zero(); ///< [m]
  PerDamageMode damage;                             ///< d_ft, d_fc, d_mt, d_mc
  std::array<Eigen::Vector2d, 4> corners{};         ///< [m], counter-clockwise
  /// The largest of the four damage variables.
  [[nodiscard]] double largest() const;
};

/// damage_elements.csv of `table` on `model` (numbers as the shortest text that reads back the same).
[[nodiscard]] std::string damage_elements_csv(const DiscretePlate& model, const PlyDamageTable& table);

/// delamination_elements.csv of a stacked plate's interfaces on `mesh`.
[[nodiscard]] std::string delamination_elements_csv(const Mesh& mesh, const DelaminationResult& result);
/// delamination_points.csv of a stacked plate's interfaces.
[[nodiscard]] std::string delamination_points_csv(const DelaminationResult& result);

/// What a map marks besides the damage: the impact point [m] and the rig's window and clamp tips.
struct MapMarks {
  std::optional<Eigen::Vector2d> impact_point;
  RigOutline rig;
};

/// Reads damage_elements.csv (columns by name). Throws std::runtime_error naming the file and the line
/// when a column is missing or a value is not a number.
[[nodiscard]] std::vector<DamageElementRow> read_damage_elements_csv(const std::filesystem::path& csv);

/// The projected damage: per element the largest damage variable of any ply, as (element, value) in
/// the order of first appearance in `rows`.
[[nodiscard]] std::vector<std::pair<int, double>> projected_damage(const std::vector<DamageElementRow>& rows);

/// The damage maps of a results folder: one per ply and the projected map; none without
/// damage_elements.csv. The marks are drawn on every map.
[[nodiscard]] std::vector<PlotSpec> ply_damage_map_plots(const std::vector<DamageElementRow>& rows,
                                                         const MapMarks& marks);

/// The maps of results folder `dir` (reads damage_elements.csv, and the impact point and the rig of
/// deck.toml).
[[nodiscard]] std::vector<PlotSpec> ply_damage_map_plots(const std::filesystem::path& dir);

/// The interfaces' maps of results folder `dir`: one per interface and the projected map (reads
/// delamination_points.csv and the impact point of deck.toml; none without the file). Throws
/// std::runtime_error naming the file and line of a missing column or a value that is not a number.
[[nodiscard]] std::vector<PlotSpec> delamination_map_plots(const std::filesystem::path& dir);

} // namespace plyimpact
