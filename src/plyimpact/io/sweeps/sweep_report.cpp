#include "plyimpact/io/sweeps/sweep_report.hpp"

#include "plyimpact/io/deck/json_text.hpp"
#include "plyimpact/io/results/html_page.hpp"
#include "plyimpact/io/results/svg_plot.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <iterator>
#include <limits>
#include <map>
#include <numeric>
#include <optional>
#include <string_view>

namespace plyimpact {

namespace {

constexpr double nan = std::numeric_limits<double>::quiet_NaN();

/// A result of a case's record shown in the report: its key in "results", the heading with the
/// unit shown, and the factor from SI to that unit (0 for text).
struct Quantity {
  std::string_view key, heading;
  double scale = 1.0;
};

constexpr std::array<Quantity, 16> table_columns{{
    {"peak_force", "peak force [N]", 1.0},
    {"time_of_peak_force", "time of peak [µs]", 1e6},
    {"contact_duration", "contact duration [µs]", 1e6},
    {"peak_contact_deflection", "peak deflection [mm]", 1e3},
    {"max_indentation", "max indentation [mm]", 1e3},
    {"absorbed_energy", "absorbed energy [J]", 1.0},
    {"rebound_velocity", "rebound velocity [m/s]", 1.0},
    {"contacts", "contacts", 1.0},
    {"first_failure_time", "first failure [µs]", 1e6},
    {"first_failure_criterion", "criterion", 0.0},
    {"first_failure_mode", "mode", 0.0},
    {"first_failure_ply", "ply", 1.0},
    {"first_failure_interface", "interface", 1.0},
    {"threshold_velocity", "threshold velocity [m/s]", 1.0},
    {"damage_dissipation", "damage dissipation [J]", 1.0},
    {"damage_area", "damage area [mm²]", 1e6},
}};

/// The curves of an impact sweep and of a threshold sweep: (key, plot title, y label, scale).
struct Curve {
  std::string_view key, title, y_label;
  double scale = 1.0;
};
constexpr std::array<Curve, 4> impact_curves{{
    {"peak_force", "Peak contact force", "peak force [kN]", 1e-3},
    {"absorbed_energy", "Absorbed energy", "absorbed energy [J]", 1.0},
    {"damage_area", "Damage area (projected)", "damage area [mm²]", 1e6},
    {"first_failure_time", "First damage", "time of first failure [µs]", 1e6},
}};
constexpr std::array<Curve, 1> threshold_curves{{
    {"threshold_velocity", "Threshold velocity", "threshold velocity [m/s]", 1.0},
}};

/// Ten distinct colours (tab10) for the series of one plot.
constexpr std::array<std::string_view, 10> palette{"#1f77b4", "#ff7f0e", "#2ca02c", "#d62728", "#9467bd",
                                                   "#8c564b", "#e377c2", "#7f7f7f", "#bcbd22", "#17becf"};

double result(const nlohmann::json& record, std::string_view key) {
  const nlohmann::json& r = record.at("results");
  const auto it = r.find(key);
  return it != r.end() && it->is_number() ? it->get<double>() : nan;
}

std::optional<double> as_number(const std::string& text) {
  double v = 0.0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), v);
  if (error != std::errc() || end != text.data() + text.size() || !std::isfinite(v)) return std::nullopt;
  return v;
}

std::string value_text(const nlohmann::json& record, std::size_t key) {
  return record.at("values").at(key).get<std::string>();
}

/// The values of swept key `key`, one per case, when every one of them is a number.
std::optional<std::vector<double>> numeric_values(const std::vector<nlohmann::json>& records,
                                                  std::size_t key) {
  std::vector<double> v;
  v.reserve(records.size());
  for (const nlohmann::json& r : records) {
    const std::optional<double> x = as_number(value_text(r, key));
    if (!x) return std::nullopt;
    v.push_back(*x);
  }
  return v;
}

std::string listed(const std::vector<SweepValue>& values) {
  std::string s;
  const std::size_t n = values.size();
  for (std::size_t i = 0; i < n; ++i) {
    if (n > 8 && i == 3) {
      s += ", …";
      i = n - 3;
      continue;
    }
    s += (i == 0 ? "" : ", ") + xml_escaped(to_text(values[i]));
  }
  return s;
}

