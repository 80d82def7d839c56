// The deck parser (docs/deck.md): the top-level table and the order in which the tables are read;
// each table has its reader in deck_*.cpp (deck_tables.hpp).
#include "plyimpact/io/deck/deck.hpp"
#include "plyimpact/analysis/impact/capabilities.hpp"
#include "plyimpact/io/deck/deck_plausibility.hpp"
#include "plyimpact/io/deck/deck_table.hpp"
#include "plyimpact/io/deck/deck_tables.hpp"

#include <fmt/format.h>
#include <toml++/toml.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace plyimpact {

using namespace deck_tables;

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

std::vector<Laminate> all_laminates(const Deck& deck) {
  std::vector<Laminate> all;
  if (deck.laminate) all.push_back(*deck.laminate);
  for (const NamedLaminate& l : deck.laminates)
    all.push_back(l.laminate);
  return all;
}

Deck parse_deck(std::string_view text, const std::string& source) {
  toml::table root;
  try {
    root = toml::parse(text, source);
  } catch (const toml::parse_error& e) {
    fail(source, e.source(), fmt::format("invalid TOML: {}", e.description()));
  }
  return parse_deck_table(root, text, source);
}

namespace {

void read_materials(const TableReader& top, Deck& d) {
  const auto mats = top.optional_table("materials");
  if (!mats) return;
  for (auto&& [name, node] : mats->table()) {
    const auto* t = node.as_table();
    if (t == nullptr)
      fail(top.file(), node.source(),
           fmt::format("materials.{} must be a table of material constants ([materials.{}])", name.str(),
                       name.str()));
    const TableReader material = top.nested(*t, "materials." + std::string(name.str()));
    d.materials.push_back(read_material(material, std::string(name.str())));
    if (const auto card = material.optional_string("library"))
      d.material_cards.emplace_back(std::string(name.str()), *card);
  }
}

void read_laminates(const TableReader& top, Deck& d) {
  if (const auto t = top.optional_table("laminate")) {
    NamedLaminate base = read_laminate(d.materials, *t, "laminate");
    d.laminate = std::move(base.laminate);
    d.laminate_spec = std::move(base.spec);
  }
  if (const auto named = top.optional_table("laminates"))
    for (auto&& [name, node] : named->table()) {
      const auto* t = node.as_table();
      if (t == nullptr)
        fail(top.file(), node.source(),
             fmt::format("laminates.{} must be a table like [laminate] ([laminates.{}])", name.str(),
                         name.str()));
      d.laminates.push_back(read_laminate(d.materials, top.nested(*t, "laminates." + std::string(name.str())),
                                          std::string(name.str())));
    }
  d.regions = read_regions(d, top);
}

/// Top-level `units`: how every number of the deck is written (docs/deck.md).
UnitSystem read_units(const toml::table& root, const std::string& source) {
  const TableReader top(root, "", source);
  const auto name = top.optional_string("units");
  if (!name) return UnitSystem::si;
  if (const auto u = parse_unit_system(*name)) return *u;
  const auto best = closest_name(*name, std::vector<std::string_view>{"SI", "mm-N-MPa-tonne"});
  top.fail_at("units",
              fmt::format("units = \"{}\" is not a unit system{}: expected {}", *name,
                          best ? fmt::format(" (did you mean \"{}\"?)", *best) : "", unit_system_names()));
}

/// Where a geometry meshed on the fly is refined: the impact point, else the point or patch load's
/// centre, when the deck gives one (peeked at before those tables are read).
std::optional<Eigen::Vector2d> refinement_point(const TableReader& top) {
  const auto point_of = [](const std::optional<TableReader>& t) -> std::optional<Eigen::Vector2d> {
    if (!t) return std::nullopt;
    const auto x = t->optional_number("x", "m");
    const auto y = t->optional_number("y", "m");
    if (!x || !y) return std::nullopt;
    return Eigen::Vector2d(*x, *y);
  };
  if (auto p = point_of(top.optional_table("impactor"))) return p;
  if (const auto load = top.optional_table("load")) {
    if (auto p = point_of(load->optional_table("point"))) return p;
    return point_of(load->optional_table("patch"));
  }
  return std::nullopt;
}

/// The plate model the deck describes (analysis/impact/capabilities.hpp).
ModelKind deck_model(const Deck& d) {
  return {d.plate && d.plate->rigid, d.nonlinear, d.damage.progressive.has_value(),
          d.delamination.has_value()};
}

/// The options of the deck that the restrictions of what runs look at.
CaseOptions deck_options(const Deck& d) {
  CaseOptions o;
  if (d.mesh) {
    o.element = d.mesh->element;
    o.mass = d.mesh->mass;
  }
  o.strain_measure = d.nonlinear_settings.measure;
  o.regions = !d.regions.empty();
  o.adaptive = d.time.adaptive.has_value();
  o.mass_scaling = d.time.mass_scaling.kind;
  o.ply_criteria = !d.damage.criteria.empty();
  return o;
}

/// Refuses, at the key that asks for it, a deck whose plate model, integrator and options the one table of
/// what runs refuses (analysis/impact/capabilities.hpp): the deck and the facade say the same.
void refuse_what_does_not_run(const TableReader& top, const Deck& d) {
  const ModelKind model = deck_model(d);
  Integrator integrator = Integrator::implicit;
  try { // the laws' integration is resolved as their tables are read (d.time.laws)
    integrator = resolve_integrator(model, d.time.integration, d.time.laws, std::nullopt);
  } catch (const std::invalid_argument& e) {
    top.fail_here(e.what());
  }
  if (auto why = refusal(model, integrator)) top.fail_here(*why);
  const Restriction* r = broken_restriction(model, integrator, deck_options(d));
  if (r == nullptr) return;
  const std::optional<TableReader> table =
      r->table.empty() ? std::optional<TableReader>(top) : top.optional_table(r->table);
  (table ? *table : top).fail_at(r->key, std::string(r->message));
}

} // namespace

