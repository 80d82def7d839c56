#include "plyimpact/io/deck.hpp"
#include "plyimpact/io/deck_table.hpp"

#include "plyimpact/laminate/failure_criteria.hpp"
#include "plyimpact/laminate/layup.hpp"

#include <fmt/format.h>
#include <toml++/toml.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <fstream>
#include <initializer_list>
#include <numbers>
#include <sstream>

namespace plyimpact {

std::size_t edit_distance(std::string_view a, std::string_view b) {
  std::vector<std::size_t> prev(b.size() + 1), cur(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j)
    prev[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    cur[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const bool same = std::tolower(static_cast<unsigned char>(a[i - 1])) ==
                        std::tolower(static_cast<unsigned char>(b[j - 1]));
      cur[j] = std::min({prev[j] + 1, cur[j - 1] + 1, prev[j - 1] + (same ? 0U : 1U)});
    }
    std::swap(prev, cur);
  }
  return prev[b.size()];
}

std::string_view to_string(AnalysisKind kind) {
  switch (kind) {
  case AnalysisKind::impact:
    return "impact";
  case AnalysisKind::static_:
    return "static";
  case AnalysisKind::modal:
    return "modal";
  case AnalysisKind::buckling:
    return "buckling";
  case AnalysisKind::laminate:
    return "laminate";
  case AnalysisKind::threshold:
    return "threshold";
  }
  return "?";
}

std::optional<AnalysisKind> parse_analysis_kind(std::string_view name) {
  for (const AnalysisKind k : {AnalysisKind::impact, AnalysisKind::static_, AnalysisKind::modal,
                               AnalysisKind::buckling, AnalysisKind::laminate, AnalysisKind::threshold})
    if (to_string(k) == name) return k;
  return std::nullopt;
}

namespace {

constexpr int max_elements_per_side = 2000;
constexpr long max_elements = 1'000'000;
constexpr long max_step_cap = 100'000'000;

/// Formats "FILE:LINE:COL: error: message".
[[noreturn]] void fail(const std::string& file, const toml::source_region& where,
                       const std::string& message) {
  if (where.begin.line > 0)
    throw DeckError(fmt::format("{}:{}:{}: error: {}", file, where.begin.line, where.begin.column, message));
  throw DeckError(fmt::format("{}: error: {}", file, message));
}

std::string type_name(const toml::node& n) {
  switch (n.type()) {
  case toml::node_type::table:
    return "a table";
  case toml::node_type::array:
    return "an array";
  case toml::node_type::string:
    return "a string";
  case toml::node_type::integer:
    return "an integer";
  case toml::node_type::floating_point:
    return "a number";
  case toml::node_type::boolean:
    return "a boolean";
  default:
    return "a date/time";
  }
}

std::string join(std::initializer_list<std::string_view> names) {
  std::string s;
  for (const auto n : names)
    s += (s.empty() ? "" : ", ") + std::string(n);
  return s;
}

/// Typed, located access to one TOML table; rejects unknown keys with a suggestion.
class TableReader {
public:
  TableReader(const toml::table& table, std::string path, const std::string& file)
      : table_(table), path_(std::move(path)), file_(file) {}

  [[nodiscard]] const std::string& path() const { return path_; }
  [[nodiscard]] const std::string& file() const { return file_; }
  [[nodiscard]] const toml::table& table() const { return table_; }
  [[nodiscard]] const toml::source_region& where() const { return table_.source(); }
  [[nodiscard]] bool has(std::string_view key) const { return table_.contains(key); }

  [[noreturn]] void fail_at(std::string_view key, const std::string& message) const {
    const toml::node* n = table_.get(key);
    fail(file_, n != nullptr ? n->source() : table_.source(), message);
  }

  /// Every key must be one of `allowed`; otherwise an error with the closest allowed name.
  void only(std::initializer_list<std::string_view> allowed) const {
    for (auto&& [key, node] : table_) {
      const std::string_view k = key.str();
      if (std::find(allowed.begin(), allowed.end(), k) != allowed.end()) continue;
      std::string_view best;
      std::size_t best_d = 1000;
      for (const auto a : allowed) {
        const std::size_t d = edit_distance(k, a);
        if (d < best_d) best_d = d, best = a;
      }
      std::string msg = fmt::format("unknown key '{}' in [{}]", k, path_);
      if (best_d <= std::max<std::size_t>(2, k.size() / 3))
        msg += fmt::format(" (did you mean '{}'?)", best);
      else
        msg += fmt::format(" (expected one of: {})", join(allowed));
      fail(file_, key.source().begin.line > 0 ? key.source() : node.source(), msg);
    }
  }

  [[nodiscard]] const toml::node* node(std::string_view key) const { return table_.get(key); }

