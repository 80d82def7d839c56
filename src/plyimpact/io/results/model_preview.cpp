#include "plyimpact/io/results/model_preview.hpp"

#include "plyimpact/io/results/gnuplot_layers.hpp"
#include "plyimpact/io/results/html_page.hpp"
#include "plyimpact/io/results/support_words.hpp"
#include "plyimpact/io/system/atomic_file.hpp"
#include "plyimpact/io/system/build_info.hpp"
#include "plyimpact/io/system/child_process.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <set>

namespace plyimpact {

namespace {

/// The points of the nodes `nodes` of `mesh`, each once [m].
std::vector<Eigen::Vector2d> node_points(const Mesh& mesh, const std::set<int>& nodes) {
  std::vector<Eigen::Vector2d> points;
  points.reserve(nodes.size());
  for (const int n : nodes)
    points.push_back(mesh.node(n));
  return points;
}

/// A gnuplot datablock of points in mm.
std::string datablock(const std::string& name, const std::vector<Eigen::Vector2d>& points) {
  std::string s = fmt::format("${} << EOD\n", name);
  for (const Eigen::Vector2d& p : points)
    s += fmt::format("{:.6f} {:.6f}\n", p.x() * 1e3, p.y() * 1e3);
  return s + "EOD\n";
}

/// Text safe inside a gnuplot double-quoted string.
std::string gnuplot_quoted(std::string_view text) {
  std::string s = "\"";
  for (const char c : text) {
    if (c == '"' || c == '\\') s += '\\';
    s += c;
  }
  return s + "\"";
}

/// The ply stack as the left-hand panel of the preview's picture: one rectangle per ply (ply 1 on top), its
/// number and angle, a red line under each ply that a cohesive interface follows.
std::string stack_panel(const Laminate& laminate, const std::vector<int>& interfaces_after_ply) {
  const auto n = static_cast<int>(laminate.ply_count());
  std::string s = "set size 0.3,1\nset origin 0.7,0\n";
  s += fmt::format("set xrange [0:2.2]\nset yrange [{}:-1.5]\nunset xtics\nunset ytics\nunset border\n",
                   n + 1.5);
  s += fmt::format("set title {} noenhanced\n",
                   gnuplot_quoted(fmt::format("{} plies, {:.3g} mm; impacted face on top", n,
                                              laminate.thickness() * 1e3)));
  const double font = std::clamp(240.0 / n, 6.0, 10.0);
  for (int k = 0; k < n; ++k) {
    const auto& ply = laminate.plies()[static_cast<std::size_t>(k)];
    s +=
        fmt::format("set object {} rect from 0,{} to 1,{} fc rgb '{}' fs solid 1.0 border lc rgb '#ffffff'\n",
                    k + 1, k, k + 1, ply_colour(ply.angle_deg));
    if (n <= 40 || k % 2 == 0)
      s += fmt::format("set label {} {} at 1.08,{} left font 'Sans,{:.0f}' noenhanced\n", k + 1,
                       gnuplot_quoted(fmt::format("{} {:g}°", k + 1, ply.angle_deg)), k + 0.5, font);
  }
  for (std::size_t i = 0; i < interfaces_after_ply.size(); ++i)
    s += fmt::format("set arrow {} from -0.05,{} to 1.05,{} nohead lc rgb '#d62728' lw 3 front\n", i + 1,
                     interfaces_after_ply[i], interfaces_after_ply[i]);
  if (!interfaces_after_ply.empty())
    s += fmt::format(
        "set label {} {} at 0,{} left tc rgb '#d62728' font 'Sans,9'\n", n + 1,
        gnuplot_quoted(fmt::format("red: {} interfaces that may delaminate", interfaces_after_ply.size())),
        n + 1.0);
  return s + "plot NaN notitle\nunset object\nunset label\nunset arrow\nset border\nset xtics\nset ytics\n";
}

/// The plan as the right-hand panel: elements, supports by type, the rig, the impact point and contact
/// circle.
std::string plan_panel(const ModelPreview& p, double width_share) {
  const BoundingBox& box = p.mesh.bounds();
  std::string s = fmt::format("set size {},1\nset origin 0,0\n", width_share);
  s += fmt::format("set title {} noenhanced\n", gnuplot_quoted(p.title));
  s += "set xlabel 'x [mm]'\nset ylabel 'y [mm]'\nset size ratio -1\n";
  s += fmt::format("set xrange [{:.6f}:{:.6f}]\nset yrange [{:.6f}:{:.6f}]\n", box.x_min * 1e3,
                   box.x_max * 1e3, box.y_min * 1e3, box.y_max * 1e3);
  s += "set xtics out nomirror\nset ytics out nomirror\nset key below left Left reverse noenhanced\n";
  s += element_outlines(p.mesh);
  std::string clauses;
  for (std::size_t k = 0; k < p.supports.size(); ++k)
    clauses +=
        fmt::format("{}$support{} using 1:2 with points pt 5 ps 0.6 lc rgb '{}' title {}",
                    clauses.empty() ? "" : ", ", k, support_colour(k), gnuplot_quoted(p.supports[k].label));
  const auto [rig_data, rig_clauses] = rig_outline_layers(p.rig);
  clauses += clauses.empty() && !rig_clauses.empty() ? rig_clauses.substr(2) : rig_clauses;
  if (p.impact_point) {
    s += fmt::format("set object 1 circle at {:.6f},{:.6f} size {:.6f} fc rgb '#d62728' fs transparent solid "
                     "0.25 border lc rgb '#d62728' front\n",
                     p.impact_point->x() * 1e3, p.impact_point->y() * 1e3, p.contact_radius * 1e3);
    clauses += fmt::format(
        "{}$impact using 1:2 with points pt 2 ps 2 lw 2 lc rgb '#d62728' title {}",
        clauses.empty() ? "" : ", ",
        gnuplot_quoted(fmt::format("impact point, and the largest contact circle expected (radius {:.3g} mm)",
                                   p.contact_radius * 1e3)));
  }
  if (clauses.empty()) clauses = "NaN notitle";
  return s + "plot " + clauses + "\n";
}

} // namespace

std::vector<SupportMarks> support_marks(const Mesh& mesh, const BoundaryConditions& bc) {
  std::vector<SupportMarks> marks;
  for (const SupportGroup& g : support_groups(bc)) {
    std::set<int> nodes;
    for (const std::string& set : g.sets)
      if (mesh.has_node_set(set))
        for (const int n : mesh.node_set(set))
          nodes.insert(n);
    marks.push_back({g.words(), node_points(mesh, nodes)});
  }
  if (bc.corners && mesh.has_node_set("corners")) {
    const std::vector<int>& corners = mesh.node_set("corners");
    const std::string code = bc.corners->code();
    marks.push_back({fmt::format("corners: {} ({})", code, held_dofs(code)),
                     node_points(mesh, std::set<int>(corners.begin(), corners.end()))});
  }
  return marks;
}

std::string model_preview_html(const ModelPreview& p) {
  std::string h = html_page_start(
      "Preview: " + p.title,
      xml_escaped(fmt::format("plyimpact {} · deck {} · the model before its run: nothing solved",
                              PLYIMPACT_VERSION, p.source)));
  h += "<section id=\"model\"><h2>The model</h2><div class=\"case\">\n";
  h += "<figure>" +
       svg_model_plan({.mesh = p.mesh,
                       .supports = p.supports,
                       .rig = p.rig,
                       .impact_point = p.impact_point,
                       .contact_radius = p.contact_radius,
                       .contact_reached = false}) +
       "</figure>\n";
  if (p.laminate) h += "<figure>" + svg_ply_stack(*p.laminate, p.interfaces_after_ply) + "</figure>\n";
  h += "</div></section>\n";
  h += "<section id=\"settings\"><h2>What the run would use</h2>\n<pre>" + xml_escaped(p.settings) +
       "</pre></section>\n";
  return h + std::string(html_page_end());
}

std::string model_preview_script(const ModelPreview& p, const std::string& svg, const std::string& png) {
  std::string s = "# plyimpact model preview; run with: gnuplot <this file>\n";
  for (std::size_t k = 0; k < p.supports.size(); ++k)
    s += datablock(fmt::format("support{}", k), p.supports[k].points);
  if (p.impact_point) s += datablock("impact", {*p.impact_point});
  s += rig_outline_layers(p.rig).first;
  const BoundingBox& box = p.mesh.bounds();
  const double aspect = (box.y_max - box.y_min) / std::max(box.x_max - box.x_min, 1e-12);
  const double plan_share = p.laminate ? 0.7 : 1.0;
  const int width = 1100;
  const int height = std::max(480, static_cast<int>(width * plan_share * aspect) + 110 +
                                       16 * static_cast<int>(p.supports.size()));
  std::string drawing = "set multiplot\n";
  drawing += plan_panel(p, plan_share);
  if (p.laminate)
    drawing += "unset object\nunset arrow\nunset label\nset size noratio\nset key off\nunset xlabel\nunset "
               "ylabel\n" +
               stack_panel(*p.laminate, p.interfaces_after_ply);
  drawing += "unset multiplot\n";
  s += fmt::format("set terminal svg size {},{} dynamic font 'Sans,11'\nset output '{}'\n", width, height,
                   svg);
  s += drawing + "reset\n";
  s += fmt::format("set terminal pngcairo size {},{} font 'Sans,10'\nset output '{}'\n", width, height, png);
  return s + drawing + "set output\n";
}

ModelPreviewFiles write_model_preview(const std::filesystem::path& dir, const ModelPreview& p) {
  namespace fs = std::filesystem;
  fs::create_directories(dir);
  ModelPreviewFiles files;
  const auto write = [&](const std::string& name, const std::string& text) {
    write_file_atomically(dir / name, text);
    files.written.push_back(dir / name);
  };
  write("preview.txt", p.settings);
  write("preview.gp", model_preview_script(p, "preview.svg", "preview.png"));
  if (!program_on_path("gnuplot")) {
    files.warning =
        "gnuplot not found: preview.gp written, preview.png and preview.svg not drawn (apt-get install "
        "gnuplot-nox)";
  } else {
    // gnuplot draws to temporary names; each picture replaces the old one only once whole.
    const fs::path run = dir / "preview.gp.tmp";
    write_file_atomically(run, model_preview_script(p, "preview.svg.tmp", "preview.png.tmp"));
    const int status = run_program({"gnuplot", run.filename().string()}, dir).exit_code;
    fs::remove(run);
    for (const char* name : {"preview.svg", "preview.png"}) {
      const fs::path drawn = dir / (std::string(name) + ".tmp");
      if (status == 0 && fs::exists(drawn)) {
        fs::rename(drawn, dir / name);
        files.written.push_back(dir / name);
      } else {
        std::error_code ec;
        fs::remove(drawn, ec);
        files.warning = fmt::format("gnuplot failed on {} (exit {})", (dir / "preview.gp").string(), status);
      }
    }
  }
  write("preview.html", model_preview_html(p));
  return files;
}

} // namespace plyimpact
