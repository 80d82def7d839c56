#include "plyimpact/io/deck/deck_tables.hpp"
#include "plyimpact/laminate/ply_damage.hpp"

#include "plyimpact/analysis/impact/capabilities.hpp"
#include "plyimpact/analysis/thresholds/threshold_search.hpp"
#include "plyimpact/laminate/failure_criteria.hpp"

#include <fmt/format.h>

#include <set>
#include <string>

namespace plyimpact {

namespace {

std::string unknown_name(std::string_view what, std::string_view name,
                         const std::vector<std::string>& names) {
  std::string list;
  for (const auto& n : names)
    list += (list.empty() ? "" : " | ") + n;
  if (const auto best = closest_name(name, names))
    return fmt::format("{}: unknown criterion \"{}\" (did you mean \"{}\"?)", what, name, *best);
  return fmt::format("{}: unknown criterion \"{}\": expected one of {}", what, name, list);
}

std::vector<std::string> failure_criterion_names() {
  std::vector<std::string> names;
  for (const Criterion k : all_criteria())
    names.emplace_back(to_string(k));
  return names;
}

} // namespace

std::string unknown_criterion(std::string_view what, std::string_view name) {
  return unknown_name(what, name, failure_criterion_names());
}

std::string unknown_threshold_criterion(std::string_view what, std::string_view name) {
  std::vector<std::string> names = failure_criterion_names();
  for (const auto k : {DamageCriterion::Kind::fibre_damage, DamageCriterion::Kind::matrix_damage,
                       DamageCriterion::Kind::damage_area})
    names.emplace_back(to_string(k));
  return unknown_name(what, name, names);
}

} // namespace plyimpact

