#pragma once
// Small SVG pictures for the HTML report (io/results/html_report.hpp): line plots with 1-2-5 ticks, a ply
// stack and a damage-onset map. Each is one <svg> element meant to be inlined in HTML (no XML declaration, no
// script, no external reference), sized by its viewBox.
#include "plyimpact/analysis/fields/damage_tracker.hpp"
#include "plyimpact/fem/mesh.hpp"
#include "plyimpact/io/mesh/test_rigs.hpp"
#include "plyimpact/laminate/laminate.hpp"

#include <Eigen/Core>

#include <array>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace plyimpact {

struct PlotSeries {
  std::string label;
  std::vector<double> x, y;
  std::string color = "#1f77b4";
  bool dashed = false;
  bool line = true;     ///< join the points
  bool markers = false; ///< a dot at every point (a sweep's cases)
};

struct LinePlot {
  std::string title, x_label, y_label; ///< labels carry their unit: "time [ms]"
  std::vector<PlotSeries> series;
};

/// Text safe inside HTML and SVG (&, <, >, " escaped).
[[nodiscard]] std::string xml_escaped(std::string_view text);

/// The colour of a ply of orientation `angle_deg` in the ply stacks (SVG and gnuplot), "#rrggbb": 0° blue,
/// 90° red, ±45° green and purple, other angles between by their angle.
[[nodiscard]] std::string ply_colour(double angle_deg);

/// Tick positions covering [lo, hi] with a step of 1, 2 or 5 × 10^k and about `target` intervals; the
/// first and last ticks enclose the range (a zero-width range is widened).
[[nodiscard]] std::vector<double> nice_ticks(double lo, double hi, int target = 5);

/// A line plot, `width` × `height` px: axes, grid, ticks, labels, one polyline per series and a legend
/// when there are several. Non-finite points are skipped.
[[nodiscard]] std::string svg_line_plot(const LinePlot& plot, int width = 640, int height = 360);

/// The laminate as a stack of plies, ply 1 (the impacted face) on top, coloured by orientation and
/// labelled with the angle and the material where there is room; a red line under each ply of
/// `interfaces_after_ply` (1-based), the interfaces of a stacked plate that may delaminate.
[[nodiscard]] std::string svg_ply_stack(const Laminate& laminate,
                                        const std::vector<int>& interfaces_after_ply = {});

/// The nodes of the supports of one type, drawn with one marker and named in the legend.
struct SupportMarks {
  std::string label; ///< the sets and the type in words: "x0, xa: simply supported, hard (…)"
  std::vector<Eigen::Vector2d> points; ///< [m]
};

/// What the plan view of a model before its run shows (issue 82, `plyimpact preview`).
struct ModelPlan {
  const Mesh& mesh;
  std::vector<SupportMarks> supports;
  RigOutline rig;
  std::optional<Eigen::Vector2d> impact_point; ///< [m]; none for a static, modal or buckling deck
  double contact_radius = 0.0;  ///< the largest contact radius, drawn around the impact point [m]
  bool contact_reached = false; ///< the radius a run reached (report.html), not the one expected (preview)
};

/// The colour of the `k`-th support type (0-based) in the plan view and its PNG.
[[nodiscard]] const char* support_colour(std::size_t k);

/// The plan view: the elements (corner to corner), the supported nodes by type, the rig's window and clamp
/// tips, the impact point and the expected contact circle, with a legend under the plate.
[[nodiscard]] std::string svg_model_plan(const ModelPlan& plan, int width = 640);

/// The plate's elements (corner to corner) with every damage onset drawn at its Gauss point, coloured by
/// its time (legend from the first to the last onset), the impact point marked, and the rig's window edge
/// and clamp tips where the plate sits on a rig (RigOutline: the onsets at the tips are the point supports'
/// singular stresses).
[[nodiscard]] std::string svg_onset_map(const Mesh& mesh, const std::vector<DamageOnset>& onsets,
                                        double impact_x, double impact_y, const RigOutline& rig = {},
                                        int width = 640);

/// A C-scan of the delaminations seen from the impacted face (time of flight): at each interface point
/// the shallowest interface that has delaminated there (d = 1) hides those below it, as the ultrasonic echo
/// returns from the first delaminated interface it meets. Per point: the 1-based index of that interface
/// (from the impacted face), 0 where no interface has delaminated. `point_damage` is per interface and
/// point (DelaminationResult::point_damage).
[[nodiscard]] std::vector<int> shallowest_delaminated(const std::vector<std::vector<double>>& point_damage);
/// The colour of interface `i` (1-based, from the impacted face) in a C-scan: tab10, repeating after ten.
[[nodiscard]] const char* cscan_colour(int i);

/// A C-scan picture: every interface point's cell (`cells`, corners counter-clockwise [m]) filled with the
/// colour of its shallowest delaminated interface (`interface_of_point`, shallowest_delaminated), white
/// where none has; a legend naming each interface by the ply above it (`after_ply`) with its projected
/// share; the impact point and the rig marked as in svg_onset_map.
struct CscanMap {
  const std::vector<std::array<Eigen::Vector2d, 4>>& cells;
  const std::vector<double>& area; ///< per point [m²]
  const std::vector<int>& interface_of_point;
  const std::vector<int>& after_ply;
  double impact_x = 0.0, impact_y = 0.0;
  RigOutline rig;
};
[[nodiscard]] std::string svg_cscan_map(const CscanMap& map, int width = 640);

} // namespace plyimpact
