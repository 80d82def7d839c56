#include "plyimpact/io/results/damage_maps.hpp"

#include "plyimpact/io/results/gnuplot_layers.hpp"
#include "plyimpact/io/system/atomic_file.hpp"
#include "plyimpact/io/system/child_process.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cstdlib>
#include <map>
#include <set>
#include <tuple>

namespace plyimpact {

std::string damage_map_script(const Mesh& mesh, const std::vector<DamageOnset>& points,
                              const std::string& title, const std::string& svg_path,
                              const std::string& png_path, const RigOutline& rig) {
  const BoundingBox& box = mesh.bounds();
  const double x0 = box.x_min * 1e3, y0 = box.y_min * 1e3, x1 = box.x_max * 1e3, y1 = box.y_max * 1e3; // mm
  const double a = x1 - x0, b = y1 - y0;
  std::string s = "# plyimpact damage map; run with: gnuplot <this file>\n$failed << EOD\n";
  for (const auto& p : points)
    s += fmt::format("{:.6f} {:.6f} {:.4f}\n", p.x * 1e3, p.y * 1e3, p.time * 1e6);
  s += "EOD\n";
  const auto [rig_data, rig_clauses] = rig_outline_layers(rig);
  s += rig_data;
  s += fmt::format("set title \"{}\" noenhanced\n", title);
  s += "set xlabel 'x [mm]'\nset ylabel 'y [mm]'\n";
  s += fmt::format("set xrange [{:.6f}:{:.6f}]\nset yrange [{:.6f}:{:.6f}]\nset size ratio -1\n", x0, x1, y0,
                   y1);
  s += element_outlines(mesh); // thin lines; tics in mm on the axes
  s += "set xtics out nomirror\nset ytics out nomirror\n";
  s += "set cblabel 'onset time [us]'\n";
  s += "set palette defined (0 '#440154', 1 '#3b528b', 2 '#21918c', 3 '#5ec962', 4 '#fde725')\n";
  s += rig_clauses.empty() ? "set key off\n" : "set key below noenhanced\n";
  const std::string plot =
      "plot $failed using 1:2:3 with points pt 5 ps 1.6 lc palette notitle" + rig_clauses + "\n";
  s += fmt::format("set terminal svg size 800,{} dynamic font 'Sans,11'\nset output '{}'\n",
                   static_cast<int>(800 * b / a) + 120, svg_path);
  s += plot;
  s += fmt::format("set terminal pngcairo size 800,{} font 'Sans,10'\nset output '{}'\n",
                   static_cast<int>(800 * b / a) + 120, png_path);
  s += plot + "set output\n";
  return s;
}

DamageMapFiles write_damage_maps(const std::filesystem::path& dir, const Mesh& mesh,
                                 const std::vector<DamageOnset>& onsets, const RigOutline& rig) {
  namespace fs = std::filesystem;
  DamageMapFiles files;
  std::map<std::tuple<std::string, std::string, int>, std::vector<DamageOnset>> groups;
  for (const auto& o : onsets) {
    const bool ply = o.ply > 0;
    groups[{std::string(to_string(o.criterion)), ply ? "ply" : "interface", ply ? o.ply : o.interface}]
        .push_back(o);
  }
  const bool have_gnuplot = program_on_path("gnuplot");
  if (!have_gnuplot && !groups.empty())
    files.warning =
        "gnuplot not found: damage map scripts written, images not drawn (apt-get install gnuplot-nox)";
  // Every map's script goes into one gnuplot run: a gnuplot start costs about 0.1 s (fonts, cairo),
  // the drawing of a map a few ms, and a 24-ply laminate has up to 47 maps.
  struct Pending {
    fs::path svg, png, svg_tmp, png_tmp, gp;
  };
  std::vector<Pending> pending;
  std::string batch;
  for (const auto& [key, points] : groups) {
    const auto& [criterion, layer, number] = key;
    const std::string stem = fmt::format("damage_map_{}_{}{}", criterion, layer, number);
    const std::string title =
        fmt::format("{}: {} {}, {} failed Gauss points", criterion, layer, number, points.size());
    const fs::path svg = dir / (stem + ".svg"), png = dir / (stem + ".png"), gp = dir / (stem + ".gp");
    const fs::path svg_tmp = dir / (stem + ".svg.tmp"), png_tmp = dir / (stem + ".png.tmp");
    // The kept script draws to the final names; the one run here draws to temporary names first.
    write_file_atomically(
        gp, damage_map_script(mesh, points, title, svg.filename().string(), png.filename().string(), rig));
    files.scripts.push_back(gp);
    if (!have_gnuplot) continue;
    batch += damage_map_script(mesh, points, title, svg_tmp.string(), png_tmp.string(), rig) + "reset\n";
    pending.push_back({svg, png, svg_tmp, png_tmp, gp});
  }
  if (pending.empty()) return files;
  const fs::path run = dir / "damage_maps.gp.tmp";
  write_file_atomically(run, batch);
  const int status = run_program({"gnuplot", run.string()}, dir).exit_code;
  fs::remove(run);
  for (const Pending& m : pending) {
    std::error_code ec;
    if (status != 0 || !fs::exists(m.svg_tmp) || !fs::exists(m.png_tmp)) {
      if (files.warning.empty()) files.warning = "gnuplot failed on " + m.gp.string();
      fs::remove(m.svg_tmp, ec);
      fs::remove(m.png_tmp, ec);
      continue;
    }
    fs::rename(m.svg_tmp, m.svg);
    fs::rename(m.png_tmp, m.png);
    files.images.push_back(m.svg);
    files.images.push_back(m.png);
  }
  return files;
}

} // namespace plyimpact