namespace plyimpact::deck_tables {

StaticLoad read_load(const TableReader& t, const std::optional<PlateGeometry>& plate, const Mesh* file_mesh) {
  t.only_keys_of("load");
  StaticLoad l;
  l.pressure = t.optional_number("pressure", "Pa").value_or(0.0);
  auto inside = [&](const TableReader& r, double x, double y) {
    if (plate && !(x >= 0.0 && x <= plate->a && y >= 0.0 && y <= plate->b))
      r.fail_at("x", fmt::format("load point ({}, {}) m lies outside the plate {} x {} m", x, y, plate->a,
                                 plate->b));
    if (file_mesh != nullptr && !file_mesh->locate(x, y)) {
      const BoundingBox& box = file_mesh->bounds();
      r.fail_at("x",
                fmt::format("load point ({}, {}) m lies outside the mesh (x from {} to {} m, y from {} to "
                            "{} m)",
                            x, y, box.x_min, box.x_max, box.y_min, box.y_max));
    }
  };
  if (const auto p = t.optional_table("point")) {
    p->only_keys_of("load.point");
    l.point = PointLoad{p->number("x", "m"), p->number("y", "m"), p->number("force", "N")};
    inside(*p, l.point->x, l.point->y);
  }
  if (const auto p = t.optional_table("patch")) {
    p->only_keys_of("load.patch");
    l.patch = PatchLoad{p->number("x", "m"), p->number("y", "m"), p->positive("dx", "m"),
                        p->positive("dy", "m"), p->number("force", "N")};
    inside(*p, l.patch->x, l.patch->y);
  }
  if (l.pressure == 0.0 && !l.point && !l.patch)
    t.fail_here("[load] needs pressure (Pa), point = {x, y, force} or patch = {x, y, dx, dy, force}");
  return l;
}

ModalSettings read_modal(const TableReader& t) {
  ModalSettings m;
  t.only_keys_of("modal");
  const long n = t.optional_integer("count").value_or(10);
  if (n < 1 || n > 1000)
    t.fail_at("count", fmt::format("modal.count must lie between 1 and 1000, got {}", n));
  m.count = static_cast<int>(n);
  return m;
}

BucklingSettings read_buckling(const TableReader& t) {
  t.only_keys_of("buckling");
  BucklingSettings b;
  b.Nx = t.optional_number("Nx", "N/m").value_or(0.0);
  b.Ny = t.optional_number("Ny", "N/m").value_or(0.0);
  b.Nxy = t.optional_number("Nxy", "N/m").value_or(0.0);
  const long n = t.optional_integer("count").value_or(5);
  if (n < 1 || n > 1000)
    t.fail_at("count", fmt::format("buckling.count must lie between 1 and 1000, got {}", n));
  b.count = static_cast<int>(n);
  if (b.Nx == 0.0 && b.Ny == 0.0 && b.Nxy == 0.0)
    fail(t.file(), t.where(),
         "[buckling] needs a non-zero reference load Nx, Ny or Nxy (N/m, compression negative)");
  return b;
}

namespace {

/// What the progressive damage law needs of the deck, checked where [damage] asks for it (a deck error
/// with its line, before any run): every ply's strengths and toughnesses and the exact reduced stiffness
/// (the element: the restrictions of analysis/impact/capabilities.hpp, deck.cpp).
void require_progressive_damage_data(const TableReader& t, const Deck& d, const PlyDamageOptions& law) {
  std::set<std::string> checked;
  for (const Laminate& lam : all_laminates(d)) {
    if (lam.stiffness_model() != ReducedStiffnessModel::exact)
      t.fail_at("model", "damage.model = \"progressive\" needs the exact reduced stiffness (1.3): leave out "
                         "laminate.reduced_stiffness or set it to \"exact\" (the damage law degrades it)");
    for (std::size_t k = 0; k < lam.ply_count(); ++k) {
      const Material& m = lam.material_of(k);
      if (!checked.insert(m.name).second) continue; // each material once
      try {
        (void)make_ply_law(m, law);
      } catch (const std::invalid_argument& e) {
        t.fail_at(
            "model",
            fmt::format("damage.model = \"progressive\": {}: add it to [materials.{}] (strengths "
                        "in Pa, fracture toughnesses G_ft, G_fc, G_mt, G_mc (ply_law = \"hashin\") or "
                        "G_ft, G_fc, G_mt, G_ms and bk_exponent (ply_law = \"fracture-plane\") in J/m^2; "
                        "docs/progressive_damage.md lists published values)",
                        e.what(), m.name));
      }
    }
  }
}

} // namespace

std::optional<Integrator> optional_law_integrator(const TableReader& t) {
  return t.optional_choice<Integrator>("integration", {{"implicit", Integrator::implicit},
                                                       {"lagged", Integrator::lagged},
                                                       {"explicit", Integrator::central_difference}});
}

DamageSettings read_damage(const TableReader& t, Deck& d) {
  DamageSettings damage;
  t.only_keys_of("damage");
  const bool progressive =
      t.optional_choice<bool>("model", {{"onset", false}, {"progressive", true}}).value_or(false);
  if (progressive) {
    ProgressiveDamageSettings p;
    p.law.law = t.optional_choice<PlyLawKind>("ply_law", {{"hashin", PlyLawKind::hashin},
                                                          {"fracture-plane", PlyLawKind::fracture_plane}})
                    .value_or(PlyLawKind::hashin);
    p.law.viscosity = t.optional_number("viscosity", "s").value_or(0.0);
    if (p.law.viscosity < 0.0)
      t.fail_at("viscosity", fmt::format("damage.viscosity is a time constant and must be >= 0 s, got {}",
                                         p.law.viscosity));
    p.law.alpha = t.optional_number("alpha", "-").value_or(0.0);
    if (!(p.law.alpha >= 0.0 && p.law.alpha <= 1.0))
      t.fail_at("alpha", fmt::format("damage.alpha weighs shear in Hashin's fibre-tension mode and must lie "
                                     "in [0, 1], got {}",
                                     p.law.alpha));
    damage.refactor_tolerance = t.optional_positive("refactor_tolerance", "-");
    p.area_threshold = t.optional_positive("area_threshold", "-").value_or(p.area_threshold);
    if (p.area_threshold > 1.0)
      t.fail_at("area_threshold", fmt::format("damage.area_threshold is a damage variable in (0, 1], got {}",
                                              p.area_threshold));
    p.reduce_strengths_above_band_limit =
        t.optional_choice<bool>("oversize", {{"error", false}, {"reduce-strength", true}}).value_or(false);
    // [time] integration = "explicit" makes the plies' step explicit too (the plate steps with one).
    const Integrator plies = optional_law_integrator(t).value_or(
        d.time.integration == TimeScheme::central_difference ? Integrator::central_difference
                                                             : Integrator::implicit);
    try {
      (void)resolve_integrator(ModelKind{false, d.nonlinear, true, false}, d.time.integration, plies,
                               std::nullopt);
    } catch (const std::invalid_argument& e) {
      t.fail_at("integration", e.what());
    }
    d.time.laws = plies;
    require_progressive_damage_data(t, d, p.law);
    damage.progressive = p;
  } else {
    for (const char* key :
         {"viscosity", "alpha", "refactor_tolerance", "area_threshold", "oversize", "integration", "ply_law"})
      if (t.node(key) != nullptr)
        t.fail_at(key, fmt::format("damage.{} belongs to the progressive damage model: add "
                                   "model = \"progressive\" to [damage]",
                                   key));
  }
  if (const toml::node* c = t.node("criteria")) {
    const toml::array* arr = c->as_array();
    if (arr == nullptr) t.fail_at("criteria", "damage.criteria must be an array of criterion names");
    for (const toml::node& n : *arr) {
      const auto* s = n.as_string();
      if (s == nullptr)
        fail(t.file(), n.source(), "damage.criteria: expected criterion names (strings) such as \"tsai-wu\"");
      if (!parse_criterion(s->get()))
        fail(t.file(), n.source(), unknown_criterion("damage.criteria", s->get()));
      const Criterion crit = *parse_criterion(s->get());
      if (d.laminate)
        for (std::size_t k = 0; k < d.laminate->ply_count(); ++k) {
          const Material& m = d.laminate->material_of(k);
          const auto missing = missing_strengths(crit, m.strength);
          if (!missing.empty())
            fail(t.file(), n.source(),
                 fmt::format("criterion {} needs {} of material '{}' (add it to [materials.{}])", s->get(),
                             to_string(missing.front()), m.name, m.name));
        }
      damage.criteria.push_back(s->get());
    }
  }
  const long every = t.optional_integer("every").value_or(1);
  if (every < 1) t.fail_at("every", fmt::format("damage.every must be a positive step count, got {}", every));
  damage.every = static_cast<int>(every);
  damage.delamination_ply_n_lower =
      t.optional_choice<bool>("delamination_ply_n", {{"upper", false}, {"lower", true}}).value_or(false);
  return damage;
}

ThresholdSettings read_threshold(const TableReader& t, const Deck& d) {
  ThresholdSettings threshold;
  t.only_keys_of("threshold");
  if (const auto c = t.optional_string("criterion")) {
    const auto damage = parse_damage_criterion(*c);
    if (!damage && !parse_criterion(*c))
      t.fail_at("criterion", unknown_threshold_criterion("threshold.criterion", *c));
    if (damage && !d.damage.progressive)
      t.fail_at("criterion", fmt::format("threshold.criterion = \"{}\" looks for ply damage, which only the "
                                         "progressive damage model computes: set [damage] model = "
                                         "\"progressive\" (and the materials' G_ft, G_fc, G_mt, G_mc)",
                                         *c));
    threshold.criterion = *c;
  }
  threshold.tolerance = t.optional_positive("tolerance", "m/s").value_or(0.01);
  threshold.max_velocity = t.optional_positive("max_velocity", "m/s").value_or(500.0);
  threshold.damage_area = t.optional_positive("damage_area", "m^2");
  const bool area_criterion =
      parse_damage_criterion(threshold.criterion) == DamageCriterion::Kind::damage_area;
  if (area_criterion && !threshold.damage_area)
    t.fail_at("criterion",
              fmt::format("threshold.criterion = \"damage-area\" needs threshold.damage_area, the "
                          "projected damaged area to exceed (in {})",
                          t.deck_unit("m^2")));
  if (threshold.damage_area && !threshold.criterion.empty() && !area_criterion)
    t.fail_at("damage_area", fmt::format("threshold.damage_area is the limit of criterion = \"damage-area\", "
                                         "but the criterion is \"{}\": remove damage_area or set "
                                         "criterion = \"damage-area\"",
                                         threshold.criterion));
  return threshold;
}

} // namespace plyimpact::deck_tables
