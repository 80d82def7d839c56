#include "plyimpact/io/plots.hpp"

#include "plyimpact/io/atomic_file.hpp"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <array>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>

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
          std::move(curves), std::move(key),   std::move(extra)};
}

/// The history.csv time axis in microseconds.
constexpr const char* t_us = "(column('t_s')*1e6)";

std::vector<PlotCurve> per_run(const std::vector<PlotRun>& runs, const std::string& using_expr) {
  std::vector<PlotCurve> curves;
  curves.reserve(runs.size());
  for (const PlotRun& r : runs)
    curves.push_back(csv_curve(r.dir / "history.csv", using_expr, r.label));
  return curves;
}

/// Failed area versus time as steps, one curve per (criterion, layer) of damage_area.csv (a row is
/// written whenever a layer's area changes), held to the end of the run at `t_end`.
std::vector<PlotCurve> damage_area_curves(const fs::path& csv, double t_end) {
  std::ifstream in(csv);
  std::string line;
  std::getline(in, line); // header: time_s,criterion,ply,interface,failed_area_m2
  std::map<std::string, std::pair<std::string, double>> layers; // title → (rows, last area)
  while (std::getline(in, line)) {
    std::istringstream row(line);
    std::string time, criterion, ply, interface, area;
    std::getline(row, time, ',');
    std::getline(row, criterion, ',');
    std::getline(row, ply, ',');
    std::getline(row, interface, ',');
    std::getline(row, area, ',');
    const bool is_ply = !ply.empty();
    const std::string title =
        fmt::format("{} {} {}", criterion, is_ply ? "ply" : "interface", is_ply ? ply : interface);
    auto& [rows, last] = layers[title];
    last = std::stod(area) * 1e6; // mm²
    rows += fmt::format("{:.6g},{:.6g}\n", std::stod(time) * 1e6, last);
  }
  std::vector<PlotCurve> curves;
  for (const auto& [title, layer] : layers) {
    PlotCurve c;
    c.using_expr = "1:2";
    c.title = title;
    c.data = "t_us,area_mm2\n" + layer.first + fmt::format("{:.6g},{:.6g}\n", t_end * 1e6, layer.second);
    c.style = "steps";
    curves.push_back(std::move(c));
  }
  return curves;
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

} // namespace

std::string run_label(const fs::path& dir) {
  std::ifstream in(dir / "summary.json");
  if (in) {
    const nlohmann::json j = nlohmann::json::parse(in, nullptr, false);
    if (!j.is_discarded() && j.contains("impact_velocity") && j.contains("impactor_mass"))
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
  p.push_back(plot_spec("force_indentation", "Contact force versus indentation (loading, Tan-Sun unloading)",
                        "indentation alpha [mm]", "contact force F_c [kN]",
                        per_run(runs, "(column('indentation_m')*1e3):(column('force_N')*1e-3)")));
  if (runs.size() == 1) {
    // Energy balance (SPEC §4): impactor + plate kinetic + plate strain + contact work = ½ m v0².
    const fs::path h = runs.front().dir / "history.csv";
    p.push_back(plot_spec(
        "energy", "Energy balance", "t [us]", "energy [J]",
        {csv_curve(h, fmt::format("{}:(column('impactor_energy_J'))", t_us), "impactor kinetic"),
         csv_curve(h, fmt::format("{}:(column('plate_kinetic_J'))", t_us), "plate kinetic"),
         csv_curve(h, fmt::format("{}:(column('plate_strain_J'))", t_us), "plate strain"),
         csv_curve(h, fmt::format("{}:(column('contact_work_J'))", t_us), "contact work (indentation)"),
         csv_curve(h,
                   fmt::format("{}:(column('impactor_energy_J')+column('plate_kinetic_J')+"
                               "column('plate_strain_J')+column('contact_work_J'))",
                               t_us),
                   "sum")},
        "center right", "set yrange [0:*]\n"));
    const fs::path area = runs.front().dir / "damage_area.csv";
    if (fs::exists(area)) {
      auto curves = damage_area_curves(area, last_time(h));
      if (!curves.empty())
        p.push_back(plot_spec("damage_area", "Failed area (tributary areas of failed Gauss points)", "t [us]",
                              "failed area [mm^2]", std::move(curves), "outside right top",
                              "set xrange [0:*]\nset yrange [0:*]\n"));
    }
  }
  return p;
}

std::string gnuplot_script(const PlotSpec& spec, const fs::path& cwd, const std::string& svg,
                           const std::string& png) {
  std::string s = "# plyimpact plot; run with: gnuplot " + spec.name + ".gp (from this folder)\n";
  s += "set datafile separator ','\nset datafile columnheaders\n";
  s += fmt::format("set title {} noenhanced\nset xlabel {} noenhanced\nset ylabel {} noenhanced\n",
                   quoted(spec.title), quoted(spec.xlabel), quoted(spec.ylabel));
  s += fmt::format("set grid lc rgb '#d0d0d0'\nset key {} noenhanced box opaque\nset border lw 1.2\n",
                   spec.key);
  for (std::size_t i = 0; i < spec.curves.size(); ++i)
    if (!spec.curves[i].data.empty()) s += fmt::format("$curve{} << EOD\n{}EOD\n", i, spec.curves[i].data);
  s += spec.extra;
  std::string plot = "plot ";
  for (std::size_t i = 0; i < spec.curves.size(); ++i) {
    const PlotCurve& c = spec.curves[i];
    const std::string source =
        c.data.empty() ? quoted(fs::relative(c.csv, cwd).generic_string()) : fmt::format("$curve{}", i);
    plot += fmt::format("{}{} using {} with {} lw 2 title {}", i ? ", \\\n     " : "", source, c.using_expr,
                        c.style, quoted(c.title));
  }
  plot += "\n";
  s += fmt::format("set terminal svg size {},{} dynamic font 'Sans,12'\nset output {}\n", plot_width_px,
                   plot_height_px, quoted(svg));
  s += plot;
  s += fmt::format("set terminal pngcairo size {},{} font 'Sans,11'\nset output {}\n", plot_width_px,
                   plot_height_px, quoted(png));
  s += plot + "set output\n";
  return s;
}

PlotFiles draw_plots(const std::vector<PlotSpec>& specs, const fs::path& out) {
  if (std::system("command -v gnuplot > /dev/null 2>&1") != 0)
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
    const std::string command =
        fmt::format("cd {} && gnuplot {} 2>&1", quoted(cwd.string()), quoted(run.filename().string()));
    std::string log;
    if (FILE* pipe = popen(command.c_str(), "r")) {
      std::array<char, 512> buffer{};
      while (fgets(buffer.data(), int(buffer.size()), pipe) != nullptr)
        log += buffer.data();
      const int status = pclose(pipe);
      fs::remove(run);
      if (status != 0 || !fs::exists(cwd / svg_tmp) || !fs::exists(cwd / png_tmp)) {
        std::error_code ec;
        fs::remove(cwd / svg_tmp, ec);
        fs::remove(cwd / png_tmp, ec);
        throw std::runtime_error(fmt::format("gnuplot failed on {}:\n{}", gp.string(), log));
      }
    } else {
      throw std::runtime_error("cannot run gnuplot");
    }
    fs::rename(cwd / svg_tmp, cwd / (spec.name + ".svg"));
    fs::rename(cwd / png_tmp, cwd / (spec.name + ".png"));
    files.images.push_back(cwd / (spec.name + ".svg"));
    files.images.push_back(cwd / (spec.name + ".png"));
  }
  return files;
}

} // namespace plyimpact
