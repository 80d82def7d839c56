#include "plyimpact/io/results/ply_damage_maps.hpp"

#include "plyimpact/io/deck/deck.hpp"
#include "plyimpact/io/results/svg_plot.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>

namespace plyimpact {
namespace {

namespace fs = std::filesystem;

constexpr const char* header =
    "element,ply,angle_deg,x_m,y_m,d_ft,d_fc,d_mt,d_mc,x1_m,y1_m,x2_m,y2_m,x3_m,y3_m,"
    "x4_m,y4_m";

std::vector<std::string> split(const std::string& line) {
  std::vector<std::string> cells;
  std::istringstream in(line);
  std::string cell;
  while (std::getline(in, cell, ','))
    cells.push_back(cell);
  return cells;
}

/// Reads the cells of one row by column name.
class RowReader {
public:
  RowReader(const fs::path& csv, const std::string& header_line) : csv_(csv) {
    const auto names = split(header_line);
    for (std::size_t i = 0; i < names.size(); ++i)
      column_[names[i]] = i;
  }
  void start(const std::string& line, int number) {
    cells_ = split(line);
    line_ = number;
  }
  [[nodiscard]] double number(const std::string& name) const {
    const auto it = column_.find(name);
    if (it == column_.end()) throw std::runtime_error(fmt::format("{}: no column {}", csv_.string(), name));
    try {
      std::size_t used = 0;
      const std::string& cell = cells_.at(it->second);
      const double v = std::stod(cell, &used);
      if (used != cell.size()) throw std::invalid_argument(cell);
      return v;
    } catch (const std::exception&) {
      throw std::runtime_error(fmt::format("{}:{}: {} is not a number", csv_.string(), line_, name));
    }
  }

private:
  fs::path csv_;
  std::map<std::string, std::size_t> column_;
  std::vector<std::string> cells_;
  int line_ = 0;
};

/// Palette of the maps (ColorBrewer YlOrRd): white only where d = 0, any damage at least pale yellow,
/// through orange to dark red at d = 1.
constexpr const char* damage_palette =
    "set palette defined (0 '#ffffff', 0.001 '#ffeda0', 0.2 '#fed976', 0.4 '#fd8d3c', "
    "0.7 '#e31a1c', 1 '#800026')\n";

/// The colour scale of a map: gnuplot's palette, the colour box's label, range and tics.
struct MapScale {
  std::string palette;
  std::string label;
  std::string range = "[0:1]";
  std::string tics; ///< gnuplot's cbtics, or empty for its own
  /// Characters right of the map for the colour box, its tics and its label; 0: gnuplot's own (which,
  /// with `size ratio -1`, leaves no room for the label beside long tic labels).
  int right_margin = 0;
};
MapScale ply_scale() {
  return {damage_palette, "damage variable d (white: 0, intact; 1: fully cracked)", "[0:1]", ""};
}
/// The interfaces: the softening points in the same colours up to red, the delaminated ones (d = 1)
/// black, so that a C-scan's delaminated area stands out from a process zone whose d is 0.998.
MapScale interface_scale() {
  return {"set palette defined (0 '#ffffff', 0.001 '#ffeda0', 0.2 '#fed976', 0.4 '#fd8d3c', 0.7 '#e31a1c', "
          "0.9999 '#bd0026', 0.9999 '#000000', 1 '#000000')\n",
          "cohesive damage d (white: intact; black: delaminated, d = 1)", "[0:1]", ""};
}

/// The gnuplot settings of a map over the rows' elements: every element a polygon filled with its value.
std::string map_settings(const std::vector<const DamageElementRow*>& elements,
                         const std::vector<double>& values, const MapScale& scale) {
  double x0 = elements.front()->corners[0].x(), x1 = x0, y0 = elements.front()->corners[0].y(), y1 = y0;
  for (const DamageElementRow* r : elements)
    for (const Eigen::Vector2d& c : r->corners) {
      x0 = std::min(x0, c.x());
      x1 = std::max(x1, c.x());
      y0 = std::min(y0, c.y());
      y1 = std::max(y1, c.y());
    }
  std::string s = "unset grid\nset size ratio -1\n";
  s += fmt::format("set xrange [{:.6f}:{:.6f}]\nset yrange [{:.6f}:{:.6f}]\n", x0 * 1e3, x1 * 1e3, y0 * 1e3,
                   y1 * 1e3);
  s += fmt::format("set cbrange {}\nset cblabel '{}' noenhanced\n", scale.range, scale.label);
  if (!scale.tics.empty()) s += fmt::format("set cbtics {}\n", scale.tics);
  if (scale.right_margin > 0) s += fmt::format("set rmargin {}\n", scale.right_margin);
  s += scale.palette;
  for (std::size_t i = 0; i < elements.size(); ++i) {
    const auto& c = elements[i]->corners;
    s += fmt::format(
        "set object {} polygon from {:.6f},{:.6f} to {:.6f},{:.6f} to {:.6f},{:.6f} to {:.6f},{:.6f} "
        "to {:.6f},{:.6f} fc palette cb {:.6g} fs solid 1 border lc rgb '#b0b0b0' lw 0.5 back\n",
        i + 1, c[0].x() * 1e3, c[0].y() * 1e3, c[1].x() * 1e3, c[1].y() * 1e3, c[2].x() * 1e3, c[2].y() * 1e3,
        c[3].x() * 1e3, c[3].y() * 1e3, c[0].x() * 1e3, c[0].y() * 1e3, values[i]);
  }
  return s;
}

/// The rig's window edge (dashed) and clamp tips (open circles) over a map, with clamp_tip_note in the key.
std::vector<PlotCurve> rig_outline_curves(const RigOutline& rig) {
  std::vector<PlotCurve> curves;
  if (!rig.window.empty()) {
    PlotCurve window;
    window.data = "x_mm,y_mm\n";
    for (std::size_t k = 0; k <= rig.window.size(); ++k) {
      const Eigen::Vector2d& p = rig.window[k % rig.window.size()];
      window.data += fmt::format("{:.6f},{:.6f}\n", p.x() * 1e3, p.y() * 1e3);
    }
    window.using_expr = "1:2";
    window.style = "lines dt 2";
    window.line_width = 1.5;
    window.colour = "#000000";
    window.title = "window edge";
    curves.push_back(std::move(window));
  }
  if (!rig.clamp_tips.empty()) {
    PlotCurve tips;
    tips.data = "x_mm,y_mm\n";
    for (const Eigen::Vector2d& p : rig.clamp_tips)
      tips.data += fmt::format("{:.6f},{:.6f}\n", p.x() * 1e3, p.y() * 1e3);
    tips.using_expr = "1:2";
    tips.style = "points pt 6 ps 2.4";
    tips.line_width = 1.5;
    tips.colour = "#000000";
    tips.title = clamp_tip_note;
    curves.push_back(std::move(tips));
  }
  return curves;
}

/// The curves of a map: the element centres in the palette (invisible; they make gnuplot draw the colour
/// box) and the impact point (a white disc, then the marker).
std::vector<PlotCurve> map_curves(const std::vector<const DamageElementRow*>& elements,
                                  const std::vector<double>& values, const MapMarks& marks) {
  const std::optional<Eigen::Vector2d>& impact_point = marks.impact_point;
  PlotCurve centres;
  centres.data = "x_mm,y_mm,d\n";
  for (std::size_t i = 0; i < elements.size(); ++i)
    centres.data += fmt::format("{:.6f},{:.6f},{:.6g}\n", elements[i]->centre.x() * 1e3,
                                elements[i]->centre.y() * 1e3, values[i]);
  centres.using_expr = "1:2:3";
  centres.style = "points pt 5 ps 0 lc palette";
  std::vector<PlotCurve> curves{centres};
  if (impact_point) {
    // A black × on a white disc: visible on white and on dark red alike.
    PlotCurve disc;
    disc.data = fmt::format("x_mm,y_mm\n{:.6f},{:.6f}\n", impact_point->x() * 1e3, impact_point->y() * 1e3);
    disc.using_expr = "1:2";
    disc.style = "points pt 7 ps 2.2";
    disc.colour = "#ffffff";
    PlotCurve cross = disc;
    cross.style = "points pt 2 ps 2.6";
    cross.colour = "#000000";
    cross.title = "impact point";
    curves.push_back(disc);
    curves.push_back(cross);
  }
  for (PlotCurve& c : rig_outline_curves(marks.rig))
    curves.push_back(std::move(c));
  return curves;
}

PlotSpec map_spec(std::string name, std::string title, const std::vector<const DamageElementRow*>& elements,
                  const std::vector<double>& values, const MapMarks& marks,
                  const MapScale& scale = ply_scale()) {
  PlotSpec spec;
  spec.name = std::move(name);
  spec.title = std::move(title);
  spec.xlabel = "x [mm]";
  spec.ylabel = "y [mm]";
  spec.key = "at screen 0.98, 0.02 right bottom"; // bottom right corner, clear of the axes and labels
  spec.extra = map_settings(elements, values, scale);
  spec.curves = map_curves(elements, values, marks);
  // A key of several lines (a rig's window edge and clamp tips) grows up from that corner: room for it below
  // the x axis's numbers and label, a character height a line.
  const auto entries = std::count_if(spec.curves.begin(), spec.curves.end(),
                                     [](const PlotCurve& c) { return !c.title.empty(); });
  if (entries > 1) spec.extra += fmt::format("set bmargin {}\n", 4 + entries);
  return spec;
}

/// The impact point and the rig of a results folder's deck.toml; none when the deck cannot be read.
MapMarks marks_of(const fs::path& dir) {
  std::ifstream in(dir / "deck.toml");
  if (!in) return {};
  std::stringstream text;
  text << in.rdbuf();
  try {
    const Deck deck = parse_deck(text.str(), (dir / "deck.toml").string());
    MapMarks marks{std::nullopt, rig_outline(deck.rig)};
    if (deck.impactor) marks.impact_point = Eigen::Vector2d(deck.impactor->x, deck.impactor->y);
    return marks;
  } catch (const std::exception&) {
    // A deck that no longer reads (e.g. a mesh file moved): the maps go without the marker.
  }
  return {};
}

/// The element's corner nodes 0-3 of the Q9 (counter-clockwise) as the cells ",x1,y1,…,x4,y4".
std::string corner_cells(const Mesh& mesh, int e) {
  std::string cells;
  for (std::size_t a = 0; a < 4; ++a) {
    const Eigen::Vector2d& c = mesh.node(mesh.element_nodes(e)[a]);
    cells += fmt::format(",{},{}", c.x(), c.y());
  }
  return cells;
}

/// The centre and corners of the row being read.
void read_geometry(const RowReader& reader, DamageElementRow& r) {
  r.centre = {reader.number("x_m"), reader.number("y_m")};
  for (std::size_t a = 0; a < 4; ++a)
    r.corners[a] = {reader.number(fmt::format("x{}_m", a + 1)), reader.number(fmt::format("y{}_m", a + 1))};
}

/// The largest value per element over the layers.
std::vector<double> largest_over(const std::vector<std::vector<double>>& layers) {
  std::vector<double> top(layers.front().size(), 0.0);
  for (const std::vector<double>& layer : layers)
    for (std::size_t i = 0; i < top.size(); ++i)
      top[i] = std::max(top[i], layer[i]);
  return top;
}

/// The C-scan's scale: white for no delamination (0), then one colour per interface (cscan_colour), each
/// a band of the colour box labelled with the ply above it.
MapScale cscan_scale(const std::vector<int>& after_ply) {
  const auto n = static_cast<int>(after_ply.size());
  MapScale scale;
  scale.palette = fmt::format("set palette maxcolors {}\nset palette defined (0 '#ffffff'", n + 1);
  scale.tics = "(\"none\" 0";
  std::size_t longest = 4; // "none"
  for (int i = 1; i <= n; ++i) {
    const std::string tic = fmt::format("after ply {}", after_ply[static_cast<std::size_t>(i - 1)]);
    longest = std::max(longest, tic.size());
    scale.palette += fmt::format(", {} '{}'", i, cscan_colour(i));
    scale.tics += fmt::format(", \"{}\" {}", tic, i);
  }
  // The box (about 4 characters), the longest tic label, the rotated label (2) and a gap on each side.
  scale.right_margin = static_cast<int>(longest) + 10;
  scale.palette += ")\n";
  scale.tics += ")";
  scale.range = fmt::format("[-0.5:{}.5]", n);
  scale.label = "shallowest delaminated interface (d = 1)";
  return scale;
}

} // namespace

double DamageElementRow::largest() const {
  return *std::max_element(damage.values.begin(), damage.values.end());
}

std::string damage_elements_csv(const DiscretePlate& model, const PlyDamageTable& table) {
  const Mesh& mesh = model.mesh();
  std::string csv = std::string(header) + "\n";
  for (int e = 0; e < mesh.element_count(); ++e) {
    const Laminate& lam = model.laminate_of(e);
    const Eigen::Vector2d centre = mesh.map(e, 0.0, 0.0);
    const std::string corners = corner_cells(mesh, e);
    for (int k = 0; k < static_cast<int>(lam.ply_count()); ++k) {
      const auto& d = table.of(k, e).values;
      csv +=
          fmt::format("{},{},{},{},{},{},{},{},{}{}\n", e + 1, k + 1, lam.plies()[std::size_t(k)].angle_deg,
                      centre.x(), centre.y(), d[0], d[1], d[2], d[3], corners);
    }
  }
  return csv;
}

std::vector<DamageElementRow> read_damage_elements_csv(const fs::path& csv) {
  std::ifstream in(csv);
  if (!in) throw std::runtime_error("cannot read " + csv.string());
  std::string line;
  std::getline(in, line);
  RowReader reader(csv, line);
  std::vector<DamageElementRow> rows;
  for (int number = 2; std::getline(in, line); ++number) {
    if (line.empty()) continue;
    reader.start(line, number);
    DamageElementRow r;
    r.element = static_cast<int>(reader.number("element"));
    read_geometry(reader, r);
    r.ply = static_cast<int>(reader.number("ply"));
    r.angle_deg = reader.number("angle_deg");
    const std::array<const char*, 4> modes{"d_ft", "d_fc", "d_mt", "d_mc"};
    for (std::size_t m = 0; m < modes.size(); ++m)
      r.damage.values[m] = reader.number(modes[m]);
    rows.push_back(r);
  }
  return rows;
}

std::vector<std::pair<int, double>> projected_damage(const std::vector<DamageElementRow>& rows) {
  std::vector<std::pair<int, double>> out;
  std::map<int, std::size_t> index;
  for (const DamageElementRow& r : rows) {
    const auto [it, added] = index.emplace(r.element, out.size());
    if (added) out.emplace_back(r.element, 0.0);
    out[it->second].second = std::max(out[it->second].second, r.largest());
  }
  return out;
}

std::vector<PlotSpec> ply_damage_map_plots(const std::vector<DamageElementRow>& rows, const MapMarks& marks) {
  std::vector<PlotSpec> specs;
  if (rows.empty()) return specs;
  std::map<int, std::vector<const DamageElementRow*>> plies;
  std::map<int, const DamageElementRow*> elements; // one row per element, for its geometry
  for (const DamageElementRow& r : rows) {
    plies[r.ply].push_back(&r);
    elements.emplace(r.element, &r);
  }
  const int count = plies.rbegin()->first;
  for (const auto& [ply, members] : plies) {
    std::vector<double> values;
    for (const DamageElementRow* r : members)
      values.push_back(r->largest());
    const double top = *std::max_element(values.begin(), values.end());
    const double angle = members.front()->angle_deg;
    const bool one_angle = std::all_of(members.begin(), members.end(),
                                       [&](const DamageElementRow* r) { return r->angle_deg == angle; });
    const std::string orientation = one_angle ? fmt::format("{:g} deg", angle) : "angle varies by region";
    specs.push_back(map_spec(fmt::format("damage_map_ply{:02d}", ply),
                             fmt::format("Ply {} of {} ({}): largest of d_ft, d_fc, d_mt, d_mc per element "
                                         "(max {:.3g})",
                                         ply, count, orientation, top),
                             members, values, marks));
  }
  std::vector<const DamageElementRow*> geometry;
  std::vector<double> values;
  std::map<int, double> projected;
  for (const auto& [element, value] : projected_damage(rows))
    projected[element] = value;
  for (const auto& [element, row] : elements) {
    geometry.push_back(row);
    values.push_back(projected[element]);
  }
  const double top = *std::max_element(values.begin(), values.end());
  specs.push_back(map_spec("damage_map_projected",
                           fmt::format("Projected damage: largest damage variable of any ply per element "
                                       "(max {:.3g})",
                                       top),
                           geometry, values, marks));
  return specs;
}

std::vector<PlotSpec> ply_damage_map_plots(const fs::path& dir) {
  const fs::path csv = dir / damage_elements_file;
  if (!fs::exists(csv)) return {};
  return ply_damage_map_plots(read_damage_elements_csv(csv), marks_of(dir));
}

std::string delamination_elements_csv(const Mesh& mesh, const DelaminationResult& result) {
  std::string csv = "element,x_m,y_m";
  for (const int p : result.interface_after_ply)
    csv += fmt::format(",d_after_ply_{}", p);
  csv += "\n";
  for (int e = 0; e < mesh.element_count(); ++e) {
    const Eigen::Vector2d centre = mesh.map(e, 0.0, 0.0);
    csv += fmt::format("{},{},{}", e + 1, centre.x(), centre.y());
    for (const std::vector<double>& d : result.element_damage)
      csv += fmt::format(",{}", d[static_cast<std::size_t>(e)]);
    csv += "\n";
  }
  return csv;
}

std::string delamination_points_csv(const DelaminationResult& result) {
  std::string csv = "point,x_m,y_m,area_m2";
  for (const int p : result.interface_after_ply)
    csv += fmt::format(",d_after_ply_{}", p);
  csv += ",x1_m,y1_m,x2_m,y2_m,x3_m,y3_m,x4_m,y4_m\n";
  for (std::size_t q = 0; q < result.point_cells.size(); ++q) {
    const auto& cell = result.point_cells[q];
    const Eigen::Vector2d centre = (cell[0] + cell[1] + cell[2] + cell[3]) / 4.0;
    csv += fmt::format("{},{},{},{}", q + 1, centre.x(), centre.y(), result.point_area[q]);
    for (const std::vector<double>& d : result.point_damage)
      csv += fmt::format(",{}", d[q]);
    for (const Eigen::Vector2d& c : cell)
      csv += fmt::format(",{},{}", c.x(), c.y());
    csv += "\n";
  }
  return csv;
}

std::vector<PlotSpec> delamination_map_plots(const fs::path& dir) {
  const fs::path csv = dir / delamination_points_file;
  std::ifstream in(csv);
  if (!in) return {};
  std::string line;
  std::getline(in, line);
  RowReader reader(csv, line);
  std::vector<int> after_ply; // the interfaces, from the column names
  for (const std::string& name : split(line))
    if (name.rfind("d_after_ply_", 0) == 0) after_ply.push_back(std::stoi(name.substr(12)));
  std::vector<DamageElementRow> cells; // one per interface point: its tributary cell
  std::vector<double> area;
  std::vector<std::vector<double>> damage(after_ply.size());
  for (int number = 2; std::getline(in, line); ++number) {
    if (line.empty()) continue;
    reader.start(line, number);
    DamageElementRow& r = cells.emplace_back();
    r.element = static_cast<int>(reader.number("point"));
    read_geometry(reader, r);
    area.push_back(reader.number("area_m2"));
    for (std::size_t i = 0; i < after_ply.size(); ++i)
      damage[i].push_back(reader.number(fmt::format("d_after_ply_{}", after_ply[i])));
  }
  if (cells.empty() || after_ply.empty()) return {};
  std::vector<const DamageElementRow*> geometry;
  geometry.reserve(cells.size());
  for (const DamageElementRow& r : cells)
    geometry.push_back(&r);
  // The areas in the titles are those of summary.json: the points with d = 1, and 0 < d < 1.
  const auto area_where = [&](const std::vector<double>& d, auto&& holds) {
    double sum = 0.0;
    for (std::size_t q = 0; q < d.size(); ++q)
      if (holds(d[q])) sum += area[q];
    return sum * 1e6;
  };
  const auto cracked = [](double d) { return d >= 1.0; };
  const auto softening = [](double d) { return d > 0.0 && d < 1.0; };
  const MapMarks marks = marks_of(dir);
  std::vector<PlotSpec> specs;
  for (std::size_t i = 0; i < after_ply.size(); ++i)
    specs.push_back(
        map_spec(fmt::format("delamination_map_after_ply{:02d}", after_ply[i]),
                 fmt::format("Interface after ply {}: cohesive damage d per interface point "
                             "(delaminated {:.3g} mm^2, softening {:.3g} mm^2)",
                             after_ply[i], area_where(damage[i], cracked), area_where(damage[i], softening)),
                 geometry, damage[i], marks, interface_scale()));
  const std::vector<double> projected = largest_over(damage);
  specs.push_back(map_spec("delamination_map_projected",
                           fmt::format("Projected delamination (C-scan view): largest d of any interface "
                                       "(delaminated {:.3g} mm^2)",
                                       area_where(projected, cracked)),
                           geometry, projected, marks, interface_scale()));
  std::vector<double> shallowest;
  for (const int i : shallowest_delaminated(damage))
    shallowest.push_back(i);
  specs.push_back(map_spec("delamination_cscan",
                           fmt::format("C-scan: the shallowest delaminated interface at each point "
                                       "(projected {:.3g} mm^2)",
                                       area_where(projected, cracked)),
                           geometry, shallowest, marks, cscan_scale(after_ply)));
  return specs;
}

} // namespace plyimpact