  /// An error located at the table itself (for what is missing or inconsistent as a whole).
  [[noreturn]] void fail_here(const std::string& message) const { fail(file_, table_.source(), message); }

  [[nodiscard]] std::optional<double> optional_number(std::string_view key, std::string_view unit) const {
    const toml::node* n = table_.get(key);
    if (n == nullptr) return std::nullopt;
    double v = 0.0;
    if (const auto* f = n->as_floating_point())
      v = f->get();
    else if (const auto* i = n->as_integer())
      v = static_cast<double>(i->get());
    else
      fail_at(key, fmt::format("{}.{} must be a number in {}, got {}", path_, key, unit, type_name(*n)));
    if (!std::isfinite(v)) fail_at(key, fmt::format("{}.{} must be a finite number in {}", path_, key, unit));
    return v;
  }

  [[nodiscard]] double number(std::string_view key, std::string_view unit) const {
    const auto v = optional_number(key, unit);
    if (!v) fail(file_, table_.source(), fmt::format("missing key {}.{} (a number in {})", path_, key, unit));
    return *v;
  }

  [[nodiscard]] double positive(std::string_view key, std::string_view unit) const {
    const double v = number(key, unit);
    check_positive(key, v, unit);
    return v;
  }

  [[nodiscard]] std::optional<double> optional_positive(std::string_view key, std::string_view unit) const {
    const auto v = optional_number(key, unit);
    if (v) check_positive(key, *v, unit);
    return v;
  }

  void check_positive(std::string_view key, double v, std::string_view unit) const {
    if (!(v > 0.0)) fail_at(key, fmt::format("{}.{} must be positive (in {}), got {}", path_, key, unit, v));
  }

  [[nodiscard]] std::optional<long> optional_integer(std::string_view key) const {
    const toml::node* n = table_.get(key);
    if (n == nullptr) return std::nullopt;
    const auto* i = n->as_integer();
    if (i == nullptr)
      fail_at(key, fmt::format("{}.{} must be an integer, got {}", path_, key, type_name(*n)));
    return static_cast<long>(i->get());
  }

  [[nodiscard]] std::optional<std::string> optional_string(std::string_view key) const {
    const toml::node* n = table_.get(key);
    if (n == nullptr) return std::nullopt;
    const auto* s = n->as_string();
    if (s == nullptr) fail_at(key, fmt::format("{}.{} must be a string, got {}", path_, key, type_name(*n)));
    return s->get();
  }

  [[nodiscard]] std::string string(std::string_view key, std::string_view expected) const {
    auto s = optional_string(key);
    if (!s) fail(file_, table_.source(), fmt::format("missing key {}.{} ({})", path_, key, expected));
    return *s;
  }

  /// A string that must be one of `choices`.
  template <class T>
  [[nodiscard]] std::optional<T>
  optional_choice(std::string_view key, std::initializer_list<std::pair<std::string_view, T>> choices) const {
    const auto s = optional_string(key);
    if (!s) return std::nullopt;
    std::string names;
    for (const auto& [name, value] : choices) {
      if (*s == name) return value;
      names += (names.empty() ? "" : " | ") + std::string(name);
    }
    fail_at(key, fmt::format("{}.{} must be one of {}, got \"{}\"", path_, key, names, *s));
  }

  [[nodiscard]] std::optional<TableReader> optional_table(std::string_view key) const {
    const toml::node* n = table_.get(key);
    if (n == nullptr) return std::nullopt;
    const auto* t = n->as_table();
    if (t == nullptr) fail_at(key, fmt::format("{}.{} must be a table, got {}", path_, key, type_name(*n)));
    return TableReader(*t, path_.empty() ? std::string(key) : path_ + "." + std::string(key), file_);
  }

