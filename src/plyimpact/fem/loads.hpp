#pragma once
// Consistent nodal forces of the static loads on the plate (SPEC §8, §10 [load]): a point force, a
// uniform pressure, and a uniform pressure on a rectangular patch. All act along +z (the impact
// direction) on the w DOFs.
#include "plyimpact/fem/discrete_plate.hpp"

#include <optional>

namespace plyimpact {

struct PointLoad {
  double x = 0.0, y = 0.0, force = 0.0; ///< [m], [m], [N] (positive along +z, the impact direction)
};
struct PatchLoad {
  double x = 0.0, y = 0.0, dx = 0.0, dy = 0.0, force = 0.0; ///< centre, size [m], total force [N]
};
struct StaticLoad {
  double pressure = 0.0; ///< uniform pressure on the top face, positive along +z [Pa]
  std::optional<PointLoad> point;
  std::optional<PatchLoad> patch;
};

/// F s with s the shape functions of the element holding (x, y). Throws outside the plate.
[[nodiscard]] Eigen::VectorXd point_load(const DiscretePlate& model, double x, double y, double force);
[[nodiscard]] Eigen::VectorXd pressure_load(const DiscretePlate& model, double q);
/// Uniform pressure force/(dx dy) over the rectangle centred at (x, y), clipped to the plate; the
/// elements it covers must be axis-aligned rectangles (std::invalid_argument otherwise).
[[nodiscard]] Eigen::VectorXd patch_load(const DiscretePlate& model, const PatchLoad& patch);
/// The sum of the loads of `load`.
[[nodiscard]] Eigen::VectorXd static_load_vector(const DiscretePlate& model, const StaticLoad& load);

} // namespace plyimpact
