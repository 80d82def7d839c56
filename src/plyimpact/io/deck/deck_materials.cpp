#include "plyimpact/io/deck/deck_tables.hpp"

#include <fmt/format.h>

#include <numbers>
#include <optional>

namespace plyimpact::deck_tables {

Material read_material(const TableReader& t, const std::string& name) {
  t.only({"E1",   "E2",   "G12",         "G13",           "G23", "nu12", "rho",  "Xt",   "Xc",
          "Yt",   "Yc",   "S12",         "S23",           "Zt",  "Da",   "G_ft", "G_fc", "G_mt",
          "G_mc", "G_ms", "bk_exponent", "fracture_angle"});
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
  if (const std::optional<double> angle = t.optional_positive("fracture_angle", "deg")) {
    if (!(*angle > 45.0 && *angle < 90.0))
      t.fail_at("fracture_angle",
                fmt::format("material '{}': fracture_angle is the angle of the fracture plane in transverse "
                            "compression, between 45 and 90 deg (about 53 for carbon/epoxy), got {}",
                            name, *angle));
    s.fracture_angle = *angle * std::numbers::pi / 180.0;
  }
  FractureToughness& g = m.toughness; // progressive damage (docs/progressive_damage.md)
  g.G_ft = t.optional_positive("G_ft", "J/m^2");
  g.G_fc = t.optional_positive("G_fc", "J/m^2");
  g.G_mt = t.optional_positive("G_mt", "J/m^2");
  g.G_mc = t.optional_positive("G_mc", "J/m^2");
  g.G_ms = t.optional_positive("G_ms", "J/m^2");
  g.bk_exponent = t.optional_positive("bk_exponent", "-");
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