void sweep_section(std::string& h, const Sweep& sweep, const std::vector<nlohmann::json>& records) {
  const SweepSpec& spec = sweep.spec();
  h += "<section id=\"sweep\"><h2>The sweep</h2><dl>\n";
  html_item(h, "base deck", xml_escaped(sweep.source()));
  html_item(h, "analysis", std::string(to_string(spec.analysis)));
  if (spec.axes.size() > 1)
    html_item(h, "combination",
              spec.mode == SweepMode::zip ? "zip (the lists in step)"
                                          : "product (every combination, the last key fastest)");
  for (const SweepAxis& a : spec.axes)
    html_item(h, xml_escaped(a.key), fmt::format("{} values: {}", a.values.size(), listed(a.values)));
  for (const RandomParameter& p : spec.random)
    html_item(h, xml_escaped(p.key),
              p.distribution == Distribution::normal
                  ? fmt::format("normal, mean {:g}, standard deviation {:g}", p.a, p.b)
                  : fmt::format("uniform on [{:g}, {:g}]", p.a, p.b));
  if (!spec.random.empty())
    html_item(h, "samples", fmt::format("{} per grid point, seed {}", spec.samples, spec.seed));
  std::map<std::string, std::size_t> by_status;
  for (const nlohmann::json& r : records)
    ++by_status[r.at("status").get<std::string>()];
  std::string counts;
  for (const auto& [status, n] : by_status)
    counts += fmt::format("{}{} {}", counts.empty() ? "" : ", ", n, xml_escaped(status));
  html_item(h, "cases", fmt::format("{} ({})", records.size(), counts));
  h += "</dl></section>\n";
}

void problems_section(std::string& h, const std::vector<nlohmann::json>& records) {
  std::vector<std::string> lines;
  for (const nlohmann::json& r : records) {
    const std::string status = r.at("status").get<std::string>();
    if (status == "ok") continue;
    const auto error = r.find("error");
    lines.push_back(
        fmt::format("case {}: {}{}", r.at("case").get<std::size_t>(), status,
                    error != r.end() && error->is_string() ? ": " + error->get<std::string>() : ""));
  }
  if (lines.empty()) return;
  h += "<section id=\"warnings\"><h2>Cases that did not complete</h2><ul class=\"warnings\">\n";
  constexpr std::size_t shown = 20;
  for (std::size_t i = 0; i < std::min(shown, lines.size()); ++i)
    h += "<li>" + xml_escaped(lines[i]) + "</li>\n";
  if (lines.size() > shown) h += fmt::format("<li>and {} more (sweep.csv)</li>\n", lines.size() - shown);
  h += "</ul></section>\n";
}

/// The series of one plot against swept key `x_key`: on a grid, one line per combination of the other
/// keys (up to ten, else dots); random keys and Monte Carlo samples give dots.
std::vector<PlotSeries> series_against(const Sweep& sweep, const std::vector<nlohmann::json>& records,
                                       std::size_t x_key, const std::vector<double>& x, const Curve& curve) {
  const SweepSpec& spec = sweep.spec();
  const std::vector<std::string> keys = sweep.keys();
  const bool scattered = !spec.random.empty();
  std::map<std::string, std::vector<std::size_t>> groups; // label of the other keys' values → cases
  for (std::size_t i = 0; i < records.size(); ++i) {
    std::string label;
    if (!scattered && spec.mode == SweepMode::product)
      for (std::size_t k = 0; k < spec.axes.size(); ++k)
        if (k != x_key)
          label += fmt::format("{}{} = {}", label.empty() ? "" : ", ", keys[k], value_text(records[i], k));
    groups[label].push_back(i);
  }
  const bool lines = !scattered && groups.size() <= palette.size();
  if (!lines) {
    groups.clear();
    std::vector<std::size_t> all(records.size());
    std::iota(all.begin(), all.end(), std::size_t{0});
    groups[""] = all;
  }
  std::vector<PlotSeries> series;
  for (auto& [label, cases] : groups) {
    std::stable_sort(cases.begin(), cases.end(), [&x](std::size_t a, std::size_t b) { return x[a] < x[b]; });
    PlotSeries s{label, {}, {}, std::string(palette[series.size() % palette.size()]), false, lines, true};
    for (const std::size_t i : cases) {
      s.x.push_back(x[i]);
      s.y.push_back(result(records[i], curve.key) * curve.scale);
    }
    series.push_back(std::move(s));
  }
  return series;
}

bool any_value(const std::vector<nlohmann::json>& records, std::string_view key) {
  return std::any_of(records.begin(), records.end(),
                     [key](const nlohmann::json& r) { return std::isfinite(result(r, key)); });
}

