#pragma once
// Linear buckling under uniform in-plane loads: (K + λ K_σ(N)) φ = 0 (SPEC §8, (2.100)–(2.102)).
#include "plyimpact/analysis/impact/parameters.hpp"
#include "plyimpact/fem/discrete_plate.hpp"

#include <vector>

namespace plyimpact {

struct BucklingResult {
  std::vector<double> load_factors; ///< ascending positive λ: the critical load is λ (Nx, Ny, Nxy)
  Eigen::MatrixXd modes;            ///< free-DOF buckling modes (columns)
};

/// Lowest positive load factors. Throws InsufficientRestraint when K is singular.
[[nodiscard]] BucklingResult solve_buckling(const DiscretePlate& model, const BucklingSettings& settings);

} // namespace plyimpact
