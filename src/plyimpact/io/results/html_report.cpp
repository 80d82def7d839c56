#include "plyimpact/io/results/html_report.hpp"

#include "plyimpact/analysis/contact/contact_rules.hpp"
#include "plyimpact/io/results/damage_report.hpp"
#include "plyimpact/io/results/html_page.hpp"
#include "plyimpact/io/results/model_preview.hpp"
#include "plyimpact/io/results/support_words.hpp"
#include "plyimpact/io/results/svg_plot.hpp"
#include "plyimpact/io/system/build_info.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <iterator>
#include <limits>
#include <string_view>

namespace plyimpact {

namespace {

/// A summary value by key: "—" for null or missing.
std::string value(const nlohmann::json& j, const char* key, std::string_view unit, double scale = 1.0) {
  if (!j.contains(key) || j[key].is_null()) return "—";
  if (j[key].is_boolean()) return j[key].get<bool>() ? "yes" : "no";
  if (j[key].is_string()) return xml_escaped(j[key].get<std::string>());
  return html_number(j[key].get<double>(), unit, scale);
}

/// The plan of the plate as the preview draws it, with the largest contact circle of the run.
std::string plan_of_the_run(const ImpactReportInput& in) {
  const Impactor& i = in.settings.impactor;
  const nlohmann::json& j = in.summary;
  const double alpha = j.contains("max_indentation") && j["max_indentation"].is_number()
                           ? j["max_indentation"].get<double>()
                           : 0.0;
  return svg_model_plan({.mesh = *in.mesh,
                         .supports = in.deck.boundary ? support_marks(*in.mesh, *in.deck.boundary)
                                                      : std::vector<SupportMarks>{},
                         .rig = rig_outline(in.deck.rig),
                         .impact_point = Eigen::Vector2d(i.x, i.y),
                         .contact_radius = contact_radius(i, std::max(alpha, 0.0)),
                         .contact_reached = true});
}

void case_section(std::string& h, const ImpactReportInput& in) {
  const Deck& d = in.deck;
  const ImpactSettings& s = in.settings;
  h += "<section id=\"case\"><h2>The case</h2><div class=\"case\"><dl>\n";
  if (!d.rig_description.empty()) html_item(h, "rig", xml_escaped(d.rig_description));
  if (d.file_mesh) {
    const BoundingBox& box = d.file_mesh->bounds();
    html_item(h, "plate",
              fmt::format("meshed in gmsh ({}), {:.4g} × {:.4g} mm overall, {:.4g} mm thick",
                          xml_escaped(d.mesh_file.empty() ? "the rig preset" : d.mesh_file),
                          (box.x_max - box.x_min) * 1e3, (box.y_max - box.y_min) * 1e3,
                          d.laminate ? d.laminate->thickness() * 1e3 : 0.0));
  } else if (d.plate) {
    const double thickness = d.laminate ? d.laminate->thickness() : 0.0;
    html_item(
        h, "plate",
        fmt::format("{:.4g} × {:.4g} × {:.4g} mm", d.plate->a * 1e3, d.plate->b * 1e3, thickness * 1e3));
  }
  if (d.laminate_spec)
    html_item(h, "laminate",
              fmt::format("{} of {}, {:.4g} mm plies ({} plies)", xml_escaped(d.laminate_spec->layup),
                          xml_escaped(d.laminate_spec->material), d.laminate_spec->ply_thickness * 1e3,
                          d.laminate ? d.laminate->ply_count() : 0));
  html_item(h, "mesh",
            fmt::format("{} {} elements{}, {:.3g} to {:.3g} mm", s.mesh.elements, to_string(s.mesh.element),
                        s.mesh.graded ? " graded toward the impact point" : "", s.mesh.smallest_element * 1e3,
                        s.mesh.largest_element * 1e3));
  html_item(h, "supports", xml_escaped(d.boundary ? supports_in_words(*d.boundary) : "none (free plate)"));
  const Impactor& i = s.impactor;
  html_item(h, "impactor",
            fmt::format("{:.4g} kg sphere, R = {:.4g} mm, E = {:.4g} GPa, at ({:.4g}, {:.4g}) mm", i.mass,
                        i.radius * 1e3, i.E * 1e-9, i.x * 1e3, i.y * 1e3));
  html_item(h, "impact",
            fmt::format("{:.4g} m/s, {:.4g} J", i.velocity, 0.5 * i.mass * i.velocity * i.velocity));
  html_item(h, "contact",
            fmt::format("k = {:.4g} N/m<sup>1.5</sup>, unloading {}, load {}", s.k,
                        s.contact.unloading == UnloadingLaw::tan_sun ? "Tan–Sun" : "elastic",
                        to_string(s.contact.load)));
  html_item(
      h, "time",
      fmt::format("Δt = {:.4g} µs, end {}", s.dt * 1e6,
                  s.end ? fmt::format("{:.4g} ms", *s.end * 1e3) : std::string("at the end of the event")));
  html_item(h, "plate model",
            fmt::format("{}{}", s.nonlinear ? "large deflections (non-linear)" : "linear",
                        s.progressive_damage ? ", progressive ply damage" : ""));
  h += "</dl>\n";
  if (d.laminate)
    h += "<figure>" +
         svg_ply_stack(*d.laminate, d.delamination ? interfaces_after_ply(d.delamination->stack.cuts)
                                                   : std::vector<int>{}) +
         "</figure>\n";
  if (in.mesh) h += "<figure>" + plan_of_the_run(in) + "</figure>\n";
  h += "</div></section>\n";
}

void warnings_section(std::string& h, const ImpactReportInput& in) {
  std::vector<std::string> all;
  if (in.summary.contains("warnings"))
    for (const auto& w : in.summary["warnings"])
      all.push_back(w.get<std::string>());
  all.insert(all.end(), in.notes.begin(), in.notes.end());
  if (all.empty()) return;
  h += "<section id=\"warnings\"><h2>Warnings</h2><ul class=\"warnings\">\n";
  for (const std::string& w : all)
    h += "<li>" + xml_escaped(w) + "</li>\n";
  h += "</ul></section>\n";
}

/// The first load drop F_d of summary.json's `load_drop`, as report.txt prints it.
void load_drop_row(std::string& h, const nlohmann::json& j) {
  if (!j.contains("load_drop") || j["load_drop"].is_null()) return;
  const nlohmann::json& d = j["load_drop"];
  html_row(h, "first load drop F<sub>d</sub>",
           d["force_N"].is_null()
               ? std::string("none (the smoothed force never fell by 5 % while loading)")
               : fmt::format("{} at {}", value(d, "force_N", "N"), value(d, "time_s", "ms", 1e3)));
}

/// summary.json's `absorbed_energy_by_mechanism`, a row each (none before the impactor has left).
void absorbed_by_mechanism_rows(std::string& h, const nlohmann::json& j) {
  if (!j.contains("absorbed_energy_by_mechanism") || j["absorbed_energy_by_mechanism"].is_null()) return;
  const nlohmann::json& a = j["absorbed_energy_by_mechanism"];
  html_row(h, "&#8195;absorbed by contact (indentation)", value(a, "contact_J", "J"));
  html_row(h, "&#8195;absorbed by ply damage", value(a, "ply_damage_J", "J"));
  html_row(h, "&#8195;absorbed by delamination", value(a, "delamination_J", "J"));
  html_row(h, "&#8195;left in plate vibration", value(a, "plate_vibration_J", "J"));
  html_row(h, "&#8195;unaccounted", value(a, "unaccounted_J", "J"));
}

void results_section(std::string& h, const nlohmann::json& j) {
  h += "<section id=\"results\"><h2>Results</h2><table class=\"summary\">\n";
  html_row(h, "peak contact force", value(j, "peak_force", "N"));
  load_drop_row(h, j);
  html_row(h, "time of peak force", value(j, "time_of_peak_force", "ms", 1e3));
  html_row(h, "contact duration (first contact)", value(j, "contact_duration", "ms", 1e3));
  html_row(h, "contacts", value(j, "contacts", ""));
  html_row(h, "peak plate deflection at the contact point", value(j, "peak_contact_deflection", "mm", 1e3));
  html_row(h, "largest indentation", value(j, "max_indentation", "mm", 1e3));
  html_row(h, "permanent indentation", value(j, "permanent_indentation", "mm", 1e3));
  html_row(h, "impact energy", value(j, "initial_energy", "J"));
  html_row(h, "rebound velocity", value(j, "rebound_velocity", "m/s"));
  html_row(h, "absorbed energy", value(j, "absorbed_energy", "J"));
  absorbed_by_mechanism_rows(h, j);
  html_row(h, "contact dissipation", value(j, "contact_dissipation", "J"));
  html_row(h, "energy balance error", value(j, "energy_balance_error", "% of the impact energy", 100.0));
  html_row(h, "steps", value(j, "steps", ""));
  html_row(h, "end time", value(j, "end_time", "ms", 1e3));
  html_row(h, "complete", value(j, "complete", ""));
  html_row(h, "suspect", value(j, "suspect", ""));
  h += "</table></section>\n";
}

PlotSeries series(const std::vector<ImpactSample>& history, double ImpactSample::*x, double xs,
                  double ImpactSample::*y, double ys, std::string label, std::string color,
                  bool dashed = false) {
  PlotSeries s{std::move(label), {}, {}, std::move(color), dashed};
  s.x.reserve(history.size());
  s.y.reserve(history.size());
  for (const ImpactSample& h : history) {
    s.x.push_back(h.*x * xs);
    s.y.push_back(h.*y * ys);
  }
  return s;
}

/// Force against the impactor's displacement while it touches the plate (α ≥ 0), as a drop-weight test
/// report plots it (ASTM D7136 §13): the loading and unloading loop; the flight after rebound, which
/// would stretch the axis far below zero, is a gap (as in plots.cpp's force_displacement).
PlotSeries contact_loop(const std::vector<ImpactSample>& history) {
  PlotSeries s =
      series(history, &ImpactSample::impactor_w, 1e3, &ImpactSample::force, 1e-3, "contact force", "#1f77b4");
  for (std::size_t i = 0; i < history.size(); ++i)
    if (history[i].indentation < 0.0) s.x[i] = std::numeric_limits<double>::quiet_NaN();
  return s;
}

/// The samples the time plots show: up to a fifth past the last contact's end, where the impactor left
/// (issue 82: the force–time axis ran to 10 ms after a 4.2 ms contact, the curve flat at zero for the
/// second half); all of them where it had not. history.csv keeps every step.
std::vector<ImpactSample> to_shortly_after_contact(const std::vector<ImpactSample>& history) {
  const auto last_touch =
      std::find_if(history.rbegin(), history.rend(), [](const ImpactSample& s) { return s.force > 0.0; });
  if (last_touch == history.rend() || last_touch == history.rbegin()) return history;
  const double until = 1.2 * last_touch->t;
  std::vector<ImpactSample> shown;
  for (const ImpactSample& s : history)
    if (s.t <= until) shown.push_back(s);
  return shown;
}

void curves_section(std::string& h, const std::vector<ImpactSample>& all, bool damage) {
  const std::vector<ImpactSample> history = to_shortly_after_contact(all);
  h += "<section id=\"curves\"><h2>Curves</h2>\n";
  if (history.size() < all.size())
    fmt::format_to(std::back_inserter(h),
                   "<p>The time plots end at {:.4g} ms, a fifth past the end of the last contact; the run "
                   "went on to {:.4g} ms (history.csv has every step).</p>\n",
                   history.back().t * 1e3, all.back().t * 1e3);
  h += svg_line_plot(
      {"Contact force",
       "time [ms]",
       "force [kN]",
       {series(history, &ImpactSample::t, 1e3, &ImpactSample::force, 1e-3, "contact force", "#1f77b4")}});
  h += svg_line_plot({"Force–displacement (impactor, in contact)",
                      "impactor displacement since first contact [mm]",
                      "force [kN]",
                      {contact_loop(history)}});
  LinePlot energy{"Energies", "time [ms]", "energy [J]", {}};
  energy.series.push_back(series(history, &ImpactSample::t, 1e3, &ImpactSample::impactor_energy, 1.0,
                                 "impactor kinetic", "#1f77b4"));
  energy.series.push_back(
      series(history, &ImpactSample::t, 1e3, &ImpactSample::plate_strain, 1.0, "plate strain", "#ff7f0e"));
  energy.series.push_back(
      series(history, &ImpactSample::t, 1e3, &ImpactSample::plate_kinetic, 1.0, "plate kinetic", "#2ca02c"));
  energy.series.push_back(series(history, &ImpactSample::t, 1e3, &ImpactSample::contact_work, 1.0,
                                 "contact work ∫F dα", "#9467bd", true));
  if (damage)
    energy.series.push_back(series(history, &ImpactSample::t, 1e3, &ImpactSample::damage_dissipation, 1.0,
                                   "ply damage dissipation", "#d62728", true));
  h += svg_line_plot(energy);
  h += "</section>\n";
}

std::string layer(const DamageOnset& o) {
  return o.ply > 0 ? fmt::format("ply {}", o.ply) : fmt::format("interface {}", o.interface);
}

/// The laminate's first failure (away from a rig's clamp tips) in words, and how many rows of the table lie
/// at the tips.
void laminate_first_failure_paragraph(std::string& h, const ImpactReportInput& in) {
  const auto& f = in.laminate_first_failure;
  h += "<p>The laminate's first failure: " +
       (f ? fmt::format("{} {} in {}, element {} at ({:.1f}, {:.1f}) mm, at {:.4g} µs under {:.5g} N",
                        to_string(f->criterion), to_string(f->mode), layer(*f), f->element, f->x * 1e3,
                        f->y * 1e3, f->time * 1e6, f->force)
          : std::string("none away from the clamp tips"));
  if (!in.clamp_tip_elements.empty()) {
    const auto tips = std::ranges::count_if(
        *in.first_failures, [&](const DamageOnset& o) { return at_clamp_tip(o, in.clamp_tip_elements); });
    h += fmt::format(". {} of the {} first failures below lie at the rig's clamp tips, point supports whose "
                     "stresses are singular: they say nothing of the laminate and are not its first failure",
                     tips, in.first_failures->size());
  }
  h += ".</p>\n";
}

void damage_section(std::string& h, const ImpactReportInput& in) {
  if (in.first_failures == nullptr) return;
  h += "<section id=\"damage\"><h2>Damage onsets</h2>\n";
  if (in.first_failures->empty()) {
    h += "<p>No criterion reached 1.</p>\n";
  } else {
    laminate_first_failure_paragraph(h, in);
    const bool rig = !in.clamp_tip_elements.empty(); // a column "where" for the clamp tips
    fmt::format_to(
        std::back_inserter(h),
        "<table class=\"onsets\"><tr><th>criterion</th><th>mode</th><th>ply / interface</th>"
        "<th>element</th><th>x, y [mm]</th><th>time [µs]</th><th>force [N]</th><th>index</th>{}</tr>\n",
        rig ? "<th>where</th>" : "");
    for (const DamageOnset& o : *in.first_failures)
      fmt::format_to(
          std::back_inserter(h),
          "<tr><td>{}</td><td>{}</td><td>{}</td><td class=\"number\">{}</td><td class=\"number\">{:.1f}, "
          "{:.1f}</td><td class=\"number\">{:.4g}</td><td class=\"number\">{:.5g}</td><td class=\"number\">"
          "{:.4g}</td>{}</tr>\n",
          to_string(o.criterion), to_string(o.mode), layer(o), o.element, o.x * 1e3, o.y * 1e3, o.time * 1e6,
          o.force, o.index,
          !rig                                     ? ""
          : at_clamp_tip(o, in.clamp_tip_elements) ? "<td>clamp tip</td>"
                                                   : "<td></td>");
    h += "</table>\n";
  }
  if (in.mesh != nullptr && in.onsets != nullptr)
    h += svg_onset_map(*in.mesh, *in.onsets, in.settings.impactor.x, in.settings.impactor.y,
                       rig_outline(in.deck.rig));
  h += "</section>\n";
}

/// The C-scan of a stacked plate's delaminations (svg_cscan_map), with the projected area of summary.json.
void delamination_section(std::string& h, const ImpactReportInput& in) {
  if (in.delamination == nullptr) return;
  const DelaminationResult& d = *in.delamination;
  h += "<section id=\"delamination\"><h2>Delaminations (C-scan)</h2>\n";
  fmt::format_to(std::back_inserter(h),
                 "<p>Projected delaminated area {:.4g} mm² (the points where some interface has d = 1). Each "
                 "point shows the shallowest interface delaminated there, as an ultrasonic C-scan from the "
                 "impacted face sees it: a deeper delamination under a shallower one is hidden (the maps of "
                 "<code>plyimpact plot</code> show each interface alone).</p>\n",
                 d.projected_area * 1e6);
  const std::vector<int> interface_of_point = shallowest_delaminated(d.point_damage);
  h += svg_cscan_map({d.point_cells, d.point_area, interface_of_point, d.interface_after_ply,
                      in.settings.impactor.x, in.settings.impactor.y, rig_outline(in.deck.rig)});
  h += "</section>\n";
}

} // namespace

std::string impact_report_html(const ImpactReportInput& in) {
  const std::string title = in.deck.title.empty() ? in.deck.source : in.deck.title;
  std::string h = html_page_start(title, fmt::format("impact analysis of {}, plyimpact {} (commit {})",
                                                     xml_escaped(in.deck.source), PLYIMPACT_VERSION,
                                                     xml_escaped(source_commit())));
  case_section(h, in);
  warnings_section(h, in);
  results_section(h, in.summary);
  curves_section(h, in.history, in.settings.progressive_damage.has_value());
  damage_section(h, in);
  delamination_section(h, in);
  return h.append(html_page_end());
}

} // namespace plyimpact
