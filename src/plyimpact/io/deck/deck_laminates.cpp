#include "plyimpact/io/deck/deck_tables.hpp"

#include "plyimpact/laminate/layup.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <tuple>

namespace plyimpact::deck_tables {

namespace {

/// reference_direction = [x, y, z]: the layup's 0° direction in the plate's (the mesh's) axes, which must
/// lie in its plane; its angle from x toward y [deg] (0 without the key).
double read_reference_angle(const TableReader& t) {
  const toml::node* n = t.node("reference_direction");
  if (n == nullptr) return 0.0;
  const std::string what =
      fmt::format("{}.reference_direction must be a vector [x, y, z] in the plate's axes "
                  "(the layup's 0° direction, e.g. [1, 0, 0] for x)",
                  t.path());
  const toml::array* arr = n->as_array();
  if (arr == nullptr || arr->size() != 3) t.fail_at("reference_direction", what);
  std::array<double, 3> d{};
  for (std::size_t i = 0; i < 3; ++i) {
    const auto v = (*arr)[i].value<double>();
    if (!v || !std::isfinite(*v)) t.fail_at("reference_direction", what);
    d[i] = *v;
  }
  const double length = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
  if (!(length > 0.0)) t.fail_at("reference_direction", what + ", got the zero vector");
  if (std::abs(d[2]) > 1e-9 * length)
    t.fail_at(
        "reference_direction",
        fmt::format("{}.reference_direction = [{}, {}, {}] leaves the plate's plane (z = 0): the fibres lie "
                    "in the plate, so give z = 0",
                    t.path(), d[0], d[1], d[2]));
  return std::atan2(d[1], d[0]) * 180.0 / std::numbers::pi;
}

} // namespace

NamedLaminate read_laminate(const std::vector<Material>& materials, const TableReader& t, std::string name) {
  const std::string& file = t.file();
  t.only_keys_of("laminate");
  LaminateSpec spec;
  spec.material = t.string("material", "the name of a [materials.NAME] table");
  const std::size_t default_material = material_index(materials, t, "material", spec.material);
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
  spec.reference_angle = read_reference_angle(t);
  std::vector<Ply> plies;
  plies.reserve(angles.size());
  for (const double a : angles)
    plies.push_back({a + spec.reference_angle, spec.ply_thickness, default_material});

  if (const toml::node* ov = t.node("override")) {
    const toml::array* arr = ov->as_array();
    if (arr == nullptr || !arr->is_array_of_tables())
      t.fail_at("override",
                fmt::format("{0}.override must be an array of tables: [[{0}.override]]", t.path()));
    for (const toml::node& item : *arr) {
      const TableReader o = t.nested(*item.as_table(), t.path() + ".override");
      o.only_keys_of("laminate.override");
      PlyOverride po;
      const toml::node* pn = o.node("plies");
      if (pn == nullptr || pn->as_array() == nullptr || pn->as_array()->empty())
        fail(file, item.source(),
             fmt::format("{}.override needs plies = [ply numbers, 1 = impacted face]", t.path()));
      for (const toml::node& p : *pn->as_array()) {
        const auto* i = p.as_integer();
        if (i == nullptr || i->get() < 1 || i->get() > static_cast<std::int64_t>(plies.size()))
          fail(file, p.source(),
               fmt::format("{}.override.plies: expected ply numbers from 1 to {} (the layup has {} plies)",
                           t.path(), plies.size(), plies.size()));
        po.plies.push_back(static_cast<int>(i->get()));
      }
      po.material = o.optional_string("material");
      po.thickness = o.optional_positive("thickness", "m");
      const std::optional<std::size_t> mi =
          po.material ? std::optional<std::size_t>(material_index(materials, o, "material", *po.material))
                      : std::nullopt;
      for (const int k : po.plies) {
        if (mi) plies[static_cast<std::size_t>(k - 1)].material = *mi;
        if (po.thickness) plies[static_cast<std::size_t>(k - 1)].thickness = *po.thickness;
      }
      spec.overrides.push_back(po);
    }
  }
  Laminate laminate(materials, std::move(plies), spec.shear_correction, spec.reduced_stiffness);
  return {std::move(name), std::move(spec), std::move(laminate)};
}

std::vector<Region> read_regions(const Deck& d, const TableReader& top) {
  std::vector<Region> regions;
  const toml::node* node = top.node("region");
  if (node == nullptr) return regions;
  const toml::array* arr = node->as_array();
  if (arr == nullptr || !arr->is_array_of_tables())
    top.fail_at(
        "region",
        "region must be an array of tables: [[region]] with laminate = \"NAME\", x = [x0, x1], y = [y0, y1]");
  for (const toml::node& item : *arr) {
    const TableReader t = top.nested(*item.as_table(), "region");
    t.only_keys_of("region");
    Region r;
    r.name = t.string("laminate", "the name of a [laminates.NAME] table");
    const auto it = std::find_if(d.laminates.begin(), d.laminates.end(),
                                 [&](const NamedLaminate& l) { return l.name == r.name; });
    if (it == d.laminates.end()) {
      std::string known;
      for (const NamedLaminate& l : d.laminates)
        known += (known.empty() ? "" : ", ") + l.name;
      t.fail_at("laminate", fmt::format("region.laminate = \"{}\": no [laminates.{}] table (defined: {})",
                                        r.name, r.name, known.empty() ? "none" : known));
    }
    r.laminate = 1 + static_cast<int>(it - d.laminates.begin());
    const auto bounds = [&](std::string_view key, double length) -> std::pair<double, double> {
      const toml::node* b = t.node(key);
      const toml::array* pair = b != nullptr ? b->as_array() : nullptr;
      const auto bound = [&](std::size_t i) -> std::optional<double> {
        const auto v = pair != nullptr && pair->size() == 2 ? (*pair)[i].value<double>() : std::nullopt;
        return v ? std::optional<double>(t.to_si(*v, "m")) : std::nullopt;
      };
      const auto lo = bound(0);
      const auto hi = bound(1);
      if (!lo || !hi || !(*lo < *hi))
        t.fail_here(fmt::format("region.{} must be [{}0, {}1] in {} with {}0 < {}1", key, key, key,
                                t.deck_unit("m"), key, key));
      if (*lo < 0.0 || *hi > length * (1.0 + 1e-12))
        t.fail_at(key, fmt::format("region.{} = [{}, {}] m reaches outside the plate (0 to {} m)", key, *lo,
                                   *hi, length));
      return {*lo, *hi};
    };
    const double a = d.plate ? d.plate->a : INFINITY, b = d.plate ? d.plate->b : INFINITY;
    std::tie(r.x_min, r.x_max) = bounds("x", a);
    std::tie(r.y_min, r.y_max) = bounds("y", b);
    regions.push_back(std::move(r));
  }
  return regions;
}

} // namespace plyimpact::deck_tables
