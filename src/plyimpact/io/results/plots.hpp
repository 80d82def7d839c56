#pragma once
// Pictures of impact results (`plyimpact plot`): contact force, contact-point deflection and impactor
// velocity versus time, the energy balance, force versus indentation (the Tan–Sun loop, contact part),
// the drop-weight pair force versus impactor displacement and impactor energy versus time and, when the
// run tracked damage, the failed area versus time (small multiples, layers in stacking order). Drawn by
// gnuplot (Debian's gnuplot-nox) from generated scripts that read the results' CSV files directly; the
// scripts are kept next to the images so a picture can be restyled and redrawn by hand. Several results
// folders give overlays (e.g. three impact velocities, thesis Fig. 4.8).
#include <array>
#include <cstddef>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

namespace plyimpact {

/// One curve: a CSV file with a gnuplot `using` expression (named columns), or inline CSV rows
/// (`data`, for curves that need regrouping, e.g. one layer of damage_area.csv); legend title; style.
struct PlotCurve {
  std::filesystem::path csv;
  std::string using_expr;
  std::string title;
  std::string data;            ///< inline CSV (a header line, then x,y rows); replaces csv if set
  std::string style = "lines"; ///< gnuplot style: lines, steps, ... (the width is line_width's)
  std::string colour;          ///< "#rrggbb", or empty for gnuplot's cycle
  double line_width = 2.0;     ///< gnuplot's lw
};

/// One panel of a small-multiples picture: its own title and curves (at most ~10, each distinguishable).
struct PlotPanel {
  std::string title;
  std::vector<PlotCurve> curves;
};

struct PlotSpec {
  std::string name; ///< file stem: <name>.gp, <name>.svg, <name>.png
  std::string title, xlabel, ylabel;
  std::vector<PlotCurve> curves;
  std::string key = "top right"; ///< legend position
  std::string extra;             ///< further gnuplot commands (ranges, ...)
  std::vector<PlotPanel> panels; ///< small multiples (2 columns) instead of `curves` when not empty
};

/// One results folder to draw, with its legend label.
struct PlotRun {
  std::filesystem::path dir;
  std::string label;
  std::filesystem::path
      history; ///< the history to draw (checked, perhaps thinned: io/results/history_check.hpp)
};

inline constexpr int plot_width_px = 900, plot_height_px = 600;
/// Small multiples: a picture of 2 columns, each row of panels this high.
inline constexpr int panels_width_px = 1400, panel_row_height_px = 400;
/// Most curves in one panel: the tab10 palette's ten colours, each used once.
inline constexpr std::size_t max_curves_per_panel = 10;
/// tab10, the ten colours of a panel (and of a C-scan's interfaces, io/results/svg_plot.hpp).
inline constexpr std::array<const char*, max_curves_per_panel> tab10 = {
    "#1f77b4", "#ff7f0e", "#2ca02c", "#d62728", "#9467bd",
    "#8c564b", "#e377c2", "#7f7f7f", "#bcbd22", "#17becf"};

/// Picture size of a spec in pixels: single plots plot_width_px x plot_height_px, small multiples
/// panels_width_px wide and panel_row_height_px per row of two panels.
[[nodiscard]] std::pair<int, int> picture_size(const PlotSpec& spec);

/// The plots for these runs (one run: its own plots; several: overlays of the time histories).
[[nodiscard]] std::vector<PlotSpec> impact_plots(const std::vector<PlotRun>& runs);

/// gnuplot script drawing `spec` to `svg` and `png`; CSV paths are written relative to `cwd`.
[[nodiscard]] std::string gnuplot_script(const PlotSpec& spec, const std::filesystem::path& cwd,
                                         const std::string& svg, const std::string& png);

struct PlotFiles {
  std::vector<std::filesystem::path> images, scripts;
};

/// Draws every spec into `out` (created): <name>.gp always, <name>.svg and <name>.png atomically.
/// Throws std::runtime_error when gnuplot is missing or fails.
[[nodiscard]] PlotFiles draw_plots(const std::vector<PlotSpec>& specs, const std::filesystem::path& out);

/// Legend label of a results folder: "v0 = 2.68 m/s, m = 6.14 kg" from its summary.json, or its name.
[[nodiscard]] std::string run_label(const std::filesystem::path& dir);

} // namespace plyimpact
