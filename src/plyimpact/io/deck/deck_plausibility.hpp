#pragma once
// Plausibility of a parsed deck (docs/deck.md, "Plausibility warnings"): every quantity is compared
// with the range it takes for laminated plates and their impactors. A value outside it is most often
// a unit slip (MPa for Pa, mm for m, g for kg, g/cm³ for kg/m³, ...): the warning names the key, the
// value as written, the unit it looks like and the number to write instead.
#include "plyimpact/io/deck/deck.hpp"

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace plyimpact {

/// A quantity of the deck with the range it plausibly takes.
struct PlausibleRange {
  std::string key;          ///< as in the deck, e.g. "materials.T300.E1"
  double value = 0.0;       ///< [SI]
  std::string_view si_unit; ///< "Pa", "m", "kg", "kg/m^3", "m/s", "s", "J"
  double lo = 0.0;          ///< [SI], inclusive
  double hi = 0.0;          ///< [SI], inclusive
  std::string_view what;    ///< "a ply modulus": what the range is for
};

/// The warning for `q` (written in `units`) when its value lies outside [lo, hi]: with the unit the
/// written number looks like when one (a power of ten away) brings it into the range.
[[nodiscard]] std::optional<std::string> plausibility_warning(const PlausibleRange& q, UnitSystem units);

/// Every plausibility warning of `deck` (numbers in SI, deck.units says how they were written):
/// moduli, strengths, densities, ply thickness, plate size, laminate thickness against the span,
/// impactor mass, radius, velocity and energy, contact stiffness and critical indentation, time step
/// and end time against the Hertz contact time, graded-mesh sizes.
[[nodiscard]] std::vector<std::string> plausibility_warnings(const Deck& deck);

} // namespace plyimpact
