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
#include "plyimpact/fem/plate_model.hpp"
#include "plyimpact/io/plots.hpp"
#include "plyimpact/io/ply_damage_table.hpp"

#include <Eigen/Core>

#include <array>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace plyimpact {

/// The file name of the per-element damage in a results folder.
inline constexpr const char* damage_elements_file = "damage_elements.csv";

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
[[nodiscard]] std::string damage_elements_csv(const PlateModel& model, const PlyDamageTable& table);

/// Reads damage_elements.csv (columns by name). Throws std::runtime_error naming the file and the line
/// when a column is missing or a value is not a number.
[[nodiscard]] std::vector<DamageElementRow> read_damage_elements_csv(const std::filesystem::path& csv);

/// The projected damage: per element the largest damage variable of any ply, as (element, value) in
/// the order of first appearance in `rows`.
[[nodiscard]] std::vector<std::pair<int, double>> projected_damage(const std::vector<DamageElementRow>& rows);

/// The damage maps of a results folder: one per ply and the projected map; none without
/// damage_elements.csv. `impact_point` [m]: marked on every map when given.
[[nodiscard]] std::vector<PlotSpec> ply_damage_map_plots(const std::vector<DamageElementRow>& rows,
                                                         const std::optional<Eigen::Vector2d>& impact_point);

/// The maps of results folder `dir` (reads damage_elements.csv and the impact point of deck.toml).
[[nodiscard]] std::vector<PlotSpec> ply_damage_map_plots(const std::filesystem::path& dir);

} // namespace plyimpact
