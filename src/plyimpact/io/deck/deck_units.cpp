#include "plyimpact/io/deck/deck_units.hpp"

#include <fmt/format.h>

#include <array>
#include <cmath>
#include <stdexcept>

namespace plyimpact {

namespace {

struct UnitRow {
  std::string_view si;
  UnitConversion mm; ///< mm-N-MPa-tonne
};

// 1 N/mm^1.5 = 1 N / (1e-3 m)^1.5 = 1e3·√1e3 N/m^1.5 (not a power of ten: the only inexact factor).
const std::array<UnitRow, 16> unit_rows{{
    {"-", {1.0, 1.0, "-"}},
    {"deg", {1.0, 1.0, "deg"}},
    {"m", {1.0, 1e3, "mm"}},
    {"m^2", {1.0, 1e6, "mm^2"}},
    {"Pa", {1e6, 1.0, "MPa"}},
    {"kg", {1e3, 1.0, "tonne"}},
    {"kg/m^3", {1e12, 1.0, "tonne/mm^3"}},
    {"m/s", {1.0, 1e3, "mm/s"}},
    {"s", {1.0, 1.0, "s"}},
    {"N", {1.0, 1.0, "N"}},
    {"N/m", {1e3, 1.0, "N/mm"}},
    {"J/m^2", {1e3, 1.0, "N/mm"}}, // fracture toughness: 1 N/mm = 1 kJ/m^2
    {"J", {1.0, 1e3, "mJ"}},
    {"N/m^1.5", {1e3 * std::sqrt(1e3), 1.0, "N/mm^1.5"}},
    {"N/m^2", {1e6, 1.0, "N/mm^2"}}, // a cone's contact constant
    {"Pa/m", {1e9, 1.0, "N/mm^3"}},  // a cohesive penalty stiffness: 1 N/mm^3 = 1e9 Pa/m
}};

} // namespace

std::string_view to_string(UnitSystem units) {
  return units == UnitSystem::si ? "SI" : "mm-N-MPa-tonne";
}

std::optional<UnitSystem> parse_unit_system(std::string_view name) {
  for (const UnitSystem u : {UnitSystem::si, UnitSystem::mm_n_mpa_tonne})
    if (to_string(u) == name) return u;
  return std::nullopt;
}

std::string unit_system_names() {
  return fmt::format("\"{}\" (m, N, Pa, kg, s) or \"{}\" (mm, N, MPa, tonne, s)", to_string(UnitSystem::si),
                     to_string(UnitSystem::mm_n_mpa_tonne));
}

UnitConversion unit_conversion(UnitSystem units, std::string_view si_unit) {
  for (const UnitRow& r : unit_rows)
    if (r.si == si_unit) return units == UnitSystem::si ? UnitConversion{1.0, 1.0, r.si} : r.mm;
  throw std::logic_error(fmt::format("deck units: no conversion for the unit '{}'", si_unit));
}

} // namespace plyimpact