  /// A number or the string "auto" (returned as nullopt).
  [[nodiscard]] std::optional<double> positive_or_auto(std::string_view key, std::string_view unit) const {
    const toml::node* n = table_.get(key);
    if (n == nullptr) return std::nullopt;
    if (const auto* s = n->as_string()) {
      if (s->get() == "auto") return std::nullopt;
      fail_at(key, fmt::format("{}.{} must be a positive number in {} or \"auto\", got \"{}\"", path_, key,
                               unit, s->get()));
    }
    return optional_positive(key, unit);
  }

private:
  const toml::table& table_;
  std::string path_;
  const std::string& file_;
};

Material read_material(const TableReader& t, const std::string& name) {
  t.only({"E1", "E2", "G12", "G13", "G23", "nu12", "rho", "Xt", "Xc", "Yt", "Yc", "S12", "S23", "Zt", "Da"});
  Material m;
  m.name = name;
  m.E1 = t.positive("E1", "Pa");
  m.E2 = t.positive("E2", "Pa");
  m.G12 = t.positive("G12", "Pa");
  m.G13 = t.optional_positive("G13", "Pa").value_or(m.G12);
  m.G23 = t.optional_positive("G23", "Pa").value_or(m.G12);
  m.nu12 = t.number("nu12", "-");
  m.rho = t.positive("rho", "kg/m^3");
  if (!(1.0 - m.nu12 * m.nu21() > 0.0))
    t.fail_at("nu12", fmt::format("material '{}' is not physical: 1 - nu12*nu21 = {:.4g} must be positive "
                                  "(nu12 = {}, nu21 = nu12*E2/E1 = {:.4g})",
                                  name, 1.0 - m.nu12 * m.nu21(), m.nu12, m.nu21()));
  if (m.nu12 <= -1.0) t.fail_at("nu12", fmt::format("material '{}': nu12 must be greater than -1", name));
  Strengths& s = m.strength;
  s.Xt = t.optional_positive("Xt", "Pa");
  s.Xc = t.optional_positive("Xc", "Pa");
  s.Yt = t.optional_positive("Yt", "Pa");
  s.Yc = t.optional_positive("Yc", "Pa");
  s.S12 = t.optional_positive("S12", "Pa");
  s.S23 = t.optional_positive("S23", "Pa");
  s.Zt = t.optional_positive("Zt", "Pa");
  s.Da = t.optional_positive("Da", "-");
  return m;
}

std::size_t material_index(const Deck& d, const TableReader& t, std::string_view key,
                           const std::string& name) {
  for (std::size_t i = 0; i < d.materials.size(); ++i)
    if (d.materials[i].name == name) return i;
  std::string known;
  std::string best;
  std::size_t best_d = 1000;
  for (const Material& m : d.materials) {
    known += (known.empty() ? "" : ", ") + m.name;
    const std::size_t dist = edit_distance(name, m.name);
    if (dist < best_d) best_d = dist, best = m.name;
  }
  if (known.empty())
    t.fail_at(key, fmt::format("material '{}' is not defined: add a [materials.{}] table", name, name));
  if (best_d <= std::max<std::size_t>(2, name.size() / 3))
    t.fail_at(key, fmt::format("unknown material '{}' (did you mean '{}'?)", name, best));
  t.fail_at(key, fmt::format("unknown material '{}' (defined: {})", name, known));
}

void read_laminate(Deck& d, const TableReader& t, const std::string& file) {
  t.only({"material", "layup", "ply_thickness", "shear_correction", "reduced_stiffness", "override"});
  LaminateSpec spec;
  spec.material = t.string("material", "the name of a [materials.NAME] table");
  const std::size_t default_material = material_index(d, t, "material", spec.material);
  spec.layup = t.string("layup", "a stacking sequence such as \"[0_2/90_4/0_2]\"");
  spec.ply_thickness = t.positive("ply_thickness", "m");
  spec.shear_correction = t.optional_positive("shear_correction", "-").value_or(5.0 / 6.0);
  spec.reduced_stiffness = t.optional_choice<ReducedStiffnessModel>(
                                "reduced_stiffness", {{"exact", ReducedStiffnessModel::exact},
                                                      {"poisson-free", ReducedStiffnessModel::poisson_free}})
                               .value_or(ReducedStiffnessModel::exact);
  std::vector<double> angles;
  try {
    angles = parse_layup(spec.layup);
  } catch (const LayupError& e) {
    const toml::node* n = t.node("layup");
    toml::source_region where = n->source();
    // Point at the offending character: the string value starts one column after its opening quote.
    if (where.begin.line == where.end.line) where.begin.column += static_cast<toml::source_index>(e.column());
    fail(file, where, e.what());
  }
  std::vector<Ply> plies;
  plies.reserve(angles.size());
  for (const double a : angles)
    plies.push_back({a, spec.ply_thickness, default_material});

  if (const toml::node* ov = t.node("override")) {
    const toml::array* arr = ov->as_array();
    if (arr == nullptr || !arr->is_array_of_tables())
      t.fail_at("override", "laminate.override must be an array of tables: [[laminate.override]]");
    for (const toml::node& item : *arr) {
      const TableReader o(*item.as_table(), "laminate.override", file);
      o.only({"plies", "material", "thickness"});
      PlyOverride po;
      const toml::node* pn = o.node("plies");
      if (pn == nullptr || pn->as_array() == nullptr || pn->as_array()->empty())
        fail(file, item.source(), "laminate.override needs plies = [ply numbers, 1 = impacted face]");
      for (const toml::node& p : *pn->as_array()) {
        const auto* i = p.as_integer();
        if (i == nullptr || i->get() < 1 || i->get() > static_cast<std::int64_t>(plies.size()))
          fail(file, p.source(),
               fmt::format(
                   "laminate.override.plies: expected ply numbers from 1 to {} (the layup has {} plies)",
                   plies.size(), plies.size()));
        po.plies.push_back(static_cast<int>(i->get()));
      }
      po.material = o.optional_string("material");
      po.thickness = o.optional_positive("thickness", "m");
      const std::optional<std::size_t> mi =
          po.material ? std::optional<std::size_t>(material_index(d, o, "material", *po.material))
                      : std::nullopt;
      for (const int k : po.plies) {
        if (mi) plies[static_cast<std::size_t>(k - 1)].material = *mi;
        if (po.thickness) plies[static_cast<std::size_t>(k - 1)].thickness = *po.thickness;
      }
      spec.overrides.push_back(po);
    }
  }
  d.laminate.emplace(d.materials, std::move(plies), spec.shear_correction, spec.reduced_stiffness);
  d.laminate_spec = std::move(spec);
}

MeshSpec read_mesh(const TableReader& t) {
  t.only({"nx", "ny", "mass", "element"});
  MeshSpec m;
  for (const auto* key : {"nx", "ny"}) {
    const auto v = t.optional_integer(key);
    if (!v) continue;
    if (*v < 1 || *v > max_elements_per_side)
      t.fail_at(key, fmt::format("mesh.{} must be an element count from 1 to {}, got {}", key,
                                 max_elements_per_side, *v));
    (std::string_view(key) == "nx" ? m.nx : m.ny) = static_cast<int>(*v);
  }
  if (static_cast<long>(m.nx) * m.ny > max_elements)
    t.fail_here(
        fmt::format("mesh of {} x {} elements exceeds the limit of {} elements", m.nx, m.ny, max_elements));
  m.mass = t.optional_choice<MassMatrix>(
                "mass", {{"lumped", MassMatrix::lumped}, {"consistent", MassMatrix::consistent}})
               .value_or(MassMatrix::lumped);
  m.element = t.optional_choice<ElementFormulation>("element", {{"auto", ElementFormulation::automatic},
                                                                {"q9", ElementFormulation::q9},
                                                                {"mitc9", ElementFormulation::mitc9}})
                  .value_or(ElementFormulation::automatic);
  return m;
}

BoundaryConditions read_boundary(const TableReader& t) {
  t.only({"x0", "xa", "y0", "yb", "corners"});
  BoundaryConditions bc;
  for (const Edge e : {Edge::x0, Edge::xa, Edge::y0, Edge::yb}) {
    const std::string_view key = to_string(e);
    const std::string text = t.optional_string(key).value_or("ss");
    const auto r = parse_restraint(text, e);
    if (!r)
      t.fail_at(key,
                fmt::format("boundary.{} must be ss | ss-soft | clamped | free or a 5-character code of 0/1 "
                            "for (u, v, w, θx, θy) such as \"01101\", got \"{}\"",
                            key, text));
    bc.edges[static_cast<int>(e)] = *r;
  }
  if (const auto c = t.optional_string("corners")) {
    const auto r = parse_restraint(*c, Edge::x0);
    if (!r || c->size() != 5)
      t.fail_at("corners",
                fmt::format("boundary.corners must be a 5-character code of 0/1 for (u, v, w, θx, θy), "
                            "got \"{}\"",
                            *c));
    bc.corners = r;
  }
  return bc;
}

Impactor read_impactor(const TableReader& t, const std::optional<PlateGeometry>& plate) {
  t.only({"mass", "density", "radius", "E", "nu", "velocity", "x", "y"});
  Impactor imp;
  imp.radius = t.positive("radius", "m");
  const auto mass = t.optional_positive("mass", "kg");
  const auto density = t.optional_positive("density", "kg/m^3");
  if (mass && density) t.fail_at("density", "give impactor.mass or impactor.density, not both");
  if (!mass && !density)
    t.fail_here("[impactor] needs mass (kg) or density (kg/m^3, mass of the sphere of the given radius)");
  imp.mass = mass ? *mass : *density * 4.0 / 3.0 * std::numbers::pi * imp.radius * imp.radius * imp.radius;
  imp.E = t.positive("E", "Pa");
  imp.nu = t.optional_number("nu", "-").value_or(0.3);
  if (!(imp.nu > -1.0 && imp.nu < 0.5))
    t.fail_at("nu", fmt::format("impactor.nu must lie in (-1, 0.5), got {}", imp.nu));
  imp.velocity = t.positive("velocity", "m/s");
  const auto x = t.optional_number("x", "m");
  const auto y = t.optional_number("y", "m");
  if (plate) {
    imp.x = x.value_or(plate->a / 2.0);
    imp.y = y.value_or(plate->b / 2.0);
    if (!(imp.x > 0.0 && imp.x < plate->a))
      t.fail_at(x ? "x" : "radius",
                fmt::format("impact point x = {} m lies outside the plate: expected 0 < x < a = {} m", imp.x,
                            plate->a));
    if (!(imp.y > 0.0 && imp.y < plate->b))
      t.fail_at(y ? "y" : "radius",
                fmt::format("impact point y = {} m lies outside the plate: expected 0 < y < b = {} m", imp.y,
                            plate->b));
  }
  return imp;
}

ContactLawParameters read_contact(const TableReader& t) {
  t.only({"k", "unloading", "q", "beta", "alpha_cr", "load"});
  ContactLawParameters c;
  c.k = t.positive_or_auto("k", "N/m^1.5");
  c.unloading = t.optional_choice<UnloadingLaw>(
                     "unloading", {{"tan-sun", UnloadingLaw::tan_sun}, {"elastic", UnloadingLaw::elastic}})
                    .value_or(UnloadingLaw::tan_sun);
  c.q = t.optional_positive("q", "-").value_or(2.5);
  c.beta = t.optional_number("beta", "-").value_or(0.094);
  if (!(c.beta >= 0.0 && c.beta < 1.0))
    t.fail_at("beta", fmt::format("contact.beta must lie in [0, 1), got {}", c.beta));
  c.alpha_cr = t.optional_number("alpha_cr", "m").value_or(1.7e-4);
  if (!(c.alpha_cr >= 0.0)) t.fail_at("alpha_cr", "contact.alpha_cr must be zero or positive (m)");
  c.load = t.optional_choice<ContactLoad>(
                "load", {{"point", ContactLoad::point}, {"hertz-pressure", ContactLoad::hertz_pressure}})
               .value_or(ContactLoad::point);
  return c;
}

TimeStepping read_time(const TableReader& t) {
  t.only({"dt", "end", "newmark_beta", "newmark_gamma", "max_steps"});
  TimeStepping ts;
  ts.dt = t.positive_or_auto("dt", "s");
  ts.end = t.positive_or_auto("end", "s");
  ts.newmark_beta = t.optional_positive("newmark_beta", "-").value_or(0.25);
  ts.newmark_gamma = t.optional_number("newmark_gamma", "-").value_or(0.5);
  if (!(ts.newmark_gamma >= 0.5))
    t.fail_at("newmark_gamma", fmt::format("time.newmark_gamma must be at least 0.5 (no numerical energy "
                                           "growth), got {}",
                                           ts.newmark_gamma));
  if (!(ts.newmark_beta <= 0.5)) t.fail_at("newmark_beta", "time.newmark_beta must lie in (0, 0.5]");
  if (const auto m = t.optional_integer("max_steps")) {
    if (*m < 1 || *m > max_step_cap)
      t.fail_at("max_steps",
                fmt::format("time.max_steps must lie between 1 and {}, got {}", max_step_cap, *m));
    ts.max_steps = *m;
  }
  if (ts.dt && ts.end && *ts.end / *ts.dt > static_cast<double>(max_step_cap))
    t.fail_at("end", fmt::format("time.end / time.dt = {:.3g} steps: more than the limit of {} steps",
                                 *ts.end / *ts.dt, max_step_cap));
  return ts;
}

StaticLoad read_load(const TableReader& t, const std::optional<PlateGeometry>& plate) {
  t.only({"pressure", "point", "patch"});
  StaticLoad l;
  l.pressure = t.optional_number("pressure", "Pa").value_or(0.0);
  auto inside = [&](const TableReader& r, double x, double y) {
    if (plate && !(x >= 0.0 && x <= plate->a && y >= 0.0 && y <= plate->b))
      r.fail_at("x", fmt::format("load point ({}, {}) m lies outside the plate {} x {} m", x, y, plate->a,
                                 plate->b));
  };
  if (const auto p = t.optional_table("point")) {
    p->only({"x", "y", "force"});
    l.point = PointLoad{p->number("x", "m"), p->number("y", "m"), p->number("force", "N")};
    inside(*p, l.point->x, l.point->y);
  }
  if (const auto p = t.optional_table("patch")) {
    p->only({"x", "y", "dx", "dy", "force"});
    l.patch = PatchLoad{p->number("x", "m"), p->number("y", "m"), p->positive("dx", "m"),
                        p->positive("dy", "m"), p->number("force", "N")};
    inside(*p, l.patch->x, l.patch->y);
  }
  if (l.pressure == 0.0 && !l.point && !l.patch)
    t.fail_here("[load] needs pressure (Pa), point = {x, y, force} or patch = {x, y, dx, dy, force}");
  return l;
}

/// A list of times in s (each finite and >= 0), e.g. output.fields_at.
std::vector<double> time_list(const TableReader& t, std::string_view key) {
  std::vector<double> times;
  const toml::node* f = t.node(key);
  if (f == nullptr) return times;
  const toml::array* arr = f->as_array();
  if (arr == nullptr) t.fail_at(key, fmt::format("{}.{} must be an array of times in s", t.path(), key));
  for (const toml::node& item : *arr) {
    const auto v = item.value<double>();
    if (!v || !(*v >= 0.0) || !std::isfinite(*v))
      fail(t.file(), item.source(),
           fmt::format("{}.{}: expected a time in s (a number >= 0)", t.path(), key));
    times.push_back(*v);
  }
  return times;
}

/// A list of 1-based layer numbers in 1..count (plies or interfaces).
std::vector<int> layer_list(const TableReader& t, std::string_view key, int count, std::string_view what) {
  std::vector<int> layers;
  const toml::node* f = t.node(key);
  if (f == nullptr) return layers;
  const toml::array* arr = f->as_array();
  if (arr == nullptr)
    t.fail_at(key, fmt::format("{}.{} must be an array of {} numbers", t.path(), key,
                               what.substr(what.find(' ') + 1)));
  for (const toml::node& item : *arr) {
    const auto v = item.value<long>();
    if (!v || *v < 1 || (count > 0 && *v > count))
      fail(t.file(), item.source(),
           fmt::format("{}.{}: expected {} number from 1 to {}", t.path(), key, what, count));
    layers.push_back(static_cast<int>(*v));
  }
  return layers;
}

/// [output] vtk, vtk_every, vtk_at, vtk_plies, vtk_interfaces, vtk_thickness_scale.
void read_vtk_output(const TableReader& t, Deck& d) {
  VtkOutputSettings& v = d.vtk;
  if (const toml::node* n = t.node("vtk")) {
    const auto b = n->value<bool>();
    if (!b) t.fail_at("vtk", "output.vtk must be true or false");
    v.enabled = *b;
  }
  if (const auto every = t.optional_integer("vtk_every")) {
    if (*every < 1 || *every > 100'000'000)
      t.fail_at("vtk_every", fmt::format("output.vtk_every must be a positive step count, got {}", *every));
    v.every = static_cast<int>(*every);
    v.enabled = true;
  }
  v.at = time_list(t, "vtk_at");
  if (!v.at.empty()) v.enabled = true;
  if (v.enabled && v.every == 0 && v.at.empty()) v.every = VtkOutputSettings::default_every;
  const int plies = d.laminate ? static_cast<int>(d.laminate->ply_count()) : 0;
  v.plies = layer_list(t, "vtk_plies", plies, "a ply");
  v.interfaces = layer_list(t, "vtk_interfaces", plies - 1, "an interface");
  if (t.has("vtk_thickness_scale")) v.thickness_scale = t.positive("vtk_thickness_scale", "-");
}

} // namespace

namespace {

/// Top-level `nonlinear` (bool), `strain_measure` and `load_steps` (SPEC §8, docs/deck.md).
void parse_nonlinear_keys(const TableReader& top, Deck& d) {
  if (const toml::node* n = top.table().get("nonlinear")) {
    const auto* b = n->as_boolean();
    if (b == nullptr)
      top.fail_at("nonlinear", fmt::format("nonlinear must be true or false, got {}", type_name(*n)));
    d.nonlinear = b->get();
  }
  if (const auto m = top.optional_string("strain_measure")) {
    if (*m == "von-karman")
      d.nonlinear_settings.measure = StrainMeasure::von_karman;
    else if (*m == "green-lagrange")
      d.nonlinear_settings.measure = StrainMeasure::green_lagrange;
    else
      top.fail_at("strain_measure",
                  fmt::format("strain_measure must be \"von-karman\" or \"green-lagrange\", got \"{}\"", *m));
  }
  if (const auto steps = top.optional_integer("load_steps")) {
    if (*steps < 1 || *steps > 100000)
      top.fail_at("load_steps", fmt::format("load_steps must be between 1 and 100000, got {}", *steps));
    d.nonlinear_settings.load_steps = static_cast<int>(*steps);
  }
}

} // namespace

Deck parse_deck(std::string_view text, const std::string& source) {
  toml::table root;
  try {
    root = toml::parse(text, source);
  } catch (const toml::parse_error& e) {
    fail(source, e.source(), fmt::format("invalid TOML: {}", e.description()));
  }
  return parse_deck_table(root, text, source);
}

Deck parse_deck_table(const toml::table& root, std::string_view text, const std::string& source) {
  Deck d;
  d.source = source;
  d.text = std::string(text);
  const TableReader top(root, "", source);
  top.only({"analysis",  "title",   "materials", "laminate",       "plate",      "mesh",     "boundary",
            "impactor",  "contact", "time",      "load",           "modal",      "buckling", "damage",
            "threshold", "output",  "nonlinear", "strain_measure", "load_steps", "sweep"});
  d.title = top.optional_string("title").value_or("");
  parse_nonlinear_keys(top, d);
  if (const auto a = top.optional_string("analysis")) {
    const auto kind = parse_analysis_kind(*a);
    if (!kind)
      top.fail_at("analysis",
                  fmt::format("analysis must be one of impact | static | modal | buckling | laminate | "
                              "threshold, got \"{}\"",
                              *a));
    d.analysis = *kind;
  }
  if (const auto mats = top.optional_table("materials")) {
    for (auto&& [name, node] : mats->table()) {
      const auto* t = node.as_table();
      if (t == nullptr)
        fail(source, node.source(),
             fmt::format("materials.{} must be a table of material constants ([materials.{}])", name.str(),
                         name.str()));
      d.materials.push_back(read_material(TableReader(*t, "materials." + std::string(name.str()), source),
                                          std::string(name.str())));
    }
  }
  if (const auto p = top.optional_table("plate")) {
    p->only({"a", "b", "rigid"});
    d.plate = PlateGeometry{p->positive("a", "m"), p->positive("b", "m")};
    if (const toml::node* r = p->node("rigid")) {
      if (r->as_boolean() == nullptr) p->fail_at("rigid", "plate.rigid must be true or false");
      d.plate->rigid = r->as_boolean()->get();
    }
  }
  if (const auto t = top.optional_table("laminate")) read_laminate(d, *t, source);
  if (const auto t = top.optional_table("mesh")) d.mesh = read_mesh(*t);
  if (const auto t = top.optional_table("boundary")) d.boundary = read_boundary(*t);
  if (const auto t = top.optional_table("impactor")) d.impactor = read_impactor(*t, d.plate);
  if (const auto t = top.optional_table("contact")) d.contact = read_contact(*t);
  if (const auto t = top.optional_table("time")) d.time = read_time(*t);
  if (const auto t = top.optional_table("load")) d.load = read_load(*t, d.plate);
  if (const auto t = top.optional_table("modal")) {
    t->only({"count"});
    const long n = t->optional_integer("count").value_or(10);
    if (n < 1 || n > 1000)
      t->fail_at("count", fmt::format("modal.count must lie between 1 and 1000, got {}", n));
    d.modal.count = static_cast<int>(n);
  }
  if (const auto t = top.optional_table("buckling")) {
    t->only({"Nx", "Ny", "Nxy", "count"});
    BucklingSettings b;
    b.Nx = t->optional_number("Nx", "N/m").value_or(0.0);
    b.Ny = t->optional_number("Ny", "N/m").value_or(0.0);
    b.Nxy = t->optional_number("Nxy", "N/m").value_or(0.0);
    const long n = t->optional_integer("count").value_or(5);
    if (n < 1 || n > 1000)
      t->fail_at("count", fmt::format("buckling.count must lie between 1 and 1000, got {}", n));
    b.count = static_cast<int>(n);
    if (b.Nx == 0.0 && b.Ny == 0.0 && b.Nxy == 0.0)
      fail(source, t->where(),
           "[buckling] needs a non-zero reference load Nx, Ny or Nxy (N/m, compression negative)");
    d.buckling = b;
  }
  if (const auto t = top.optional_table("damage")) {
    t->only({"criteria", "every", "delamination_ply_n"});
    if (const toml::node* c = t->node("criteria")) {
      const toml::array* arr = c->as_array();
      if (arr == nullptr) t->fail_at("criteria", "damage.criteria must be an array of criterion names");
      for (const toml::node& n : *arr) {
        const auto* s = n.as_string();
        if (s == nullptr || !parse_criterion(s->get())) {
          std::string names;
          for (const Criterion k : all_criteria())
            names += (names.empty() ? "" : " | ") + std::string(to_string(k));
          fail(source, n.source(), "damage.criteria: expected a criterion name, one of " + names);
        }
        const Criterion crit = *parse_criterion(s->get());
        if (d.laminate)
          for (std::size_t k = 0; k < d.laminate->ply_count(); ++k) {
            const Material& m = d.laminate->material_of(k);
            const auto missing = missing_strengths(crit, m.strength);
            if (!missing.empty())
              fail(source, n.source(),
                   fmt::format("criterion {} needs {} of material '{}' (add it to [materials.{}])", s->get(),
                               to_string(missing.front()), m.name, m.name));
          }
        d.damage.criteria.push_back(s->get());
      }
    }
    const long every = t->optional_integer("every").value_or(1);
    if (every < 1)
      t->fail_at("every", fmt::format("damage.every must be a positive step count, got {}", every));
    d.damage.every = static_cast<int>(every);
    d.damage.delamination_ply_n_lower =
        t->optional_choice<bool>("delamination_ply_n", {{"upper", false}, {"lower", true}}).value_or(false);
  }
  if (const auto t = top.optional_table("threshold")) {
    t->only({"criterion", "tolerance", "max_velocity"});
    if (const auto c = t->optional_string("criterion")) {
      if (!parse_criterion(*c))
        t->fail_at("criterion", fmt::format("threshold.criterion: unknown criterion \"{}\"", *c));
      d.threshold.criterion = *c;
    }
    d.threshold.tolerance = t->optional_positive("tolerance", "m/s").value_or(0.01);
    d.threshold.max_velocity = t->optional_positive("max_velocity", "m/s").value_or(500.0);
  }
  if (const auto t = top.optional_table("output")) {
    t->only({"dir", "fields_at", "history_every", "probe", "vtk", "vtk_every", "vtk_at", "vtk_plies",
             "vtk_interfaces", "vtk_thickness_scale", "report_displacements_at"});
    if (const toml::node* pr = t->node("probe")) {
      const toml::array* arr = pr->as_array();
      if (arr == nullptr || !arr->is_array_of_tables())
        t->fail_at("probe", "output.probe must be an array of tables: [[output.probe]]");
      for (const toml::node& item : *arr) {
        const TableReader p(*item.as_table(), "output.probe", source);
        p.only({"name", "x", "y", "ply", "interface", "position"});
        StressProbeSpec spec;
        spec.x = p.number("x", "m");
        spec.y = p.number("y", "m");
        spec.ply = static_cast<int>(p.optional_integer("ply").value_or(0));
        spec.interface = static_cast<int>(p.optional_integer("interface").value_or(0));
        spec.position = p.optional_choice<std::string>(
                             "position", {{"average", "average"}, {"top", "top"}, {"bottom", "bottom"}})
                            .value_or("average");
        const int plies = d.laminate ? static_cast<int>(d.laminate->ply_count()) : 0;
        if ((spec.ply > 0) == (spec.interface > 0))
          p.fail_here("output.probe needs exactly one of ply = N or interface = N (1-based)");
        if (d.laminate &&
            (spec.ply > plies || spec.interface > plies - 1 || spec.ply < 0 || spec.interface < 0))
          p.fail_here(
              fmt::format("output.probe: the laminate has {} plies and {} interfaces", plies, plies - 1));
        if (d.plate && !(spec.x >= 0 && spec.x <= d.plate->a && spec.y >= 0 && spec.y <= d.plate->b))
          p.fail_at("x", fmt::format("output.probe point ({}, {}) m lies outside the plate", spec.x, spec.y));
        spec.name =
            p.optional_string("name").value_or(spec.ply > 0 ? fmt::format("ply{}_{}", spec.ply, spec.position)
                                                            : fmt::format("interface{}", spec.interface));
        d.probes.push_back(spec);
      }
    }
    d.output_dir = t->optional_string("dir").value_or("results");
    d.field_times = time_list(*t, "fields_at");
    const long every = t->optional_integer("history_every").value_or(1);
    if (every < 1)
      t->fail_at("history_every",
                 fmt::format("output.history_every must be a positive step count, got {}", every));
    d.history_every = static_cast<int>(every);
    read_vtk_output(*t, d);
    if (t->has("report_displacements_at"))
      d.report_displacements_at = t->number("report_displacements_at", "s");
  }
  return d;
}

Deck load_deck(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw DeckError(fmt::format("{}: error: cannot open the deck file", path.string()));
  std::ostringstream ss;
  ss << in.rdbuf();
  return parse_deck(ss.str(), path.string());
}

void require_sections(const Deck& d, AnalysisKind kind) {
  std::vector<std::string> missing;
  const auto need = [&](bool present, std::string_view what) {
    if (!present) missing.emplace_back(what);
  };
  need(d.laminate.has_value(), "[laminate] (with [materials.NAME])");
  if (kind != AnalysisKind::laminate) {
    need(d.plate.has_value(), "[plate]");
    need(d.boundary.has_value() || (d.plate && d.plate->rigid), "[boundary]");
  }
  if (kind == AnalysisKind::static_) need(d.load.has_value(), "[load]");
  if (kind == AnalysisKind::buckling) need(d.buckling.has_value(), "[buckling]");
  if (kind == AnalysisKind::impact || kind == AnalysisKind::threshold)
    need(d.impactor.has_value(), "[impactor]");
  if (missing.empty()) return;
  std::string list;
  for (const auto& m : missing)
    list += (list.empty() ? "" : ", ") + m;
  throw DeckError(fmt::format("{}: error: the {} analysis needs {}", d.source, to_string(kind), list));
}

} // namespace plyimpact
