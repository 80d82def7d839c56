#pragma once
// Small SVG pictures for the HTML report (io/html_report.hpp): line plots with 1-2-5 ticks, a ply stack
// and a damage-onset map. Each is one <svg> element meant to be inlined in HTML (no XML declaration,
// no script, no external reference), sized by its viewBox.
#include "plyimpact/analysis/damage_tracker.hpp"
#include "plyimpact/fem/mesh.hpp"
#include "plyimpact/io/test_rigs.hpp"
#include "plyimpact/laminate/laminate.hpp"

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

/// Tick positions covering [lo, hi] with a step of 1, 2 or 5 × 10^k and about `target` intervals; the
/// first and last ticks enclose the range (a zero-width range is widened).
[[nodiscard]] std::vector<double> nice_ticks(double lo, double hi, int target = 5);

/// A line plot, `width` × `height` px: axes, grid, ticks, labels, one polyline per series and a legend
/// when there are several. Non-finite points are skipped.
[[nodiscard]] std::string svg_line_plot(const LinePlot& plot, int width = 640, int height = 360);

/// The laminate as a stack of plies, ply 1 (the impacted face) on top, coloured by orientation and
/// labelled with the angle and the material where there is room.
[[nodiscard]] std::string svg_ply_stack(const Laminate& laminate);

/// The plate's elements (corner to corner) with every damage onset drawn at its Gauss point, coloured by
/// its time (legend from the first to the last onset), the impact point marked, and the rig's window edge
/// and clamp tips where the plate sits on a rig (RigOutline: the onsets at the tips are the point supports'
/// singular stresses).
[[nodiscard]] std::string svg_onset_map(const Mesh& mesh, const std::vector<DamageOnset>& onsets,
                                        double impact_x, double impact_y, const RigOutline& rig = {},
                                        int width = 640);

} // namespace plyimpact
