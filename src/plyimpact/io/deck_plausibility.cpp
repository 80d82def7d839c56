#include "plyimpact/io/deck_plausibility.hpp"

#include "plyimpact/analysis/contact_rules.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <utility>

namespace plyimpact {

namespace {

struct NamedUnit {
  std::string_view name;
  double si; ///< SI value of one of it
};

/// Units a number of the quantity with SI unit `si_unit` is likely to have been written in.
std::vector<NamedUnit> likely_units(std::string_view si_unit) {
  if (si_unit == "Pa") return {{"Pa", 1.0}, {"kPa", 1e3}, {"MPa", 1e6}, {"GPa", 1e9}};
  if (si_unit == "m") return {{"m", 1.0}, {"mm", 1e-3}, {"µm", 1e-6}, {"km", 1e3}};
  if (si_unit == "kg") return {{"kg", 1.0}, {"g", 1e-3}, {"mg", 1e-6}, {"tonne", 1e3}};
  if (si_unit == "kg/m^3") return {{"kg/m^3", 1.0}, {"g/cm^3", 1e3}, {"g/mm^3", 1e6}, {"tonne/mm^3", 1e12}};
  if (si_unit == "m/s") return {{"m/s", 1.0}, {"mm/s", 1e-3}, {"km/s", 1e3}};
  if (si_unit == "s") return {{"s", 1.0}, {"ms", 1e-3}, {"µs", 1e-6}};
  if (si_unit == "J") return {{"J", 1.0}, {"mJ", 1e-3}, {"kJ", 1e3}};
  return {};
}

/// 142e9, 0.127, 6.14, 350e-6: at most 6 significant digits, exponents in steps of three.
std::string short_number(double v) {
  const double a = std::abs(v);
  if (a == 0.0 || (a >= 1e-3 && a < 1e6)) return fmt::format("{:.6g}", v);
  const int e = 3 * static_cast<int>(std::floor(std::log10(a) / 3.0));
  return fmt::format("{:.6g}e{}", v / std::pow(10.0, e), e);
}

/// "decks are in Pa (SI)" or "this deck is in MPa (units = "mm-N-MPa-tonne")".
std::string deck_units_note(UnitSystem units, std::string_view si_unit) {
  if (units == UnitSystem::si) return fmt::format("decks are in {} (SI)", si_unit);
  return fmt::format("this deck is in {} (units = \"{}\")", unit_conversion(units, si_unit).unit,
                     to_string(units));
}

/// Plausible ranges [SI] shared by checks whose results feed other checks.
struct Range {
  double lo, hi;
  [[nodiscard]] bool holds(double v) const { return v >= lo && v <= hi; }
};
constexpr Range modulus{5e8, 1.5e12};
constexpr Range radius_range{5e-4, 0.5};
constexpr Range velocity_range{0.01, 300.0};
constexpr Range mass_range{1e-3, 100.0};
constexpr double k_ratio = 30.0; ///< k within a factor of it of the Hertz value

struct Checks {
  UnitSystem units;
  std::vector<std::string> warnings;
  void add(const PlausibleRange& q) {
    if (auto w = plausibility_warning(q, units)) warnings.push_back(std::move(*w));
  }
};

void check_materials(const Deck& d, Checks& c) {
  for (const Material& m : d.materials) {
    const std::string k = "materials." + m.name + ".";
    for (const auto& [name, v] : {std::pair{"E1", m.E1}, {"E2", m.E2}})
      c.add({k + name, v, "Pa", modulus.lo, modulus.hi, "a ply modulus"});
    for (const auto& [name, v] : {std::pair{"G12", m.G12}, {"G13", m.G13}, {"G23", m.G23}})
      c.add({k + name, v, "Pa", 1e8, 5e11, "a ply shear modulus"});
    c.add({k + "rho", m.rho, "kg/m^3", 300.0, 25e3, "a density"});
    const Strengths& s = m.strength;
    for (const auto& [name, v] : {std::pair{"Xt", s.Xt}, {"Xc", s.Xc}})
      if (v) c.add({k + name, *v, "Pa", 3e7, 1e10, "a fibre-direction strength"});
    for (const auto& [name, v] :
         {std::pair{"Yt", s.Yt}, {"Yc", s.Yc}, {"S12", s.S12}, {"S23", s.S23}, {"Zt", s.Zt}})
      if (v) c.add({k + name, *v, "Pa", 1e6, 5e9, "a matrix or shear strength"});
  }
}

void check_laminate(const std::string& path, const LaminateSpec& spec, const Laminate& laminate,
                    const Deck& d, Checks& c) {
  constexpr double lo = 1e-5, hi = 5e-3;
  c.add({path + ".ply_thickness", spec.ply_thickness, "m", lo, hi, "a ply thickness"});
  for (const PlyOverride& o : spec.overrides)
    if (o.thickness) c.add({path + ".override.thickness", *o.thickness, "m", lo, hi, "a ply thickness"});
  if (!d.plate || d.plate->rigid) return;
  const double span = std::min(d.plate->a, d.plate->b);
  const double h = laminate.thickness();
  const UnitConversion mm = unit_conversion(d.units, "m");
  if (h > span / 5.0)
    c.warnings.push_back(fmt::format(
        "[{}] is {} {} thick, more than a fifth of the plate's shorter side ({} {}): plate theory no longer "
        "applies (a thick plate or a solid needs a 3-D model); check {}.ply_thickness and the layup",
        path, short_number(mm.from_si(h)), mm.unit, short_number(mm.from_si(span)), mm.unit, path));
}

/// The laminate under the impact point: the contact stiffness "auto" takes E2 of its ply 1.
const Laminate& impacted_laminate(const Deck& d) {
  for (auto r = d.regions.rbegin(); r != d.regions.rend(); ++r)
    if (r->laminate >= 1 && r->contains(d.impactor->x, d.impactor->y))
      return d.laminates[static_cast<std::size_t>(r->laminate - 1)].laminate;
  return *d.laminate;
}

void check_contact_stiffness(const Deck& d, double k_auto, Checks& c) {
  if (!d.contact.k) return;
  const double k = *d.contact.k;
  const double ratio = k / k_auto;
  if (ratio >= 1.0 / k_ratio && ratio <= k_ratio) return;
  const std::string_view unit = contact_constant_unit(d.impactor->nose);
  const UnitConversion conv = unit_conversion(d.units, unit);
  const UnitConversion mm = unit_conversion(UnitSystem::mm_n_mpa_tonne, unit);
  // Written in N/mm^n where N/m^n was meant, or the other way round.
  const double as_other = d.units == UnitSystem::si ? k * mm.multiply : k / mm.multiply;
  const std::string_view other = d.units == UnitSystem::si ? mm.unit : unit;
  std::string hint = "check its unit";
  if (as_other / k_auto >= 1.0 / 3.0 && as_other / k_auto <= 3.0)
    hint = fmt::format("this looks like {}; {} — write {}", other, deck_units_note(d.units, unit),
                       short_number(conv.from_si(as_other)));
  c.warnings.push_back(fmt::format("contact.k = {}: {} times the Hertz stiffness of this impactor on ply 1 "
                                   "(k = \"auto\" gives {} {}); {}",
                                   short_number(conv.from_si(k)), fmt::format("{:.3g}", ratio),
                                   short_number(conv.from_si(k_auto)), conv.unit, hint));
}

void check_impactor(const Deck& d, Checks& c) {
  const Impactor& imp = *d.impactor;
  const bool cone = imp.nose == NoseShape::cone; // no radius
  const bool radius_ok = cone || radius_range.holds(imp.radius);
  if (!cone)
    c.add({"impactor.radius", imp.radius, "m", radius_range.lo, radius_range.hi, "an impactor radius"});
  if (d.impactor_input.density) {
    c.add({"impactor.density", *d.impactor_input.density, "kg/m^3", 300.0, 25e3, "a density"});
  } else {
    // Lighter than a sphere of its radius of 300 kg/m^3 (wood) is as implausible as a heavy drop weight.
    const double sphere = 300.0 * 4.0 / 3.0 * std::numbers::pi * std::pow(imp.radius, 3);
    c.add({"impactor.mass", imp.mass, "kg",
           radius_ok && !cone ? std::max(mass_range.lo, sphere) : mass_range.lo, mass_range.hi,
           "an impactor mass"});
  }
  c.add({"impactor.E", imp.E, "Pa", modulus.lo, modulus.hi, "an impactor modulus"});
  if (d.impactor_input.energy)
    c.add({"impactor.energy", *d.impactor_input.energy, "J", 1e-3, 1e4, "a low-velocity impact energy"});
  else
    c.add({"impactor.velocity", imp.velocity, "m/s", velocity_range.lo, velocity_range.hi,
           "a low-velocity impact velocity"});
  if (d.contact.alpha_cr > 0.0)
    c.add({"contact.alpha_cr", d.contact.alpha_cr, "m", 1e-6, 5e-3, "a critical indentation"});
  if (!d.laminate) return;
  // The checks below rest on the Hertz stiffness and contact time: only from plausible inputs (an
  // implausible one has its own warning, and would make these say the wrong thing).
  const Laminate& impacted = impacted_laminate(d);
  const double E2 = impacted.material_of(0).E2;
  if (!(modulus.holds(E2) && modulus.holds(imp.E) && radius_ok)) return;
  const double k_auto = automatic_contact_stiffness(imp, impacted);
  check_contact_stiffness(d, k_auto, c);
  const double k = d.contact.k.value_or(k_auto);
  if (!(mass_range.holds(imp.mass) && velocity_range.holds(imp.velocity) && k >= k_auto / k_ratio &&
        k <= k_auto * k_ratio))
    return;
  // Δt and the end time against the rigid-target Hertz contact time (the plate only lengthens it).
  const double tc = hertz_contact_time(imp.mass, imp.velocity, k, contact_exponent(imp.nose));
  const std::string what = fmt::format("this impact (Hertz contact time {} s)", short_number(tc));
  // With error-controlled steps dt is only the longest step (out of contact it is taken as it is).
  if (d.time.dt)
    c.add({"time.dt", *d.time.dt, "s", tc / 1e5, d.time.adaptive ? tc * 10.0 : tc / 5.0,
           (d.time.adaptive ? "the longest time step of " : "a time step of ") + what});
  if (d.time.end) c.add({"time.end", *d.time.end, "s", tc / 1e3, tc * 1e3, "an end time of " + what});
}

void check_plate(const Deck& d, Checks& c) {
  const PlateGeometry& p = *d.plate;
  c.add({"plate.a", p.a, "m", 0.01, 10.0, "a plate side"});
  c.add({"plate.b", p.b, "m", 0.01, 10.0, "a plate side"});
  if (!d.mesh || !d.mesh->grading) return;
  const double span = std::min(p.a, p.b);
  const MeshGrading& g = *d.mesh->grading;
  if (g.size_at_impact)
    c.add({"mesh.size_at_impact", *g.size_at_impact, "m", span / 1e4, span, "an element size on this plate"});
  if (g.max_size)
    c.add({"mesh.max_size", *g.max_size, "m", span / 1e4, span, "an element size on this plate"});
}

} // namespace

std::optional<std::string> plausibility_warning(const PlausibleRange& q, UnitSystem units) {
  if (q.value >= q.lo && q.value <= q.hi) return std::nullopt;
  const UnitConversion conv = unit_conversion(units, q.si_unit);
  const double written = conv.from_si(q.value);
  const std::string range =
      fmt::format("{} is expected between {} and {} {}", q.what, short_number(conv.from_si(q.lo)),
                  short_number(conv.from_si(q.hi)), conv.unit);
  // Of the units that bring the number into the range, the one that brings it nearest the middle.
  const double middle = std::log(q.lo * q.hi) / 2.0;
  std::optional<NamedUnit> best;
  for (const NamedUnit& u : likely_units(q.si_unit)) {
    const double meant = written * u.si;
    if (u.name == conv.unit || !(meant >= q.lo && meant <= q.hi)) continue;
    if (!best || std::abs(std::log(meant) - middle) < std::abs(std::log(written * best->si) - middle))
      best = u;
  }
  if (best) {
    const NamedUnit& u = *best;
    const double meant = written * u.si;
    const bool fe_units = units == UnitSystem::si &&
                          u.name == unit_conversion(UnitSystem::mm_n_mpa_tonne, q.si_unit).unit &&
                          u.si != 1.0;
    return fmt::format("{} = {}: this looks like {}; {} — write {}{} ({})", q.key, short_number(written),
                       u.name, deck_units_note(units, q.si_unit), short_number(conv.from_si(meant)),
                       fe_units ? fmt::format(", or set units = \"{}\" for the whole deck",
                                              to_string(UnitSystem::mm_n_mpa_tonne))
                                : "",
                       range);
  }
  return fmt::format("{} = {} {}: implausible ({}); check its unit", q.key, short_number(written), conv.unit,
                     range);
}

std::vector<std::string> plausibility_warnings(const Deck& d) {
  Checks c{d.units, {}};
  check_materials(d, c);
  if (d.plate) check_plate(d, c);
  if (d.laminate_spec && d.laminate) check_laminate("laminate", *d.laminate_spec, *d.laminate, d, c);
  for (const NamedLaminate& l : d.laminates)
    check_laminate("laminates." + l.name, l.spec, l.laminate, d, c);
  if (d.impactor) check_impactor(d, c);
  return c.warnings;
}

} // namespace plyimpact
