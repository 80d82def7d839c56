#pragma once
// Stacking-sequence notation (SPEC §1): "[45/90/-45/0]3s", "[0_2/90_4/0_2]", "[0/±45/90]s".
#include <cstddef>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace plyimpact {

/// A layup string that cannot be parsed. `column` is the 1-based character (not byte) position of
/// the offending character; what() names it and the expected form.
class LayupError : public std::runtime_error {
public:
  LayupError(const std::string& message, std::size_t column);
  [[nodiscard]] std::size_t column() const { return column_; }

private:
  std::size_t column_;
};

/// Expands a layup string into ply angles in degrees, listed from ply 1 (impacted face) down.
///
/// Grammar (white space ignored):
///   layup    := '[' sequence ']' ['_'] [count] ['s' | 'S']
///   sequence := item ('/' item)*
///   item     := (angle | '±'angle | '+-'angle | '∓'angle | '-+'angle | '(' sequence ')') ['_' count] ['*']
/// `_n` repeats a ply or group n times, a trailing count repeats the whole sequence, `s` mirrors it.
/// `±45` expands to 45/−45. In a symmetric laminate with an odd number of plies the unrepeated
/// middle ply is the last ply of the sequence marked with `*`: "[0/45/90*]s" = 0/45/90/45/0.
[[nodiscard]] std::vector<double> parse_layup(std::string_view text);

} // namespace plyimpact