Deck parse_deck_table(const toml::table& root, std::string_view text, const std::string& source) {
  Deck d;
  d.source = source;
  d.text = std::string(text);
  d.units = read_units(root, source);
  const TableReader top(root, "", source, d.units);
  top.only_keys_of("");
  d.title = top.optional_string("title").value_or("");
  read_nonlinear_keys(top, d);
  if (const auto a = top.optional_string("analysis")) {
    const auto kind = parse_analysis_kind(*a);
    if (!kind)
      top.fail_at("analysis",
                  fmt::format("analysis must be one of impact | static | modal | buckling | laminate | "
                              "threshold, got \"{}\"",
                              *a));
    d.analysis = *kind;
  }
  read_materials(top, d);
  if (const auto p = top.optional_table("plate")) d.plate = read_plate(*p);
  read_laminates(top, d);
  const auto mesh_table = top.optional_table("mesh");
  if (mesh_table) {
    d.mesh = read_mesh(*mesh_table);
    for (const char* key : {"file", "geo"}) // before gmsh reads anything
      if (top.has("rig") && mesh_table->has(key))
        mesh_table->fail_at(key, fmt::format("[rig] meshes its plate: leave out mesh.{}", key));
    d.file_mesh = read_mesh_file(*mesh_table, d.mesh_file, refinement_point(top), d.geo_meshing);
  }
  if (const auto t = top.optional_table("rig")) read_rig(top, *t, mesh_table, refinement_point(top), d);
  if (d.file_mesh && d.plate)
    top.fail_at(
        "plate",
        "[plate] gives a rectangle, but mesh.file or mesh.geo gives the plate's shape: leave out [plate] "
        "(its size comes from the mesh)");
  if (const auto t = top.optional_table("boundary"); t && !d.rig)
    d.boundary = read_boundary(*t, d.file_mesh.get());
  if (const auto t = top.optional_table("impactor"))
    d.impactor = read_impactor(*t, d.plate, d.file_mesh.get(), d.impactor_input, d.impactor_defaults);
  const NoseShape nose = d.impactor ? d.impactor->nose : NoseShape::hemisphere;
  if (const auto t = top.optional_table("contact"))
    d.contact = read_contact(*t, nose);
  else if (nose != NoseShape::hemisphere)
    d.contact.unloading = UnloadingLaw::elastic; // docs/impactor.md
  if (const auto t = top.optional_table("time")) d.time = read_time(*t);
  if (const auto t = top.optional_table("load")) d.load = read_load(*t, d.plate, d.file_mesh.get());
  if (const auto t = top.optional_table("modal")) d.modal = read_modal(*t);
  if (const auto t = top.optional_table("buckling")) d.buckling = read_buckling(*t);
  if (const auto t = top.optional_table("damage")) d.damage = read_damage(*t, d);
  if (const auto t = top.optional_table("delamination")) {
    // The plate steps with one integrator: plies whose [damage] leaves `integration` out follow the
    // interfaces' (lagged unless [delamination] or [time] says otherwise; docs/deck.md).
    const auto damage = top.optional_table("damage");
    const bool plies_given = damage && damage->node("integration") != nullptr;
    d.delamination = read_delamination(*t, d, plies_given);
  }
  size_rig_for_damage(d); // once the damage's laws are known
  if (const auto t = top.optional_table("threshold")) d.threshold = read_threshold(*t, d);
  if (const auto t = top.optional_table("output")) read_output(*t, d);
  if (const auto t = top.optional_table("run")) read_run(*t, d);
  refuse_what_does_not_run(top, d);
  d.warnings = plausibility_warnings(d);
  return d;
}

