#include "plyimpact/io/deck/deck_plausibility.hpp"

#include "plyimpact/analysis/contact/contact_rules.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
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
  if (si_unit == "J/m^2") return {{"J/m^2", 1.0}, {"N/mm", 1e3}};
  if (si_unit == "Pa/m") return {{"Pa/m", 1.0}, {"N/mm^3", 1e9}};
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
constexpr Range plate_side{0.01, 10.0};
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
    const FractureToughness& g = m.toughness;
    for (const auto& [name, v] : {std::pair{"G_ft", g.G_ft}, {"G_fc", g.G_fc}})
      if (v) c.add({k + name, *v, "J/m^2", 1e3, 1e6, "a fibre-mode (translaminar) fracture toughness"});
    for (const auto& [name, v] : {std::pair{"G_mt", g.G_mt}, {"G_mc", g.G_mc}, {"G_ms", g.G_ms}})
      if (v) c.add({k + name, *v, "J/m^2", 10.0, 2e4, "a matrix-mode (intralaminar) fracture toughness"});
    if (g.bk_exponent)
      c.add({k + "bk_exponent", *g.bk_exponent, "-", 0.3, 10.0, "a Benzeggagh-Kenane exponent"});
  }
}

/// [damage] progressive: the viscous regularisation's time constant, against an impact's milliseconds.
void check_damage(const Deck& d, Checks& c) {
  if (!d.damage.progressive) return;
  const double eta = d.damage.progressive->law.viscosity;
  if (eta > 0.0)
    c.add({"damage.viscosity", eta, "s", 0.0, 1e-3,
           "a viscous regularisation time (it delays damage by about itself; an impact lasts milliseconds)"});
}

/// [delamination]: the interfaces' toughnesses, strengths, B-K exponent and penalty stiffness.
std::optional<std::array<double, 2>> plate_sides(const Deck& d);

void check_delamination(const Deck& d, Checks& c) {
  if (!d.delamination) return;
  const CohesiveParameters& law = d.delamination->stack.interface;
  c.add({"delamination.G_Ic", law.G_Ic, "J/m^2", 20.0, 1e4, "an interlaminar mode I toughness"});
  c.add({"delamination.G_IIc", law.G_IIc, "J/m^2", 50.0, 2e4, "an interlaminar mode II toughness"});
  c.add({"delamination.bk_exponent", law.bk_exponent, "-", 0.3, 10.0,
         "a Benzeggagh-Kenane exponent (published fits lie between 1 and 3)"});
  c.add({"delamination.normal_strength", law.normal_strength, "Pa", 1e6, 1e9, "an interface strength"});
  c.add({"delamination.shear_strength", law.shear_strength, "Pa", 1e6, 1e9, "an interface strength"});
  c.add({"delamination.penalty_stiffness", law.penalty_stiffness, "Pa/m", 1e11, 1e17,
         "a cohesive penalty stiffness (Turon et al. 2007: 50 E3/t, about 1e13 to 1e16 Pa/m)"});
  // a seed larger than the plate cracks every interface everywhere (issue 77: 1e300 ran 15 s a step,
  // silently)
  if (const double seed = d.delamination->stack.seed_radius; seed > 0.0)
    if (const auto sides = plate_sides(d))
      c.add({"delamination.seed_radius", seed, "m", 1e-4, 0.5 * std::max((*sides)[0], (*sides)[1]),
             "the radius of a seeded delamination on this plate (at most half its longer side)"});
}

/// The plate's sides [m]: [plate] a and b, or the bounding box of a mesh from gmsh (mesh.file, mesh.geo,
/// [rig]); nothing for a rigid target.
std::optional<std::array<double, 2>> plate_sides(const Deck& d) {
  if (d.plate) {
    if (d.plate->rigid) return std::nullopt;
    return std::array{d.plate->a, d.plate->b};
  }
  if (!d.file_mesh) return std::nullopt;
  const BoundingBox& box = d.file_mesh->bounds();
  return std::array{box.x_max - box.x_min, box.y_max - box.y_min};
}

/// Where a deck's mesh came from, for the messages.
std::string mesh_source(const Deck& d) {
  if (d.rig) return "[rig]";
  return d.geo_meshing ? fmt::format("mesh.geo (\"{}\")", d.mesh_file)
                       : fmt::format("mesh.file (\"{}\")", d.mesh_file);
}

