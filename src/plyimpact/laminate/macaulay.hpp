#pragma once

namespace plyimpact {

/// The Macaulay bracket ⟨x⟩ = max(x, 0): the positive part of a strain, a traction or a separation.
[[nodiscard]] constexpr double macaulay(double x) {
  return x > 0.0 ? x : 0.0;
}

} // namespace plyimpact