/// The largest deck file load_deck reads [bytes]: a deck is a page of text; anything larger is another file.
constexpr std::uintmax_t max_deck_bytes = 16U << 20U;

Deck load_deck(const std::filesystem::path& path) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) // an ifstream opens a folder and reads nothing
    throw DeckError(
        fmt::format("{}: error: this is a folder, not a deck file: give the .toml file (a results "
                    "folder keeps the deck it ran as deck.toml)",
                    path.string()));
  if (std::filesystem::exists(path, ec) && !std::filesystem::is_regular_file(path, ec))
    throw DeckError(fmt::format( // reading a FIFO or a device would block, or never end (/dev/zero)
        "{}: error: not a regular file (a FIFO, a device or a socket): give the deck's .toml file",
        path.string()));
  if (const auto bytes = std::filesystem::file_size(path, ec); !ec && bytes > max_deck_bytes)
    throw DeckError(
        fmt::format("{}: error: {} bytes is not a deck (a deck is a short text file, at most {} bytes): "
                    "give the deck's .toml file",
                    path.string(), bytes, max_deck_bytes));
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
    need(d.plate.has_value() || d.file_mesh != nullptr, "[plate] (or [mesh] file, geo or [rig])");
    need(d.boundary.has_value() || (d.plate && d.plate->rigid), "[boundary]");
  }
  if (kind == AnalysisKind::static_) need(d.load.has_value(), "[load]");
  if (kind == AnalysisKind::buckling) need(d.buckling.has_value(), "[buckling]");
  if (kind == AnalysisKind::impact || kind == AnalysisKind::threshold)
    need(d.impactor.has_value(), "[impactor]");
  if (d.delamination && kind != AnalysisKind::impact && kind != AnalysisKind::laminate)
    throw DeckError(
        fmt::format("{}: error: [delamination] is read by the impact analysis only; the {} analysis "
                    "runs the single laminate (remove [delamination] or run `plyimpact impact`)",
                    d.source, to_string(kind)));
  if (missing.empty()) return;
  std::string list;
  for (const auto& m : missing)
    list += (list.empty() ? "" : ", ") + m;
  throw DeckError(fmt::format("{}: error: the {} analysis needs {}", d.source, to_string(kind), list));
}

} // namespace plyimpact