void curves_section(std::string& h, const Sweep& sweep, const std::vector<nlohmann::json>& records) {
  const std::vector<std::string> keys = sweep.keys();
  std::vector<Curve> curves;
  if (sweep.spec().analysis == AnalysisKind::threshold)
    curves.assign(threshold_curves.begin(), threshold_curves.end());
  else
    curves.assign(impact_curves.begin(), impact_curves.end());
  std::erase_if(curves, [&records](const Curve& c) { return !any_value(records, c.key); });
  if (curves.empty() || records.empty()) return;
  h += "<section id=\"curves\"><h2>Results against the swept values</h2>\n";
  bool plotted = false;
  for (std::size_t k = 0; k < keys.size(); ++k) {
    const std::optional<std::vector<double>> x = numeric_values(records, k);
    if (!x) continue;
    plotted = true;
    h += "<div class=\"plots\">\n";
    for (const Curve& c : curves)
      h += svg_line_plot(
          {std::string(c.title), keys[k], std::string(c.y_label), series_against(sweep, records, k, *x, c)},
          512, 320);
    h += "</div>\n";
  }
  if (!plotted) { // no numeric key: the results case by case
    std::vector<double> index(records.size());
    std::iota(index.begin(), index.end(), 0.0);
    h += "<div class=\"plots\">\n";
    for (const Curve& c : curves) {
      PlotSeries s{"", index, {}, std::string(palette[0]), false, false, true};
      for (const nlohmann::json& r : records)
        s.y.push_back(result(r, c.key) * c.scale);
      h += svg_line_plot({std::string(c.title), "case", std::string(c.y_label), {s}}, 512, 320);
    }
    h += "</div>\n";
  }
  h += "</section>\n";
}

std::string cell(const nlohmann::json& record, const Quantity& q) {
  const nlohmann::json& r = record.at("results");
  const auto it = r.find(q.key);
  if (it == r.end() || it->is_null()) return "";
  if (it->is_string()) return xml_escaped(it->get<std::string>());
  if (it->is_number_integer()) return fmt::format("{}", it->get<long>());
  return it->is_number() ? html_number(it->get<double>(), "", q.scale) : xml_escaped(json_text(*it));
}

void table_section(std::string& h, const Sweep& sweep, const std::vector<nlohmann::json>& records) {
  std::vector<Quantity> shown;
  for (const Quantity& q : table_columns)
    if (std::any_of(records.begin(), records.end(), [&q](const nlohmann::json& r) {
          const auto it = r.at("results").find(q.key);
          return it != r.at("results").end() && !it->is_null();
        }))
      shown.push_back(q);
  h += "<section id=\"cases\"><h2>Cases</h2>\n<p>Every case of sweep.csv, in engineering units (sweep.csv "
       "keeps SI and every digit).</p>\n<div class=\"wide\"><table class=\"cases\">\n<tr><th>case</th>";
  const std::vector<std::string> keys = sweep.keys();
  for (const std::string& k : keys)
    h += "<th>" + xml_escaped(k) + "</th>";
  h += "<th>status</th>";
  for (const Quantity& q : shown)
    fmt::format_to(std::back_inserter(h), "<th>{}</th>", q.heading);
  h += "</tr>\n";
  for (const nlohmann::json& r : records) {
    const bool ok = r.at("status").get<std::string>() == "ok";
    fmt::format_to(std::back_inserter(h), "<tr{}><td class=\"number\">{}</td>", ok ? "" : " class=\"failed\"",
                   r.at("case").get<std::size_t>());
    for (std::size_t k = 0; k < keys.size(); ++k)
      h += "<td class=\"number\">" + xml_escaped(value_text(r, k)) + "</td>";
    h += "<td>" + xml_escaped(r.at("status").get<std::string>()) + "</td>";
    for (const Quantity& q : shown)
      h += "<td class=\"number\">" + cell(r, q) + "</td>";
    h += "</tr>\n";
  }
  h += "</table></div></section>\n";
}

} // namespace

std::string sweep_report_html(const Sweep& sweep, const std::vector<nlohmann::json>& records) {
  const std::string title = sweep.title().empty() ? sweep.source() : sweep.title();
  std::string h = html_page_start(
      title,
      fmt::format("sweep of {} case{} over {}, plyimpact {}", records.size(), records.size() == 1 ? "" : "s",
                  xml_escaped(fmt::format("{}", fmt::join(sweep.keys(), ", "))), PLYIMPACT_VERSION));
  sweep_section(h, sweep, records);
  problems_section(h, records);
  curves_section(h, sweep, records);
  table_section(h, sweep, records);
  return h.append(html_page_end());
}

} // namespace plyimpact
