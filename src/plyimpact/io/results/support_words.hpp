#pragma once
// The supports of [boundary] in words, for readers who have not read docs/deck.md: the preview, report.html
// and the terminal say "simply supported, soft (w held both ways)" where the deck says "ss-soft" (issue 82:
// "window: ss-soft, clamps: 11100" was printed unexplained).
#include "plyimpact/fem/boundary.hpp"

#include <string>
#include <string_view>
#include <vector>

namespace plyimpact {

/// "u, v, w held" for a restraint code "uvwθxθy" of 0/1 (fem/boundary.hpp); "nothing held" for 00000.
[[nodiscard]] std::string held_dofs(std::string_view code);

/// A support type of [boundary] (free, clamped, ss, ss-soft, unilateral or a code) in words.
[[nodiscard]] std::string restraint_words(std::string_view type);

/// The sets of one support type, in the order of the first of them in [boundary].
struct SupportGroup {
  std::string type;
  std::vector<std::string> sets;
  /// "x0, xa: simply supported, hard (…)".
  [[nodiscard]] std::string words() const;
};

/// The sets of `bc` grouped by type, in the order of each type's first set (corners not included).
[[nodiscard]] std::vector<SupportGroup> support_groups(const BoundaryConditions& bc);

/// Every group's words joined by "; ", and the corners' code where [boundary] gives one; "none (free plate)"
/// without supports.
[[nodiscard]] std::string supports_in_words(const BoundaryConditions& bc);

} // namespace plyimpact