void check_laminate(const std::string& path, const LaminateSpec& spec, const Laminate& laminate,
                    const Deck& d, Checks& c) {
  constexpr double lo = 1e-5, hi = 5e-3;
  c.add({path + ".ply_thickness", spec.ply_thickness, "m", lo, hi, "a ply thickness"});
  for (const PlyOverride& o : spec.overrides)
    if (o.thickness) c.add({path + ".override.thickness", *o.thickness, "m", lo, hi, "a ply thickness"});
  const auto sides = plate_sides(d);
  if (!sides) return;
  const double span = std::min((*sides)[0], (*sides)[1]);
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

/// A flat punch wider than the plate, a cone sharper than a needle (its angle in radians).
void check_nose(const Deck& d, Checks& c) {
  const Impactor& imp = *d.impactor;
  const auto sides = plate_sides(d);
  const double span = sides ? std::min((*sides)[0], (*sides)[1]) : INFINITY;
  if (imp.nose == NoseShape::flat && 2.0 * imp.radius > span)
    c.warnings.push_back(fmt::format("impactor.radius = {} m: the flat end ({} m across) is wider than the "
                                     "plate's shorter side ({} m): its whole face cannot bear on the plate, "
                                     "which the flat-punch law assumes; check the radius and its unit",
                                     short_number(imp.radius), short_number(2.0 * imp.radius),
                                     short_number(span)));
  constexpr double needle_deg = 5.0;
  const double deg = imp.half_angle * 180.0 / std::numbers::pi;
  if (imp.nose == NoseShape::cone && deg < needle_deg)
    c.warnings.push_back(fmt::format(
        "impactor.half_angle = {} deg: a cone sharper than {} degrees is a needle; half_angle is in degrees, "
        "and {} looks like radians — write {}",
        short_number(deg), needle_deg, short_number(deg), short_number(deg * 180.0 / std::numbers::pi)));
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
  check_nose(d, c);
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

/// mesh.size_at_impact and mesh.max_size against the plate's shorter side `span` (a structured or a gmsh
/// mesh).
void check_element_sizes(const std::optional<double>& at_impact, const std::optional<double>& max_size,
                         double span, Checks& c) {
  if (at_impact)
    c.add({"mesh.size_at_impact", *at_impact, "m", span / 1e4, span, "an element size on this plate"});
  if (max_size) c.add({"mesh.max_size", *max_size, "m", span / 1e4, span, "an element size on this plate"});
}

/// A plate meshed by gmsh: its bounding box, and the sizes it was meshed with.
void check_gmsh_plate(const Deck& d, Checks& c) {
  const auto sides = plate_sides(d);
  if (!sides) return;
  const auto [w, h] = *sides;
  if (d.rig && d.rig->kind == RigKind::circular) {
    c.add({"rig.diameter", d.rig->diameter, "m", plate_side.lo, plate_side.hi, "a plate side"});
  } else if (!d.rig && !(plate_side.holds(w) && plate_side.holds(h))) {
    c.warnings.push_back(fmt::format(
        "the plate of {} is {} x {} m: implausible (a plate side is expected between {} and {} m); check the "
        "unit of its coordinates: plyimpact reads them in the deck's length unit, and drawings are often in "
        "mm",
        mesh_source(d), short_number(w), short_number(h), plate_side.lo, plate_side.hi));
  }
  if (d.geo_meshing)
    check_element_sizes(d.geo_meshing->size_at_point, d.geo_meshing->max_size, std::min(w, h), c);
}

void check_plate(const Deck& d, Checks& c) {
  const PlateGeometry& p = *d.plate;
  c.add({"plate.a", p.a, "m", plate_side.lo, plate_side.hi, "a plate side"});
  c.add({"plate.b", p.b, "m", plate_side.lo, plate_side.hi, "a plate side"});
  if (d.mesh && d.mesh->grading)
    check_element_sizes(d.mesh->grading->size_at_impact, d.mesh->grading->max_size, std::min(p.a, p.b), c);
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
  if (d.file_mesh) check_gmsh_plate(d, c);
  check_damage(d, c);
  check_delamination(d, c);
  if (d.laminate_spec && d.laminate) check_laminate("laminate", *d.laminate_spec, *d.laminate, d, c);
  for (const NamedLaminate& l : d.laminates)
    check_laminate("laminates." + l.name, l.spec, l.laminate, d, c);
  if (d.impactor) check_impactor(d, c);
  return c.warnings;
}

} // namespace plyimpact
