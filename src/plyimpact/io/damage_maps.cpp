#include "plyimpact/io/damage_maps.hpp"

#include "plyimpact/io/atomic_file.hpp"

#include <fmt/format.h>

#include <cstdlib>
#include <map>
#include <tuple>

namespace plyimpact {

std::string damage_map_script(const PlateMesh& mesh, const std::vector<DamageOnset>& points,
                              const std::string& title, const std::string& svg_path,
                              const std::string& png_path) {
  const double a = mesh.plate().a * 1e3, b = mesh.plate().b * 1e3; // mm
  std::string s = "# plyimpact damage map; run with: gnuplot <this file>\n$failed << EOD\n";
  for (const auto& p : points)
    s += fmt::format("{:.6f} {:.6f} {:.4f}\n", p.x * 1e3, p.y * 1e3, p.time * 1e6);
  s += "EOD\n";
  s += fmt::format("set title \"{}\" noenhanced\n", title);
  s += "set xlabel 'x [mm]'\nset ylabel 'y [mm]'\n";
  s += fmt::format("set xrange [0:{:.6f}]\nset yrange [0:{:.6f}]\nset size ratio -1\n", a, b);
  // Element boundaries as thin lines; tics in mm on the axes.
  s += fmt::format(
      "set for [i=0:{0}] arrow from i*{1:.6f},0 to i*{1:.6f},{2:.6f} nohead lc rgb '#a0a0a0' lw 0.6 back\n",
      mesh.nx(), a / mesh.nx(), b);
  s += fmt::format(
      "set for [j=0:{0}] arrow from 0,j*{1:.6f} to {2:.6f},j*{1:.6f} nohead lc rgb '#a0a0a0' lw 0.6 back\n",
      mesh.ny(), b / mesh.ny(), a);
  s += "set xtics out nomirror\nset ytics out nomirror\n";
  s += "set cblabel 'onset time [us]'\n";
  s += "set palette defined (0 '#440154', 1 '#3b528b', 2 '#21918c', 3 '#5ec962', 4 '#fde725')\nset key off\n";
  const std::string plot = "plot $failed using 1:2:3 with points pt 5 ps 1.6 lc palette\n";
  s += fmt::format("set terminal svg size 800,{} dynamic font 'Sans,11'\nset output '{}'\n",
                   static_cast<int>(800 * b / a) + 120, svg_path);
  s += plot;
  s += fmt::format("set terminal pngcairo size 800,{} font 'Sans,10'\nset output '{}'\n",
                   static_cast<int>(800 * b / a) + 120, png_path);
  s += plot + "set output\n";
  return s;
}

DamageMapFiles write_damage_maps(const std::filesystem::path& dir, const PlateMesh& mesh,
                                 const std::vector<DamageOnset>& onsets) {
  namespace fs = std::filesystem;
  DamageMapFiles files;
  std::map<std::tuple<std::string, std::string, int>, std::vector<DamageOnset>> groups;
  for (const auto& o : onsets) {
    const bool ply = o.ply > 0;
    groups[{std::string(to_string(o.criterion)), ply ? "ply" : "interface", ply ? o.ply : o.interface}]
        .push_back(o);
  }
  const bool have_gnuplot = std::system("command -v gnuplot > /dev/null 2>&1") == 0;
  if (!have_gnuplot && !groups.empty())
    files.warning =
        "gnuplot not found: damage map scripts written, images not drawn (apt-get install gnuplot-nox)";
  for (const auto& [key, points] : groups) {
    const auto& [criterion, layer, number] = key;
    const std::string stem = fmt::format("damage_map_{}_{}{}", criterion, layer, number);
    const std::string title =
        fmt::format("{}: {} {}, {} failed Gauss points", criterion, layer, number, points.size());
    const fs::path svg = dir / (stem + ".svg"), png = dir / (stem + ".png"), gp = dir / (stem + ".gp");
    const fs::path svg_tmp = dir / (stem + ".svg.tmp"), png_tmp = dir / (stem + ".png.tmp");
    // The kept script draws to the final names; the one run here draws to temporary names first.
    write_file_atomically(
        gp, damage_map_script(mesh, points, title, svg.filename().string(), png.filename().string()));
    files.scripts.push_back(gp);
    if (!have_gnuplot) continue;
    const fs::path run = dir / (stem + ".gp.tmp");
    write_file_atomically(run, damage_map_script(mesh, points, title, svg_tmp.string(), png_tmp.string()));
    const int status = std::system(fmt::format("gnuplot '{}' > /dev/null 2>&1", run.string()).c_str());
    fs::remove(run);
    std::error_code ec;
    if (status != 0 || !fs::exists(svg_tmp) || !fs::exists(png_tmp)) {
      files.warning = "gnuplot failed on " + gp.string();
      fs::remove(svg_tmp, ec);
      fs::remove(png_tmp, ec);
      continue;
    }
    fs::rename(svg_tmp, svg);
    fs::rename(png_tmp, png);
    files.images.push_back(svg);
    files.images.push_back(png);
  }
  return files;
}

} // namespace plyimpact
