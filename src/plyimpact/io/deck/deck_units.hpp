#pragma once
// The deck's unit system (top-level `units`, docs/deck.md): "SI" (m, N, Pa, kg, s) or the usual FE
// system "mm-N-MPa-tonne" (mm, N, MPa, tonne, s). Every number is converted to SI once, where the deck
// is read; everything after the deck (analyses, outputs) is SI.
#include <optional>
#include <string>
#include <string_view>

namespace plyimpact {

enum class UnitSystem { si, mm_n_mpa_tonne };

/// "SI" or "mm-N-MPa-tonne".
[[nodiscard]] std::string_view to_string(UnitSystem units);
/// The unit system named `name`, or nullopt for an unknown name.
[[nodiscard]] std::optional<UnitSystem> parse_unit_system(std::string_view name);
/// "SI, mm-N-MPa-tonne": the names parse_unit_system accepts.
[[nodiscard]] std::string unit_system_names();

/// How a number written in `units` for a quantity whose SI unit is `si_unit` ("Pa", "m", "m^2", "kg",
/// "kg/m^3", "m/s", "N/m^1.5", "N/m^2", "s", "N", "N/m", "J", "J/m^2", "Pa/m" or "-") becomes SI.
struct UnitConversion {
  double multiply = 1.0; ///< SI value = written · multiply / divide (one of them is 1: no
  double divide = 1.0;   ///< inexact reciprocal such as 1e-3 enters the conversion)
  std::string_view unit; ///< the unit of the written number ("MPa" for "Pa" in mm-N-MPa-tonne)
  [[nodiscard]] double to_si(double written) const { return written * multiply / divide; }
  [[nodiscard]] double from_si(double si) const { return si * divide / multiply; }
};

/// The conversion of `si_unit` in `units`. Throws std::logic_error for a unit the table does not know.
[[nodiscard]] UnitConversion unit_conversion(UnitSystem units, std::string_view si_unit);

} // namespace plyimpact
