#include "plyimpact/io/deck/deck_tables.hpp"

#include "plyimpact/analysis/fields/damage_zone.hpp"
#include "plyimpact/io/mesh/gmsh_mesh.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <filesystem>

namespace plyimpact::deck_tables {

PlateGeometry read_plate(const TableReader& t) {
  t.only_keys_of("plate");
  PlateGeometry plate{t.positive("a", "m"), t.positive("b", "m")};
  if (const toml::node* r = t.node("rigid")) {
    if (r->as_boolean() == nullptr) t.fail_at("rigid", "plate.rigid must be true or false");
    plate.rigid = r->as_boolean()->get();
  }
  return plate;
}

namespace {

/// mesh.impact_offset = [ox, oy]: where the impact point lies in its element, fractions in [0, 1).
std::array<double, 2> read_impact_offset(const TableReader& t) {
  const toml::array* arr = t.node("impact_offset")->as_array();
  std::array<double, 2> offset{};
  if (arr == nullptr || arr->size() != 2)
    t.fail_at("impact_offset",
              "mesh.impact_offset must be two numbers [ox, oy] (fractions of the element "
              "under the impact point: [0.5, 0.5] = its centre node, [0, 0] = a corner node)");
  for (std::size_t i = 0; i < 2; ++i) {
    const auto v = (*arr)[i].value<double>();
    if (!v || !(*v >= 0.0 && *v < 1.0))
      t.fail_at("impact_offset", "mesh.impact_offset: each fraction must be a number from 0 (inclusive) to 1 "
                                 "(exclusive)");
    offset[i] = *v;
  }
  return offset;
}

} // namespace

namespace {

/// The smallest element a deck may ask for [m]: a hundredth of the thinnest plies made (0.03 mm was the
/// thinnest mesh of a plate model of a laminate). Below it the sizes were absurd, and the run was not merely
/// slow: a rig with size_at_impact = 1e-7 m factored its matrix for ever (issue 77).
constexpr double min_element_size = 1e-5;

/// Refuses mesh.size_at_impact and mesh.max_size below min_element_size.
void require_element_sizes(const TableReader& t, const std::optional<double>& at_impact,
                           const std::optional<double>& max_size) {
  for (const auto& [key, value] : {std::pair{"size_at_impact", at_impact}, std::pair{"max_size", max_size}})
    if (value && *value < min_element_size)
      t.fail_at(key,
                fmt::format("mesh.{} = {:g} m is below {:g} m, a hundredth of the thinnest plies made: no "
                            "plate element is that small (a unit slip? the deck is in m)",
                            key, *value, min_element_size));
}

/// mesh.growth, the size ratio of neighbouring elements (1 … 3), of a graded or a gmsh mesh.
std::optional<double> read_growth(const TableReader& t) {
  const auto r = t.optional_number("growth", "-");
  if (r && !(*r >= 1.0 && *r <= 3.0))
    t.fail_at("growth", fmt::format("mesh.growth must lie between 1 and 3 (size ratio of neighbouring "
                                    "elements), got {}",
                                    *r));
  return r;
}

} // namespace

MeshSpec read_mesh(const TableReader& t) {
  t.only_keys_of("mesh");
  MeshSpec m;
  if (t.has("file") && t.has("geo"))
    t.fail_at("geo", "give mesh.file (a mesh made by gmsh) or mesh.geo (a geometry to mesh), not both");
  if (t.has("file")) {
    for (const char* key : {"nx", "ny", "grading", "size_at_impact", "growth", "max_size", "impact_offset"})
      if (t.has(key))
        t.fail_at(key, fmt::format("mesh.{} shapes the structured rectangle, but mesh.file gives the mesh: "
                                   "leave out mesh.{} (refine in gmsh)",
                                   key, key));
  }
  if (t.has("geo")) {
    for (const char* key : {"nx", "ny", "grading", "impact_offset"})
      if (t.has(key))
        t.fail_at(key, fmt::format("mesh.{} shapes the structured rectangle, but mesh.geo gives the plate: "
                                   "leave out mesh.{} (size the elements with mesh.size_at_impact, growth "
                                   "and max_size)",
                                   key, key));
    return m; // the size keys are read with the geometry (read_mesh_file)
  }
  bool counts = false;
  for (const auto* key : {"nx", "ny"}) {
    const auto v = t.optional_integer(key);
    if (!v) continue;
    if (*v < 1 || *v > max_elements_per_side)
      t.fail_at(key, fmt::format("mesh.{} must be an element count from 1 to {}, got {}", key,
                                 max_elements_per_side, *v));
    (std::string_view(key) == "nx" ? m.nx : m.ny) = static_cast<int>(*v);
    counts = true;
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
  // Graded toward the impact point unless the element counts are given (docs/deck.md).
  const bool graded = t.optional_choice<bool>("grading", {{"auto", true}, {"none", false}})
                          .value_or(!counts && !t.has("file"));
  if (graded && counts)
    t.fail_at("grading", "mesh.grading = \"auto\" grades the mesh toward the impact point: leave out mesh.nx "
                         "and mesh.ny, or set grading = \"none\" for a uniform nx x ny mesh");
  const bool grading_keys =
      t.has("size_at_impact") || t.has("growth") || t.has("max_size") || t.has("impact_offset");
  if (!graded && grading_keys)
    t.fail_here("mesh.size_at_impact, growth, max_size and impact_offset shape a graded mesh: leave out "
                "mesh.nx and mesh.ny "
                "(or grading = \"none\")");
  if (graded) {
    MeshGrading g;
    g.size_at_impact = t.positive_or_auto("size_at_impact", "m");
    g.max_size = t.positive_or_auto("max_size", "m");
    if (const auto r = read_growth(t)) g.growth = *r;
    if (t.has("impact_offset")) g.impact_offset = read_impact_offset(t);
    require_element_sizes(t, g.size_at_impact, g.max_size);
    if (g.size_at_impact && g.max_size && *g.max_size < *g.size_at_impact)
      t.fail_at("max_size", "mesh.max_size must not be smaller than mesh.size_at_impact");
    m.grading = g;
  }
  return m;
}

GeometryMeshing read_geometry_meshing(const TableReader& t, const std::optional<Eigen::Vector2d>& refine_at) {
  GeometryMeshing how;
  how.refine_at = refine_at;
  how.size_at_point = t.optional_positive("size_at_impact", "m");
  how.max_size = t.optional_positive("max_size", "m");
  if (const auto r = read_growth(t)) {
    if (!how.size_at_point)
      t.fail_at("growth", "mesh.growth grades the elements away from mesh.size_at_impact: give it too");
    how.growth = *r;
  }
  require_element_sizes(t, how.size_at_point, how.max_size);
  if (how.size_at_point && how.max_size && *how.max_size < *how.size_at_point)
    t.fail_at("max_size", "mesh.max_size must not be smaller than mesh.size_at_impact");
  return how;
}

void read_rig(const TableReader& top, const TableReader& t, const std::optional<TableReader>& mesh,
              const std::optional<Eigen::Vector2d>& refine_at, Deck& d) {
  t.only_keys_of("rig");
  RigSpec spec;
  const auto kind = t.optional_choice<RigKind>("preset", {{"astm-d7136", RigKind::astm_d7136},
                                                          {"aitm-1-0010", RigKind::aitm_1_0010},
                                                          {"circular", RigKind::circular}});
  if (!kind) t.fail_here("[rig] needs preset = \"astm-d7136\", \"aitm-1-0010\" or \"circular\"");
  spec.kind = *kind;
  if (spec.kind == RigKind::circular) {
    spec.diameter = t.positive("diameter", "m");
  } else if (t.has("diameter")) {
    t.fail_at("diameter",
              fmt::format("rig.diameter sizes the circular rig; the {} rig's window is 125 x 75 mm",
                          to_string(spec.kind)));
  }
  if (d.plate) top.fail_at("plate", "[rig] gives the plate: leave out [plate]");
  if (top.has("boundary"))
    top.fail_at("boundary", "[rig] sets the supports (docs/mesh.md, test rigs): leave out [boundary]");
  spec.meshing = rig_meshing(spec);
  if (mesh) {
    for (const char* key : {"nx", "ny", "grading", "impact_offset"})
      if (mesh->has(key))
        mesh->fail_at(key, fmt::format("mesh.{} shapes the structured rectangle, but [rig] gives the plate: "
                                       "leave out mesh.{} (size the elements with mesh.size_at_impact, "
                                       "growth and max_size)",
                                       key, key));
    if (mesh->has("size_at_impact"))
      spec.meshing = read_geometry_meshing(*mesh, std::nullopt);
    else if (mesh->has("max_size") || mesh->has("growth"))
      mesh->fail_here("[rig] with mesh.max_size or growth needs mesh.size_at_impact too");
  }
  spec.meshing.refine_at = refine_at;
  if (d.mesh) d.mesh->grading.reset(); // the size keys grade gmsh's mesh, not a structured one
  try {
    Rig rig = build_rig(spec, d.analysis == AnalysisKind::static_);
    d.file_mesh = std::make_shared<const Mesh>(std::move(rig.mesh));
    d.boundary = std::move(rig.boundary);
    d.rig_description = std::move(rig.description);
    if (rig.impactor_radius > 0.0) d.impactor_defaults.radius = rig.impactor_radius;
    if (rig.energy_per_thickness && d.laminate) {
      d.impactor_defaults.energy = *rig.energy_per_thickness * d.laminate->thickness();
      // The standard's energy is named only where it is the one that runs.
      const auto impactor = top.optional_table("impactor");
      if (impactor && gives_impact_speed(*impactor))
        d.rig_description += "; impact energy from [impactor] (the standard's C_E x h not used)";
      else
        d.rig_description += fmt::format(
            "; impact energy {:.4g} J/mm x {:.4g} mm = {:.4g} J (the standard's)",
            *rig.energy_per_thickness * 1e-3, d.laminate->thickness() * 1e3, *d.impactor_defaults.energy);
    }
  } catch (const MeshFileError& e) {
    t.fail_at("preset", fmt::format("rig.preset: gmsh could not mesh the rig: {}", e.what()));
  }
  d.rig = spec;
  if (mesh && mesh->has("size_at_impact")) d.geo_meshing = spec.meshing; // the user's sizes, to check
}

namespace {

/// The largest √(element area) of the elements whose centre lies within `radius` of `at` [m].
double largest_side_within(const Mesh& mesh, const Eigen::Vector2d& at, double radius) {
  double largest = 0.0;
  for (int e = 0; e < mesh.element_count(); ++e)
    if ((mesh.map(e, 0.0, 0.0) - at).norm() <= radius)
      largest = std::max(largest, std::sqrt(mesh.element_area(e)));
  return largest;
}

} // namespace

void size_rig_for_damage(Deck& d) {
  if (!d.rig || d.geo_meshing || d.analysis != AnalysisKind::impact || !d.laminate || !d.file_mesh) return;
  const std::optional<DamageElementSize> need =
      damage_element_size(*d.laminate, d.damage.progressive, d.delamination);
  if (!need || need->size >= d.rig->meshing.size_at_point.value_or(INFINITY)) return;
  RigSpec spec = *d.rig;
  const Eigen::Vector2d at = spec.meshing.refine_at.value_or(d.file_mesh->bounds().centre());
  spec.meshing.size_at_point = need->size;
  spec.meshing.uniform_radius = damage_zone_radius(*d.laminate);
  Rig rig = build_rig(spec, false);
  // gmsh's quadrilaterals, paired from triangles of the field's size, come out somewhat larger than
  // it: the field is scaled by what the zone's elements measure, at most three times.
  const double inner = spec.meshing.uniform_radius - need->size;
  for (int again = 0; again < 3; ++again) {
    const double measured = largest_side_within(rig.mesh, at, inner);
    if (measured <= need->size) break;
    spec.meshing.size_at_point = *spec.meshing.size_at_point * need->size / measured;
    rig = build_rig(spec, false);
  }
  const std::string before = fmt::format("; {} elements", d.file_mesh->element_count());
  const std::string after = fmt::format(
      "; {} elements, at most {:.3g} mm (the square root of their area) within {:.3g} mm of the impact point "
      "for the damage: {}, less 10 % (docs/mesh.md, \"Meshes for damage\")",
      rig.mesh.element_count(), largest_side_within(rig.mesh, at, inner) * 1e3,
      spec.meshing.uniform_radius * 1e3, need->reason);
  if (const std::size_t p = d.rig_description.find(before); p != std::string::npos)
    d.rig_description.replace(p, before.size(), after);
  d.file_mesh = std::make_shared<const Mesh>(std::move(rig.mesh));
  d.rig = spec;
}

std::shared_ptr<const Mesh> read_mesh_file(const TableReader& t, std::string& written,
                                           const std::optional<Eigen::Vector2d>& refine_at,
                                           std::optional<GeometryMeshing>& meshing) {
  const bool geo = t.has("geo");
  const std::string_view key = geo ? "geo" : "file";
  const auto name = t.optional_string(key);
  if (!name) return nullptr;
  written = *name;
  std::filesystem::path path(*name);
  if (path.is_relative()) path = std::filesystem::path(t.file()).parent_path() / path; // beside the deck
  if (path.extension() != (geo ? ".geo" : ".msh"))
    t.fail_at(key, geo ? fmt::format("mesh.geo must be a gmsh geometry script (.geo), got \"{}\"", *name)
                       : fmt::format("mesh.file must be a gmsh mesh (.msh), got \"{}\"", *name));
  if (geo) meshing = read_geometry_meshing(t, refine_at);
  try {
    return std::make_shared<const Mesh>(geo ? mesh_gmsh_geometry(path, *meshing) : read_gmsh_mesh(path));
  } catch (const MeshFileError& e) {
    t.fail_at(key, fmt::format("mesh.{} = \"{}\": {}", key, *name, e.what()));
  }
}

namespace {

/// [boundary] of the structured rectangle: x0, xa, y0, yb (ss unless given) and corners.
BoundaryConditions read_rectangle_boundary(const TableReader& t) {
  t.only_keys_of("boundary");
  BoundaryConditions bc;
  for (const Edge e : {Edge::x0, Edge::xa, Edge::y0, Edge::yb}) {
    const std::string_view key = to_string(e);
    const std::string text = t.optional_string(key).value_or("ss");
    const auto r = parse_restraint(text, e);
    if (!r)
      t.fail_at(key,
                fmt::format("boundary.{} must be ss | ss-soft | clamped | free | unilateral or a 5-character "
                            "code of 0/1 for (u, v, w, θx, θy) such as \"01101\", got \"{}\"",
                            key, text));
    bc.set(key, text);
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

/// [boundary] of a mesh from a file: one key per named set of the mesh (gmsh's physical groups); the
/// sets left out are free.
BoundaryConditions read_mesh_boundary(const TableReader& t, const Mesh& mesh) {
  const std::vector<std::string> names = mesh.node_set_names();
  BoundaryConditions bc;
  for (auto&& [key, node] : t.table()) {
    const std::string name(key.str());
    if (std::find(names.begin(), names.end(), name) == names.end()) {
      const auto best = closest_name(name, names);
      std::string known;
      for (const std::string& n : names)
        known += (known.empty() ? "" : ", ") + n;
      t.fail_at(name,
                fmt::format("boundary.{}: the mesh has no physical group \"{}\"{} (its groups: {})", name,
                            name, best ? fmt::format(" (did you mean \"{}\"?)", *best) : "", known));
    }
    const auto text = t.optional_string(name);
    if (!is_restraint_type(*text))
      t.fail_at(name,
                fmt::format("boundary.{} must be ss | ss-soft | clamped | free | unilateral or a 5-character "
                            "code of 0/1 for (u, v, w, θx, θy), got \"{}\"",
                            name, *text));
    try {
      (void)resolve_restraint(mesh, SetRestraint{name, *text});
    } catch (const std::exception& e) {
      t.fail_at(name, fmt::format("boundary.{} = \"{}\": {}", name, *text, e.what()));
    }
    bc.set(name, *text);
  }
  return bc;
}

} // namespace

BoundaryConditions read_boundary(const TableReader& t, const Mesh* file_mesh) {
  return file_mesh != nullptr ? read_mesh_boundary(t, *file_mesh) : read_rectangle_boundary(t);
}

} // namespace plyimpact::deck_tables
