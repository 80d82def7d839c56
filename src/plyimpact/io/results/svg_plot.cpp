#include "plyimpact/io/results/svg_plot.hpp"

#include "plyimpact/io/results/plots.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <iterator>
#include <limits>
#include <vector>

namespace plyimpact {

namespace {

/// Plot area inside the picture: margins for the tick labels, the axis labels and the title.
struct Frame {
  double left = 72.0, right = 16.0, top = 34.0, bottom = 48.0;
  double width = 0.0, height = 0.0;
  double x0 = 0.0, x1 = 1.0, y0 = 0.0, y1 = 1.0; ///< data range shown

  [[nodiscard]] double px(double x) const { return left + (x - x0) / (x1 - x0) * (width - left - right); }
  [[nodiscard]] double py(double y) const {
    return height - bottom - (y - y0) / (y1 - y0) * (height - top - bottom);
  }
};

/// The shortest tick label: 0.5, 2, 1e+04 (fmt's general format with 4 significant digits).
std::string tick_label(double v, double step) {
  if (std::abs(v) < 1e-9 * step) v = 0.0;
  return fmt::format("{:.4g}", v);
}

std::pair<double, double> finite_range(const std::vector<double>& v) {
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (const double x : v)
    if (std::isfinite(x)) {
      lo = std::min(lo, x);
      hi = std::max(hi, x);
    }
  return {lo, hi};
}

void axes(std::string& s, const Frame& f, const std::vector<double>& xt, const std::vector<double>& yt,
          const LinePlot& plot) {
  auto out = std::back_inserter(s);
  const double xstep = xt.size() > 1 ? xt[1] - xt[0] : 1.0, ystep = yt.size() > 1 ? yt[1] - yt[0] : 1.0;
  for (const double x : xt)
    fmt::format_to(out,
                   "<line x1=\"{0:.1f}\" y1=\"{1:.1f}\" x2=\"{0:.1f}\" y2=\"{2:.1f}\" class=\"grid\"/>"
                   "<text x=\"{0:.1f}\" y=\"{3:.1f}\" text-anchor=\"middle\">{4}</text>\n",
                   f.px(x), f.py(f.y0), f.py(f.y1), f.py(f.y0) + 16.0, tick_label(x, xstep));
  for (const double y : yt)
    fmt::format_to(out,
                   "<line x1=\"{0:.1f}\" y1=\"{1:.1f}\" x2=\"{2:.1f}\" y2=\"{1:.1f}\" class=\"grid\"/>"
                   "<text x=\"{3:.1f}\" y=\"{4:.1f}\" text-anchor=\"end\">{5}</text>\n",
                   f.px(f.x0), f.py(y), f.px(f.x1), f.px(f.x0) - 6.0, f.py(y) + 4.0, tick_label(y, ystep));
  fmt::format_to(out,
                 "<rect x=\"{:.1f}\" y=\"{:.1f}\" width=\"{:.1f}\" height=\"{:.1f}\" class=\"frame\"/>\n",
                 f.left, f.top, f.width - f.left - f.right, f.height - f.top - f.bottom);
  fmt::format_to(out, "<text x=\"{:.1f}\" y=\"{:.1f}\" text-anchor=\"middle\" class=\"label\">{}</text>\n",
                 0.5 * (f.left + f.width - f.right), f.height - 10.0, xml_escaped(plot.x_label));
  fmt::format_to(out,
                 "<text transform=\"translate(16 {:.1f}) rotate(-90)\" text-anchor=\"middle\" "
                 "class=\"label\">{}</text>\n",
                 0.5 * (f.top + f.height - f.bottom), xml_escaped(plot.y_label));
  fmt::format_to(out, "<text x=\"{:.1f}\" y=\"20\" text-anchor=\"middle\" class=\"title\">{}</text>\n",
                 0.5 * f.width, xml_escaped(plot.title));
}

void polyline(std::string& s, const Frame& f, const PlotSeries& series) {
  auto out = std::back_inserter(s);
  const std::size_t n = std::min(series.x.size(), series.y.size());
  const auto shown = [&series](std::size_t i) {
    return std::isfinite(series.x[i]) && std::isfinite(series.y[i]);
  };
  // A point that is not finite is a gap: each run of shown points is a line of its own.
  for (std::size_t i = 0; series.line && i < n;) {
    if (!shown(i)) {
      ++i;
      continue;
    }
    fmt::format_to(out, "<polyline fill=\"none\" stroke=\"{}\" stroke-width=\"1.6\"{} points=\"",
                   series.color, series.dashed ? " stroke-dasharray=\"6 4\"" : "");
    for (; i < n && shown(i); ++i)
      fmt::format_to(out, "{:.1f},{:.1f} ", f.px(series.x[i]), f.py(series.y[i]));
    s += "\"/>\n";
  }
  if (series.markers)
    for (std::size_t i = 0; i < n; ++i)
      if (shown(i))
        fmt::format_to(out, "<circle cx=\"{:.1f}\" cy=\"{:.1f}\" r=\"3.2\" fill=\"{}\"/>\n",
                       f.px(series.x[i]), f.py(series.y[i]), series.color);
}

/// How many points of `series` (and midpoints of their segments) fall in the box [x, x + w] × [y, y + h] px.
std::size_t points_in_box(const Frame& f, const std::vector<PlotSeries>& series, double x, double y, double w,
                          double h) {
  const auto inside = [&](double px, double py) { return px >= x && px <= x + w && py >= y && py <= y + h; };
  std::size_t covered = 0;
  for (const PlotSeries& c : series) {
    const std::size_t n = std::min(c.x.size(), c.y.size());
    for (std::size_t i = 0; i < n; ++i) {
      if (!std::isfinite(c.x[i]) || !std::isfinite(c.y[i])) continue;
      covered += inside(f.px(c.x[i]), f.py(c.y[i])) ? 1 : 0;
      if (i + 1 < n && std::isfinite(c.x[i + 1]) && std::isfinite(c.y[i + 1]))
        covered +=
            inside(0.5 * (f.px(c.x[i]) + f.px(c.x[i + 1])), 0.5 * (f.py(c.y[i]) + f.py(c.y[i + 1]))) ? 1 : 0;
    }
  }
  return covered;
}

/// The legend where its box covers the fewest points of the curves, of nine places in the plot area: the
/// corners (top right first, then top left, bottom right, bottom left), then the middles of the right and
/// left sides, of the top and bottom, and the centre. So it sits on no curve where one of them is free
/// (issue 82: the energy plot's legend sat on the impactor's kinetic energy, which ends high at the right).
void legend(std::string& s, const Frame& f, const std::vector<PlotSeries>& series) {
  if (series.size() < 2) return;
  auto out = std::back_inserter(s);
  const double w = 196.0, h = 16.0 * static_cast<double>(series.size()) + 8.0;
  const double left = f.left + 6.0, right = f.width - f.right - w - 6.0, centre = 0.5 * (left + right);
  const double top = f.top + 4.0, bottom = f.height - f.bottom - h - 4.0, middle = 0.5 * (top + bottom);
  const std::array<std::array<double, 2>, 9> corners = {{{right, top},
                                                         {left, top},
                                                         {right, bottom},
                                                         {left, bottom},
                                                         {right, middle},
                                                         {left, middle},
                                                         {centre, top},
                                                         {centre, bottom},
                                                         {centre, middle}}};
  std::array<double, 2> at = corners[0];
  std::size_t fewest = std::numeric_limits<std::size_t>::max();
  for (const auto& c : corners)
    if (const std::size_t n = points_in_box(f, series, c[0], c[1], w, h); n < fewest) {
      fewest = n;
      at = c;
    }
  for (std::size_t k = 0; k < series.size(); ++k) {
    const double x = at[0] + 4.0, y = at[1] + 10.0 + 16.0 * static_cast<double>(k);
    fmt::format_to(out,
                   "<line x1=\"{0:.1f}\" y1=\"{1:.1f}\" x2=\"{2:.1f}\" y2=\"{1:.1f}\" stroke=\"{3}\" "
                   "stroke-width=\"2\"{4}/><text x=\"{5:.1f}\" y=\"{6:.1f}\">{7}</text>\n",
                   x, y, x + 22.0, series[k].color, series[k].dashed ? " stroke-dasharray=\"6 4\"" : "",
                   x + 28.0, y + 4.0, xml_escaped(series[k].label));
  }
}

std::string svg_open(int width, int height, std::string_view kind, std::string_view label) {
  return fmt::format(
      "<svg xmlns=\"http://www.w3.org/2000/svg\" class=\"{}\" viewBox=\"0 0 {} {}\" width=\"{}\" "
      "height=\"{}\" role=\"img\" aria-label=\"{}\">\n",
      kind, width, height, width, height, xml_escaped(label));
}

/// Five-stop perceptual ramp (viridis) at t in [0, 1].
std::string ramp(double t) {
  static constexpr double stops[5][3] = {
      {68, 1, 84}, {59, 82, 139}, {33, 145, 140}, {94, 201, 98}, {253, 231, 37}};
  t = std::clamp(t, 0.0, 1.0) * 4.0;
  const int i = std::min(3, static_cast<int>(t));
  const double u = t - i;
  return fmt::format("rgb({:.0f},{:.0f},{:.0f})", stops[i][0] + u * (stops[i + 1][0] - stops[i][0]),
                     stops[i][1] + u * (stops[i + 1][1] - stops[i][1]),
                     stops[i][2] + u * (stops[i + 1][2] - stops[i][2]));
}

/// A plate drawn to scale above its legend: the rectangle [x0, x1] × [y0, y1] [m] fills the width less a
/// margin on each side, the legend (legend_h px) lies below it; X and Y map plate coordinates to the picture
/// [px].
struct PlateFrame {
  static constexpr double margin = 20.0;
  double x0, y0, legend_h, scale;
  int height;
  PlateFrame(double x_min, double x_max, double y_min, double y_max, double legend, int width)
      : x0(x_min), y0(y_min), legend_h(legend),
        scale((width - 2.0 * margin) / std::max(x_max - x_min, 1e-12)),
        height(static_cast<int>(std::ceil((y_max - y_min) * scale + 2.0 * margin + legend_h))) {}
  /// The frame of `mesh`'s bounding box.
  PlateFrame(const Mesh& mesh, double legend, int width)
      : PlateFrame(mesh.bounds().x_min, mesh.bounds().x_max, mesh.bounds().y_min, mesh.bounds().y_max, legend,
                   width) {}
  [[nodiscard]] double X(double x) const { return margin + (x - x0) * scale; }
  [[nodiscard]] double Y(double y) const { return height - legend_h - margin - (y - y0) * scale; }
};

/// Every element of `mesh` as a polygon through its corners.
std::string svg_elements(const Mesh& mesh, const PlateFrame& f) {
  std::string s;
  auto out = std::back_inserter(s);
  for (int e = 0; e < mesh.element_count(); ++e) {
    s += "<polygon class=\"element\" points=\"";
    for (const auto& [xi, eta] : {std::pair{-1.0, -1.0}, {1.0, -1.0}, {1.0, 1.0}, {-1.0, 1.0}}) {
      const Eigen::Vector2d p = mesh.map(e, xi, eta);
      fmt::format_to(out, "{:.1f},{:.1f} ", f.X(p.x()), f.Y(p.y()));
    }
    s += "\"/>\n";
  }
  return s;
}

/// The rig's window edge (dashed) and clamp tips (open circles) over a plate drawn in `f`.
std::string svg_rig_outline(const RigOutline& rig, const PlateFrame& f) {
  std::string s;
  auto out = std::back_inserter(s);
  if (!rig.window.empty()) {
    s += "<polygon class=\"window\" fill=\"none\" stroke=\"#000\" stroke-dasharray=\"6 4\" points=\"";
    for (const Eigen::Vector2d& p : rig.window)
      fmt::format_to(out, "{:.1f},{:.1f} ", f.X(p.x()), f.Y(p.y()));
    s += "\"/>\n";
  }
  for (const Eigen::Vector2d& p : rig.clamp_tips)
    fmt::format_to(
        out,
        "<circle class=\"clamp\" cx=\"{:.1f}\" cy=\"{:.1f}\" r=\"7\" fill=\"none\" stroke=\"#000\" "
        "stroke-width=\"1.5\"/>\n",
        f.X(p.x()), f.Y(p.y()));
  return s;
}

} // namespace

std::string ply_colour(double angle_deg) {
  double a = std::fmod(angle_deg, 180.0);
  if (a < -90.0) a += 180.0;
  if (a > 90.0) a -= 180.0;
  if (std::abs(a) < 1e-9) return "#4e79a7";
  if (std::abs(std::abs(a) - 90.0) < 1e-9) return "#e15759";
  if (std::abs(a - 45.0) < 1e-9) return "#59a14f";
  if (std::abs(a + 45.0) < 1e-9) return "#b07aa1";
  // hsl(200° + a, 45 %, 60 %) as RGB (the usual HSL to RGB conversion)
  const double h = std::fmod(200.0 + a + 360.0, 360.0) / 60.0, l = 0.60, sat = 0.45;
  const double c = (1.0 - std::abs(2.0 * l - 1.0)) * sat, x = c * (1.0 - std::abs(std::fmod(h, 2.0) - 1.0));
  const double m = l - 0.5 * c;
  const std::array<std::array<double, 3>, 6> sextant = {
      {{c, x, 0.0}, {x, c, 0.0}, {0.0, c, x}, {0.0, x, c}, {x, 0.0, c}, {c, 0.0, x}}};
  const auto& rgb = sextant[static_cast<std::size_t>(std::min(5.0, std::floor(h)))];
  return fmt::format("#{:02x}{:02x}{:02x}", static_cast<int>(std::lround((rgb[0] + m) * 255.0)),
                     static_cast<int>(std::lround((rgb[1] + m) * 255.0)),
                     static_cast<int>(std::lround((rgb[2] + m) * 255.0)));
}

std::string xml_escaped(std::string_view text) {
  std::string s;
  s.reserve(text.size());
  for (const char c : text)
    switch (c) {
    case '&':
      s += "&amp;";
      break;
    case '<':
      s += "&lt;";
      break;
    case '>':
      s += "&gt;";
      break;
    case '"':
      s += "&quot;";
      break;
    default:
      s += c;
    }
  return s;
}

std::vector<double> nice_ticks(double lo, double hi, int target) {
  if (!std::isfinite(lo) || !std::isfinite(hi)) lo = 0.0, hi = 1.0;
  if (hi <= lo) {
    const double pad = lo == 0.0 ? 1.0 : 0.1 * std::abs(lo);
    lo -= pad;
    hi += pad;
  }
  const double raw = (hi - lo) / std::max(1, target);
  const int exponent = static_cast<int>(std::floor(std::log10(raw)));
  const double magnitude = std::pow(10.0, std::abs(exponent)); // exact for the exponents plots meet
  double mantissa = 10.0;                                      // step = mantissa × 10^exponent
  for (const double m : {1.0, 2.0, 5.0})
    if ((exponent < 0 ? m / magnitude : m * magnitude) >= raw) {
      mantissa = m;
      break;
    }
  // k·mantissa is an integer: one rounding (a division by 10^n) gives 0.3, not 3 × 0.1.
  const auto tick = [&](long k) {
    const double units = static_cast<double>(k) * mantissa;
    return exponent < 0 ? units / magnitude : units * magnitude;
  };
  const double step = tick(1);
  const auto first = static_cast<long>(std::floor(lo / step + 1e-9));
  const auto last = std::max(first + 1, static_cast<long>(std::ceil(hi / step - 1e-9)));
  std::vector<double> ticks;
  for (long k = first; k <= last; ++k)
    ticks.push_back(tick(k));
  return ticks;
}

std::string svg_line_plot(const LinePlot& plot, int width, int height) {
  double xlo = std::numeric_limits<double>::infinity(), xhi = -xlo, ylo = xlo, yhi = -xlo;
  for (const PlotSeries& s : plot.series) {
    const auto [a, b] = finite_range(s.x);
    const auto [c, d] = finite_range(s.y);
    xlo = std::min(xlo, a), xhi = std::max(xhi, b), ylo = std::min(ylo, c), yhi = std::max(yhi, d);
  }
  const std::vector<double> xt = nice_ticks(xlo, xhi), yt = nice_ticks(ylo, yhi);
  Frame f;
  f.width = width;
  f.height = height;
  f.x0 = xt.front(), f.x1 = xt.back(), f.y0 = yt.front(), f.y1 = yt.back();
  std::string s = svg_open(width, height, "plot", plot.title);
  axes(s, f, xt, yt, plot);
  for (const PlotSeries& series : plot.series)
    polyline(s, f, series);
  legend(s, f, plot.series);
  return s + "</svg>\n";
}

std::string svg_ply_stack(const Laminate& laminate, const std::vector<int>& interfaces_after_ply) {
  const int n = static_cast<int>(laminate.ply_count());
  const double ply_h = std::clamp(360.0 / n, 4.0, 22.0);
  const bool interfaces = !interfaces_after_ply.empty();
  const int width = 360, height = static_cast<int>(std::ceil(ply_h * n)) + (interfaces ? 56 : 40);
  std::string s = svg_open(width, height, "plies", "ply stack, ply 1 (impacted face) on top");
  auto out = std::back_inserter(s);
  fmt::format_to(out, "<text x=\"10\" y=\"14\" class=\"label\">impacted face</text>\n");
  for (int k = 0; k < n; ++k) {
    const auto& ply = laminate.plies()[static_cast<std::size_t>(k)];
    const double y = 20.0 + ply_h * k;
    fmt::format_to(
        out, "<rect x=\"10\" y=\"{:.1f}\" width=\"200\" height=\"{:.1f}\" fill=\"{}\" class=\"ply\"/>\n", y,
        ply_h, ply_colour(ply.angle_deg));
    if (ply_h >= 9.0)
      fmt::format_to(out, "<text x=\"218\" y=\"{:.1f}\">{} {:g}° {}</text>\n", y + 0.5 * ply_h + 4.0, k + 1,
                     ply.angle_deg, xml_escaped(laminate.material_of(static_cast<std::size_t>(k)).name));
  }
  for (const int after : interfaces_after_ply)
    fmt::format_to(out,
                   "<line class=\"interface\" x1=\"4\" y1=\"{0:.1f}\" x2=\"216\" y2=\"{0:.1f}\" "
                   "stroke=\"#d62728\" stroke-width=\"2.5\"/>\n",
                   20.0 + ply_h * after);
  const double foot = 20.0 + ply_h * n + 14.0;
  fmt::format_to(out, "<text x=\"10\" y=\"{:.1f}\" class=\"label\">back face ({} plies, {:.3g} mm)</text>\n",
                 foot, n, laminate.thickness() * 1e3);
  if (interfaces)
    fmt::format_to(
        out,
        "<text x=\"10\" y=\"{:.1f}\"><tspan fill=\"#d62728\">━</tspan> the {} interface{} that may "
        "delaminate</text>\n",
        foot + 16.0, interfaces_after_ply.size(), interfaces_after_ply.size() == 1 ? "" : "s");
  return s + "</svg>\n";
}

const char* support_colour(std::size_t k) {
  static constexpr std::array<const char*, 6> colours = {"#1f77b4", "#2ca02c", "#9467bd",
                                                         "#ff7f0e", "#8c564b", "#17becf"};
  return colours[k % colours.size()];
}

std::string svg_model_plan(const ModelPlan& plan, int width) {
  const Mesh& mesh = plan.mesh;
  const std::size_t legend_lines = plan.supports.size() + (plan.impact_point ? 1 : 0) +
                                   (plan.rig.clamp_tips.empty() && plan.rig.window.empty() ? 0 : 1);
  const PlateFrame f(mesh, 10.0 + 18.0 * static_cast<double>(legend_lines), width);
  const double margin = PlateFrame::margin;
  std::string s = svg_open(width, f.height, "plan", "the plate: mesh, supports and impact point");
  auto out = std::back_inserter(s);
  s += svg_elements(mesh, f);
  for (std::size_t k = 0; k < plan.supports.size(); ++k)
    for (const Eigen::Vector2d& p : plan.supports[k].points)
      fmt::format_to(
          out, "<rect class=\"support\" x=\"{:.1f}\" y=\"{:.1f}\" width=\"5\" height=\"5\" fill=\"{}\"/>\n",
          f.X(p.x()) - 2.5, f.Y(p.y()) - 2.5, support_colour(k));
  s += svg_rig_outline(plan.rig, f);
  if (plan.impact_point) {
    const Eigen::Vector2d& p = *plan.impact_point;
    fmt::format_to(out,
                   "<circle class=\"contact\" cx=\"{0:.1f}\" cy=\"{1:.1f}\" r=\"{2:.2f}\" fill=\"#d62728\" "
                   "fill-opacity=\"0.25\" stroke=\"#d62728\"/>\n"
                   "<path d=\"M{0:.1f},{1:.1f}m-7,-7l14,14m0,-14l-14,14\" class=\"impact\"/>\n",
                   f.X(p.x()), f.Y(p.y()), plan.contact_radius * f.scale);
  }
  double ly = f.height - f.legend_h + 12.0;
  for (std::size_t k = 0; k < plan.supports.size(); ++k, ly += 18.0)
    fmt::format_to(out,
                   "<rect x=\"{:.1f}\" y=\"{:.1f}\" width=\"8\" height=\"8\" fill=\"{}\"/>"
                   "<text x=\"{:.1f}\" y=\"{:.1f}\">{}</text>\n",
                   margin, ly - 8.0, support_colour(k), margin + 14.0, ly,
                   xml_escaped(plan.supports[k].label));
  if (plan.impact_point) {
    fmt::format_to(out,
                   "<text x=\"{:.1f}\" y=\"{:.1f}\"><tspan fill=\"#d62728\">✕ ●</tspan> impact point "
                   "({:.4g}, {:.4g}) mm and the largest contact circle {}, radius {:.3g} mm</text>\n",
                   margin, ly, plan.impact_point->x() * 1e3, plan.impact_point->y() * 1e3,
                   plan.contact_reached ? "of the run" : "expected", plan.contact_radius * 1e3);
    ly += 18.0;
  }
  if (!plan.rig.clamp_tips.empty())
    fmt::format_to(out, "<text x=\"{:.1f}\" y=\"{:.1f}\">○ {}; - - window edge</text>\n", margin, ly,
                   xml_escaped(clamp_tip_note));
  else if (!plan.rig.window.empty())
    fmt::format_to(out, "<text x=\"{:.1f}\" y=\"{:.1f}\">- - window edge</text>\n", margin, ly);
  return s + "</svg>\n";
}

std::string svg_onset_map(const Mesh& mesh, const std::vector<DamageOnset>& onsets, double impact_x,
                          double impact_y, const RigOutline& rig, int width) {
  const PlateFrame f(mesh, 46.0, width);
  const double margin = PlateFrame::margin;
  std::string s = svg_open(width, f.height, "map", "damage onsets on the plate");
  auto out = std::back_inserter(s);
  s += svg_elements(mesh, f);
  double t0 = std::numeric_limits<double>::infinity(), t1 = -t0;
  for (const DamageOnset& o : onsets)
    t0 = std::min(t0, o.time), t1 = std::max(t1, o.time);
  for (const DamageOnset& o : onsets)
    fmt::format_to(out, "<circle cx=\"{:.1f}\" cy=\"{:.1f}\" r=\"3\" fill=\"{}\"/>\n", f.X(o.x), f.Y(o.y),
                   ramp(t1 > t0 ? (o.time - t0) / (t1 - t0) : 0.0));
  s += svg_rig_outline(rig, f);
  fmt::format_to(out,
                 "<path d=\"M{0:.1f},{1:.1f}m-7,-7l14,14m0,-14l-14,14\" class=\"impact\"/>"
                 "<text x=\"{2:.1f}\" y=\"{3:.1f}\">impact point</text>\n",
                 f.X(impact_x), f.Y(impact_y), f.X(impact_x) + 9.0, f.Y(impact_y) - 9.0);
  const double ly = f.height - f.legend_h + 8.0;
  for (int k = 0; k < 40; ++k)
    fmt::format_to(out, "<rect x=\"{:.1f}\" y=\"{:.1f}\" width=\"5\" height=\"12\" fill=\"{}\"/>",
                   margin + 5.0 * k, ly, ramp(k / 39.0));
  if (onsets.empty())
    fmt::format_to(out, "<text x=\"{:.1f}\" y=\"{:.1f}\">no onset</text>\n", margin + 210.0, ly + 10.0);
  else
    fmt::format_to(out, "<text x=\"{:.1f}\" y=\"{:.1f}\">onset time {:.4g} … {:.4g} µs ({} onsets)</text>\n",
                   margin + 210.0, ly + 10.0, t0 * 1e6, t1 * 1e6, onsets.size());
  if (!rig.clamp_tips.empty())
    fmt::format_to(out, "<text x=\"{:.1f}\" y=\"{:.1f}\">○ {}; - - window edge</text>\n", margin, ly + 30.0,
                   xml_escaped(clamp_tip_note));
  return s + "</svg>\n";
}

std::vector<int> shallowest_delaminated(const std::vector<std::vector<double>>& point_damage) {
  std::vector<int> interface_of(point_damage.empty() ? 0 : point_damage.front().size(), 0);
  for (std::size_t q = 0; q < interface_of.size(); ++q)
    for (std::size_t i = 0; i < point_damage.size(); ++i)
      if (point_damage[i][q] >= 1.0) {
        interface_of[q] = static_cast<int>(i) + 1;
        break;
      }
  return interface_of;
}

const char* cscan_colour(int i) {
  return tab10[static_cast<std::size_t>(i - 1) % tab10.size()];
}

std::string svg_cscan_map(const CscanMap& map, int width) {
  double x0 = std::numeric_limits<double>::infinity(), x1 = -x0, y0 = x0, y1 = -x0;
  for (const auto& cell : map.cells)
    for (const Eigen::Vector2d& c : cell)
      x0 = std::min(x0, c.x()), x1 = std::max(x1, c.x()), y0 = std::min(y0, c.y()), y1 = std::max(y1, c.y());
  for (const Eigen::Vector2d& p : map.rig.window)
    x0 = std::min(x0, p.x()), x1 = std::max(x1, p.x()), y0 = std::min(y0, p.y()), y1 = std::max(y1, p.y());
  const double margin = PlateFrame::margin, row_h = 18.0;
  const PlateFrame f(x0, x1, y0, y1, row_h * static_cast<double>(map.after_ply.size() + 2) + 8.0, width);
  std::string s = svg_open(width, f.height, "map", "C-scan of the delaminations from the impacted face");
  auto out = std::back_inserter(s);
  std::vector<double> share(map.after_ply.size() + 1, 0.0); // projected area per interface [m²]
  for (std::size_t q = 0; q < map.cells.size(); ++q) {
    const int i = map.interface_of_point[q];
    if (i == 0) continue; // intact: the background
    share[static_cast<std::size_t>(i)] += map.area[q];
    s += fmt::format("<polygon fill=\"{0}\" stroke=\"{0}\" stroke-width=\"0.6\" points=\"", cscan_colour(i));
    for (const Eigen::Vector2d& c : map.cells[q])
      fmt::format_to(out, "{:.1f},{:.1f} ", f.X(c.x()), f.Y(c.y()));
    s += "\"/>\n";
  }
  fmt::format_to(out,
                 "<rect x=\"{:.1f}\" y=\"{:.1f}\" width=\"{:.1f}\" height=\"{:.1f}\" fill=\"none\" "
                 "stroke=\"#bbb\"/>\n",
                 f.X(x0), f.Y(y1), f.X(x1) - f.X(x0), f.Y(y0) - f.Y(y1));
  s += svg_rig_outline(map.rig, f);
  fmt::format_to(
      out,
      "<path d=\"M{0:.1f},{1:.1f}m-7,-7l14,14m0,-14l-14,14\" stroke=\"#000\" stroke-width=\"2.5\"/>"
      "<text x=\"{2:.1f}\" y=\"{3:.1f}\">impact point</text>\n",
      f.X(map.impact_x), f.Y(map.impact_y), f.X(map.impact_x) + 9.0, f.Y(map.impact_y) - 9.0);
  double ly = f.height - f.legend_h + 8.0;
  fmt::format_to(
      out,
      "<text x=\"{:.1f}\" y=\"{:.1f}\">{:.4g} × {:.4g} mm; the shallowest delaminated interface:</text>\n",
      margin, ly + 12.0, (x1 - x0) * 1e3, (y1 - y0) * 1e3);
  for (std::size_t i = 1; i <= map.after_ply.size(); ++i) {
    ly += row_h;
    fmt::format_to(out,
                   "<rect x=\"{:.1f}\" y=\"{:.1f}\" width=\"14\" height=\"12\" fill=\"{}\"/><text "
                   "x=\"{:.1f}\" y=\"{:.1f}\">interface after ply {}: {:.4g} mm² seen</text>\n",
                   margin, ly + 2.0, cscan_colour(static_cast<int>(i)), margin + 20.0, ly + 12.0,
                   map.after_ply[i - 1], share[i] * 1e6);
  }
  return s + "</svg>\n";
}

} // namespace plyimpact
