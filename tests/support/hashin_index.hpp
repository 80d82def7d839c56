#pragma once
// Hashin's plane-stress index with the sign conditions applied, for tests: the fibre pair chosen by the sign
// of σ11, the matrix pair by σ22's, each mode's index from hashin_plane_stress_index (α = 0).
#include "plyimpact/laminate/ply_damage.hpp"

#include <Eigen/Core>

#include <algorithm>

namespace plyimpact::test {

/// The larger of the active fibre and matrix indices at the in-plane stress s = (σ11, σ22, τ12) [Pa].
inline double active_hashin_index(const Eigen::Vector3d& s, const Strengths& strengths) {
  const auto index = [&](DamageMode mode) { return hashin_plane_stress_index(mode, s, strengths, 0.0); };
  return std::max(index(s(0) >= 0.0 ? DamageMode::fibre_tension : DamageMode::fibre_compression),
                  index(s(1) >= 0.0 ? DamageMode::matrix_tension : DamageMode::matrix_compression));
}

} // namespace plyimpact::test
