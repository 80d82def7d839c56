#include "plyimpact/io/results/plots.hpp"

#include "plyimpact/io/results/ply_damage_maps.hpp"
#include "plyimpact/io/system/atomic_file.hpp"
#include "plyimpact/io/system/child_process.hpp"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string_view>
#include <tuple>

namespace plyimpact {
namespace {

namespace fs = std::filesystem;

/// Single-quoted gnuplot string (a single quote is doubled).
std::string quoted(const std::string& s) {
  std::string q = "'";
  for (const char c : s)
    q += c == '\'' ? std::string("''") : std::string(1, c);
  return q + "'";
}

PlotCurve csv_curve(fs::path csv, std::string using_expr, std::string title) {
  PlotCurve c;
  c.csv = std::move(csv);
  c.using_expr = std::move(using_expr);
  c.title = std::move(title);
  return c;
}

PlotSpec plot_spec(std::string name, std::string title, std::string xlabel, std::string ylabel,
                   std::vector<PlotCurve> curves, std::string key = "top right", std::string extra = "") {
  return {std::move(name),   std::move(title), std::move(xlabel), std::move(ylabel),
          std::move(curves), std::move(key),   std::move(extra),  {}};
}

/// The history.csv time axis in microseconds.
constexpr const char* t_us = "(column('t_s')*1e6)";

std::vector<PlotCurve> per_run(const std::vector<PlotRun>& runs, const std::string& using_expr) {
  std::vector<PlotCurve> curves;
  curves.reserve(runs.size());
  for (const PlotRun& r : runs)
    curves.push_back(csv_curve(r.history, using_expr, r.label));
  return curves;
}

/// One layer of damage_area.csv: criterion, ply or interface, and its number (1 = top).
struct DamageLayer {
  std::string criterion;
  bool is_ply = true;
  int index = 0;
  bool operator<(const DamageLayer& o) const {
    return std::tie(criterion, is_ply, index) < std::tie(o.criterion, o.is_ply, o.index);
  }
};

/// The failed-area history of every layer of damage_area.csv (a row is written whenever a layer's
/// area changes), as (t [µs], area [mm²]) rows, held to the end of the run at `t_end`; layers sorted by
/// criterion, plies before interfaces, then in stacking order.
std::map<DamageLayer, std::string> damage_area_rows(const fs::path& csv, double t_end) {
  std::ifstream in(csv);
  std::string line;
  std::getline(in, line); // header: time_s,criterion,ply,interface,failed_area_m2
  std::map<DamageLayer, std::pair<std::string, double>> layers; // → (rows, last area)
  while (std::getline(in, line)) {
    std::istringstream row(line);
    std::string time, criterion, ply, interface, area;
    std::getline(row, time, ',');
    std::getline(row, criterion, ',');
    std::getline(row, ply, ',');
    std::getline(row, interface, ',');
    std::getline(row, area, ',');
    const bool is_ply = !ply.empty();
    auto& [rows, last] = layers[{criterion, is_ply, std::stoi(is_ply ? ply : interface)}];
    last = std::stod(area) * 1e6; // mm²
    rows += fmt::format("{:.6g},{:.6g}\n", std::stod(time) * 1e6, last);
  }
  std::map<DamageLayer, std::string> out;
  for (const auto& [layer, history] : layers)
    out[layer] =
        "t_us,area_mm2\n" + history.first + fmt::format("{:.6g},{:.6g}\n", t_end * 1e6, history.second);
  return out;
}

PlotCurve damage_curve(const DamageLayer& layer, std::string rows, std::string title, std::size_t position) {
  PlotCurve c;
  c.using_expr = "1:2";
  c.title = std::move(title);
  c.data = std::move(rows);
  c.style = "steps";
  c.colour = tab10.at(position % tab10.size());
  (void)layer;
  return c;
}

std::string layer_name(const DamageLayer& layer) {
  return fmt::format("{} {}", layer.is_ply ? "ply" : "interface", layer.index);
}

/// Failed area versus time as steps. Up to max_curves_per_panel layers: one plot. More (a 24-ply
/// laminate has 24 plies and 23 interfaces per criterion pair): small multiples, one group of panels
/// per criterion and kind of layer, each panel a contiguous run of the stacking order of at most
/// max_curves_per_panel layers, the runs as even as possible.
PlotSpec damage_area_plot(const fs::path& csv, double t_end) {
  const auto layers = damage_area_rows(csv, t_end);
  PlotSpec spec =
      plot_spec("damage_area", "Failed area (tributary areas of failed Gauss points)", "t [us]",
                "failed area [mm^2]", {}, "outside right top", "set xrange [0:*]\nset yrange [0:*]\n");
  if (layers.size() <= max_curves_per_panel) {
    for (const auto& [layer, rows] : layers)
      spec.curves.push_back(
          damage_curve(layer, rows, layer.criterion + " " + layer_name(layer), spec.curves.size()));
    return spec;
  }
  std::vector<std::vector<std::pair<DamageLayer, std::string>>> groups; // criterion × kind
  for (const auto& [layer, rows] : layers) {
    if (groups.empty() || groups.back().front().first.criterion != layer.criterion ||
        groups.back().front().first.is_ply != layer.is_ply)
      groups.emplace_back();
    groups.back().emplace_back(layer, rows);
  }
  for (const auto& group : groups) {
    const std::size_t panels = (group.size() + max_curves_per_panel - 1) / max_curves_per_panel;
    const std::size_t per_panel = (group.size() + panels - 1) / panels;
    for (std::size_t first = 0; first < group.size(); first += per_panel) {
      const std::size_t last = std::min(group.size(), first + per_panel) - 1;
      const DamageLayer& a = group[first].first;
      PlotPanel panel{fmt::format("{}: {} {}-{}", a.criterion, a.is_ply ? "plies" : "interfaces", a.index,
                                  group[last].first.index),
                      {}};
      for (std::size_t i = first; i <= last; ++i)
        panel.curves.push_back(
            damage_curve(group[i].first, group[i].second, layer_name(group[i].first), i - first));
      spec.panels.push_back(std::move(panel));
    }
  }
  return spec;
}

/// Index of `column` in a CSV header line, or npos.
std::size_t column_index(const std::string& header, const std::string& column) {
  std::istringstream names(header);
  std::string name;
  for (std::size_t i = 0; std::getline(names, name, ','); ++i)
    if (name == column) return i;
  return std::string::npos;
}

/// Value of `column` in the first data row of a history.csv (0 when absent).
double first_value(const fs::path& history, const std::string& column) {
  std::ifstream in(history);
  std::string header, row, cell;
  std::getline(in, header);
  std::getline(in, row);
  const std::size_t k = column_index(header, column);
  std::istringstream cells(row);
  for (std::size_t i = 0; std::getline(cells, cell, ','); ++i)
    if (i == k) {
      try {
        return std::stod(cell);
      } catch (const std::exception&) {
        return 0.0;
      }
    }
  return 0.0;
}

/// Time of the last row of a history.csv [s].
double last_time(const fs::path& history) {
  std::ifstream in(history);
  std::string line, last;
  while (std::getline(in, line))
    if (!line.empty()) last = line;
  try {
    return std::stod(last.substr(0, last.find(',')));
  } catch (const std::exception&) {
    return 0.0; // header only
  }
}

/// Impactor energy against time, as a drop-weight report draws it: the impact energy E0 = ½ m v0²,
/// the impactor's kinetic energy, and E0 minus it — the energy given to the plate, whose maximum is at
/// the largest deflection and whose final value is the absorbed energy once the impactor has left.
PlotSpec impactor_energy_plot(const std::vector<PlotRun>& runs) {
  std::vector<PlotCurve> curves;
  for (const PlotRun& r : runs) {
    const fs::path h = r.history;
    const double e0 = first_value(h, "impactor_energy_J");
    const std::string suffix = runs.size() > 1 ? ", " + r.label : "";
    if (runs.size() == 1) {
      curves.push_back(csv_curve(h, fmt::format("{}:({:.17g})", t_us, e0), "impact energy E0"));
      curves.push_back(
          csv_curve(h, fmt::format("{}:(column('impactor_energy_J'))", t_us), "impactor kinetic"));
    }
    curves.push_back(csv_curve(h, fmt::format("{}:({:.17g}-column('impactor_energy_J'))", t_us, e0),
                               "E0 - impactor kinetic (to the plate)" + suffix));
  }
  return plot_spec("impactor_energy", "Impactor energy (drop-weight convention)", "t [us]", "energy [J]",
                   std::move(curves), "center right", "set yrange [0:*]\nset offsets 0, 0, graph 0.08, 0\n");
}

/// The column names of a history.csv.
std::vector<std::string> history_header(const fs::path& history) {
  std::ifstream in(history);
  std::string header, name;
  std::getline(in, header);
  std::vector<std::string> names;
  std::istringstream cells(header);
  while (std::getline(cells, name, ','))
    names.push_back(name);
  return names;
}

/// Energy balance (SPEC §4): impactor + plate kinetic + plate strain + contact work (+ the energy the plies'
/// damage and the interfaces dissipated, when the run has them) = ½ m v0².
PlotSpec energy_plot(const fs::path& h) {
  std::vector<std::pair<std::string, std::string>> terms{{"impactor_energy_J", "impactor kinetic"},
                                                         {"plate_kinetic_J", "plate kinetic"},
                                                         {"plate_strain_J", "plate strain"},
                                                         {"contact_work_J", "contact work (indentation)"}};
  const std::vector<std::string> columns = history_header(h);
  const auto has = [&](const std::string& c) {
    return std::find(columns.begin(), columns.end(), c) != columns.end();
  };
  if (has("damage_dissipation_J")) terms.emplace_back("damage_dissipation_J", "dissipated by ply damage");
  if (has("delamination_dissipation_J"))
    terms.emplace_back("delamination_dissipation_J", "dissipated by the interfaces");
  std::vector<PlotCurve> curves;
  std::string sum;
  for (const auto& [column, title] : terms) {
    curves.push_back(csv_curve(h, fmt::format("{}:(column('{}'))", t_us, column), title));
    sum += fmt::format("{}column('{}')", sum.empty() ? "" : "+", column);
  }
  curves.push_back(csv_curve(h, fmt::format("{}:({})", t_us, sum), "sum"));
  return plot_spec("energy", "Energy balance", "t [us]", "energy [J]", std::move(curves), "center right",
                   "set yrange [0:*]\n");
}

/// Delaminated area (cohesive damage d = 1) of each interface and projected, against time, from the
/// history.csv of a stacked plate (no curves otherwise).
PlotSpec delamination_area_plot(const fs::path& h) {
  std::vector<PlotCurve> curves;
  constexpr std::string_view prefix = "delamination_area_after_ply";
  for (const std::string& column : history_header(h))
    if (column.rfind(prefix, 0) == 0)
      curves.push_back(csv_curve(h, fmt::format("{}:(column('{}')*1e6)", t_us, column),
                                 "interface after ply " +
                                     column.substr(prefix.size(), column.size() - prefix.size() - 3)));
  if (curves.empty()) return {};
  curves.push_back(csv_curve(h, fmt::format("{}:(column('delamination_area_m2')*1e6)", t_us),
                             "projected (union over the interfaces)"));
  curves.back().colour = "#000000";
  curves.back().style = "lines dt 2"; // dashed: an interface it equals stays visible beneath it
  return plot_spec("delamination_area", "Delaminated area (cohesive damage d = 1)", "t [us]",
                   "delaminated area [mm^2]", std::move(curves), "bottom right",
                   "set yrange [0:*]\nset offsets 0, 0, graph 0.08, 0\n");
}

} // namespace

std::pair<int, int> picture_size(const PlotSpec& spec) {
  if (spec.panels.empty()) return {plot_width_px, plot_height_px};
  const auto rows = int((spec.panels.size() + 1) / 2);
  return {panels_width_px, panel_row_height_px * rows};
}

std::string run_label(const fs::path& dir) {
  std::ifstream in(dir / "summary.json");
  if (in) {
    const nlohmann::json j = nlohmann::json::parse(in, nullptr, false);
    // numbers only: a summary edited to hold a string there threw json's type_error.302 (issue 77)
    if (!j.is_discarded() && j.is_object() && j.contains("impact_velocity") && j.contains("impactor_mass") &&
        j["impact_velocity"].is_number() && j["impactor_mass"].is_number())
      return fmt::format("v0 = {:.3g} m/s, m = {:.3g} kg", j["impact_velocity"].get<double>(),
                         j["impactor_mass"].get<double>());
  }
  return dir.filename().string();
}

std::vector<PlotSpec> impact_plots(const std::vector<PlotRun>& runs) {
  std::vector<PlotSpec> p;
  p.push_back(plot_spec("force_time", "Contact force", "t [us]", "contact force F_c [kN]",
                        per_run(runs, fmt::format("{}:(column('force_N')*1e-3)", t_us))));
  p.push_back(plot_spec("deflection_time", "Plate deflection at the contact point", "t [us]", "w_s [mm]",
                        per_run(runs, fmt::format("{}:(column('plate_w_m')*1e3)", t_us))));
  p.push_back(plot_spec("velocity_time", "Impactor velocity (+ towards the plate)", "t [us]", "v_i [m/s]",
                        per_run(runs, fmt::format("{}:(column('impactor_v_m_per_s'))", t_us))));
  // Contact part only (indentation >= 0): after separation the indentation runs far negative and
  // would swamp the loading-unloading loop.
  p.push_back(plot_spec("force_indentation", "Contact force versus indentation (loading, Tan-Sun unloading)",
                        "indentation alpha [mm]", "contact force F_c [kN]",
                        per_run(runs, "(column('indentation_m') >= 0 ? column('indentation_m')*1e3 : NaN)"
                                      ":(column('force_N')*1e-3)"),
                        "top left"));
  // The two plots of a drop-weight test report (ASTM D7136 §13): force against the impactor's
  // displacement since first contact (contact part), and the impactor's energy against time.
  p.push_back(plot_spec("force_displacement", "Contact force versus impactor displacement",
                        "impactor displacement [mm]", "contact force F_c [kN]",
                        per_run(runs, "(column('indentation_m') >= 0 ? column('impactor_w_m')*1e3 : NaN)"
                                      ":(column('force_N')*1e-3)"),
                        "top left"));
  p.push_back(impactor_energy_plot(runs));
  if (runs.size() == 1) {
    const fs::path h = runs.front().history;
    p.push_back(energy_plot(h));
    if (PlotSpec delamination = delamination_area_plot(h); !delamination.curves.empty())
      p.push_back(std::move(delamination));
    const fs::path area = runs.front().dir / "damage_area.csv";
    if (fs::exists(area)) {
      PlotSpec damage = damage_area_plot(area, last_time(h));
      if (!damage.curves.empty() || !damage.panels.empty()) p.push_back(std::move(damage));
    }
    // Progressive damage: a map per ply and the projected map (io/results/ply_damage_maps.hpp).
    for (PlotSpec& map : ply_damage_map_plots(runs.front().dir))
      p.push_back(std::move(map));
    // Stacked plate: a map per interface and the projected map.
    for (PlotSpec& map : delamination_map_plots(runs.front().dir))
      p.push_back(std::move(map));
  }
  return p;
}

namespace {

/// Inline data blocks of `curves` (named $<tag><i>) and the `plot` command that draws them.
std::pair<std::string, std::string> plot_command(const std::vector<PlotCurve>& curves, const fs::path& cwd,
                                                 const std::string& tag) {
  std::string blocks, plot = "plot ";
  for (std::size_t i = 0; i < curves.size(); ++i) {
    const PlotCurve& c = curves[i];
    if (!c.data.empty()) blocks += fmt::format("${}{} << EOD\n{}EOD\n", tag, i, c.data);
    const std::string source =
        c.data.empty() ? quoted(fs::relative(c.csv, cwd).generic_string()) : fmt::format("${}{}", tag, i);
    const std::string colour = c.colour.empty() ? "" : fmt::format(" lc rgb {}", quoted(c.colour));
    plot += fmt::format("{}{} using {} with {} lw {:g}{} title {}", i ? ", \\\n     " : "", source,
                        c.using_expr, c.style, c.line_width, colour, quoted(c.title));
  }
  return {blocks, plot + "\n"};
}

/// The drawing commands of a spec: one plot, or a 2-column multiplot of its panels.
std::pair<std::string, std::string> drawing(const PlotSpec& spec, const fs::path& cwd) {
  if (spec.panels.empty()) return plot_command(spec.curves, cwd, "curve");
  std::string blocks, draw = fmt::format("set multiplot layout {},2 title {} noenhanced\n",
                                         (spec.panels.size() + 1) / 2, quoted(spec.title));
  for (std::size_t k = 0; k < spec.panels.size(); ++k) {
    const auto [data, plot] = plot_command(spec.panels[k].curves, cwd, fmt::format("panel{}_", k));
    blocks += data;
    draw += fmt::format("set title {} noenhanced\n{}", quoted(spec.panels[k].title), plot);
  }
  return {blocks, draw + "unset multiplot\n"};
}

} // namespace

std::string gnuplot_script(const PlotSpec& spec, const fs::path& cwd, const std::string& svg,
                           const std::string& png) {
  std::string s = "# plyimpact plot; run with: gnuplot " + spec.name + ".gp (from this folder)\n";
  s += "set datafile separator ','\nset datafile columnheaders\n";
  s += fmt::format("set title {} noenhanced\nset xlabel {} noenhanced\nset ylabel {} noenhanced\n",
                   quoted(spec.title), quoted(spec.xlabel), quoted(spec.ylabel));
  s += fmt::format("set grid lc rgb '#d0d0d0'\nset key {} noenhanced box opaque\nset border lw 1.2\n",
                   spec.key);
  const auto [blocks, draw] = drawing(spec, cwd);
  s += blocks + spec.extra;
  const auto [width, height] = picture_size(spec);
  s += fmt::format("set terminal svg size {},{} dynamic font 'Sans,12'\nset output {}\n", width, height,
                   quoted(svg));
  s += draw;
  s += fmt::format("set terminal pngcairo size {},{} font 'Sans,11'\nset output {}\n", width, height,
                   quoted(png));
  s += draw + "set output\n";
  return s;
}

PlotFiles draw_plots(const std::vector<PlotSpec>& specs, const fs::path& out) {
  if (!program_on_path("gnuplot"))
    throw std::runtime_error("gnuplot not found (apt-get install gnuplot-nox, or run scripts/install-deps)");
  fs::create_directories(out);
  const fs::path cwd = fs::absolute(out);
  PlotFiles files;
  for (const PlotSpec& spec : specs) {
    const fs::path gp = cwd / (spec.name + ".gp");
    write_file_atomically(gp, gnuplot_script(spec, cwd, spec.name + ".svg", spec.name + ".png"));
    files.scripts.push_back(gp);
    // Drawn to temporary names, then renamed: an image is complete or absent.
    const std::string svg_tmp = spec.name + ".svg.tmp", png_tmp = spec.name + ".png.tmp";
    const fs::path run = cwd / (spec.name + ".gp.tmp");
    write_file_atomically(run, gnuplot_script(spec, cwd, svg_tmp, png_tmp));
    const ProgramResult gnuplot = run_program({"gnuplot", run.filename().string()}, cwd);
    fs::remove(run);
    if (gnuplot.exit_code != 0 || !fs::exists(cwd / svg_tmp) || !fs::exists(cwd / png_tmp)) {
      std::error_code ec;
      fs::remove(cwd / svg_tmp, ec);
      fs::remove(cwd / png_tmp, ec);
      throw std::runtime_error(fmt::format("gnuplot failed on {}:\n{}", gp.string(), gnuplot.output));
    }
    fs::rename(cwd / svg_tmp, cwd / (spec.name + ".svg"));
    fs::rename(cwd / png_tmp, cwd / (spec.name + ".png"));
    files.images.push_back(cwd / (spec.name + ".svg"));
    files.images.push_back(cwd / (spec.name + ".png"));
  }
  return files;
}

} // namespace plyimpact
