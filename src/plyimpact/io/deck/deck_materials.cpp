#include "plyimpact/io/deck/deck_tables.hpp"
#include "plyimpact/io/deck/material_library.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <numbers>
#include <optional>

namespace plyimpact::deck_tables {

namespace {

/// The library card `library` names, as a reader in SI units whose messages name the card; an error at
/// the deck's key when no card has that name.
TableReader library_card(const TableReader& t, const toml::table& library, const std::string& card) {
  const toml::table* found = library[card].as_table();
  if (found == nullptr) {
    const std::vector<std::string> names = material_library_names();
    std::string msg = fmt::format("{}.library: no card '{}' in the material library", t.path(), card);
    if (const auto best = closest_name(card, names))
      msg += fmt::format(" (did you mean '{}'?)", *best);
    else
      msg += fmt::format(" (cards: {}; `plyimpact materials` lists them with their sources)",
                         fmt::join(names, ", "));
    t.fail_at("library", msg);
  }
  return {*found, "material library card " + card, "material library (plyimpact materials)", UnitSystem::si};
}

} // namespace

Material read_material(const TableReader& t, const std::string& name) {
  t.only_keys_of("material");
  // A library card gives what the deck's table leaves out; a key of the deck's table replaces the card's.
  // The library is parsed only for a table that names a card (it outlives `base`, which reads it).
  const std::optional<std::string> card = t.optional_string("library");
  const std::optional<toml::table> library =
      card ? std::optional<toml::table>(material_library()) : std::nullopt;
  const std::optional<TableReader> base =
      card ? std::optional<TableReader>(library_card(t, *library, *card)) : std::nullopt;
  const auto from = [&](std::string_view key) -> const TableReader& {
    return base && !t.has(key) && base->has(key) ? *base : t;
  };
  // Each key in its unit of the one table the library and the command use (material_key_unit).
  const auto required = [&](std::string_view key) { return from(key).positive(key, material_key_unit(key)); };
  const auto optional = [&](std::string_view key) {
    return from(key).optional_positive(key, material_key_unit(key));
  };
  if (base && !t.has("rho") && !base->has("rho"))
    t.fail_here(
        fmt::format("[{}] takes the library card '{}', which gives no density (its source has none; "
                    "`plyimpact materials {}` shows the card): give rho ({}) in [{}], with its source",
                    t.path(), *card, *card, t.deck_unit("kg/m^3"), t.path()));
  Material m;
  m.name = name;
  m.E1 = required("E1");
  m.E2 = required("E2");
  m.G12 = required("G12");
  m.G13 = optional("G13").value_or(m.G12);
  m.G23 = optional("G23").value_or(m.G12);
  m.nu12 = from("nu12").number("nu12", "-");
  m.rho = required("rho");
  if (!(1.0 - m.nu12 * m.nu21() > 0.0))
    from("nu12").fail_at("nu12", fmt::format("material '{}' is not physical: 1 - nu12*nu21 = {:.4g} must be "
                                             "positive (nu12 = {}, nu21 = nu12*E2/E1 = {:.4g})",
                                             name, 1.0 - m.nu12 * m.nu21(), m.nu12, m.nu21()));
  if (m.nu12 <= -1.0)
    from("nu12").fail_at("nu12", fmt::format("material '{}': nu12 must be greater than -1", name));
  Strengths& s = m.strength;
  s.Xt = optional("Xt");
  s.Xc = optional("Xc");
  s.Yt = optional("Yt");
  s.Yc = optional("Yc");
  s.S12 = optional("S12");
  s.S23 = optional("S23");
  s.Zt = optional("Zt");
  s.Da = optional("Da");
  if (const std::optional<double> angle = optional("fracture_angle")) {
    if (!(*angle > 45.0 && *angle < 90.0))
      from("fracture_angle")
          .fail_at(
              "fracture_angle",
              fmt::format("material '{}': fracture_angle is the angle of the fracture plane in transverse "
                          "compression, between 45 and 90 deg (about 53 for carbon/epoxy), got {}",
                          name, *angle));
    s.fracture_angle = *angle * std::numbers::pi / 180.0;
  }
  FractureToughness& g = m.toughness; // progressive damage (docs/progressive_damage.md)
  g.G_ft = optional("G_ft");
  g.G_fc = optional("G_fc");
  g.G_mt = optional("G_mt");
  g.G_mc = optional("G_mc");
  g.G_ms = optional("G_ms");
  g.bk_exponent = optional("bk_exponent");
  return m;
}

std::size_t material_index(const std::vector<Material>& materials, const TableReader& t, std::string_view key,
                           const std::string& name) {
  for (std::size_t i = 0; i < materials.size(); ++i)
    if (materials[i].name == name) return i;
  std::string known;
  std::string best;
  std::size_t best_d = 1000;
  for (const Material& m : materials) {
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

} // namespace plyimpact::deck_tables
