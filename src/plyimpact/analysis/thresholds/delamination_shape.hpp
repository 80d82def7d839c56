#pragma once
// The shape of a delamination as a C-scan study reads it (issue 51, "Shapes"): the delaminated area of an
// interface (its points with d = 1), its centroid, and the principal axes of its second moments of area.
// C-scans of impacted laminates show each interface's delamination as two lobes ("peanut") along the fibres
// of the ply below it; the long principal axis gives that direction, the ratio of the axes its elongation.
//
// With the second moments of the delaminated area about its centroid, I_xx = ∫(y − ȳ)² dA,
// I_yy = ∫(x − x̄)² dA, I_xy = ∫(x − x̄)(y − ȳ) dA, summed exactly over the cells of the delaminated
// points (each cell a polygon: its shoelace moments, scaled to the point's area), the long axis makes the
// angle
//
//     φ = ½ atan2(2 I_xy, I_yy − I_xx)                                                         (DS1)
//
// with x, towards y (the fibre angles' convention, SPEC §1), and the aspect ratio is √(λ₁/λ₂) of the
// eigenvalues λ₁ ≥ λ₂ of [[I_yy, I_xy], [I_xy, I_xx]]: a/b for an ellipse of semi-axes a, b (its second
// moments are πab³/4 and πa³b/4).
#include "plyimpact/fem/stacked_plate.hpp"

#include <Eigen/Core>

#include <array>
#include <optional>
#include <vector>

namespace plyimpact {

/// One interface's delaminated area and its principal axes.
struct DelaminationShape {
  double area = 0.0;                                  ///< the points with d = 1 [m²]
  Eigen::Vector2d centroid = Eigen::Vector2d::Zero(); ///< [m]
  /// The long principal axis, degrees from x towards y in (−90, 90]; empty without delaminated area.
  std::optional<double> axis_deg;
  /// √(λ₁/λ₂) of the second moments (1 for a disc; a/b for an ellipse; w/h for one w × h cell); empty
  /// without area.
  std::optional<double> aspect_ratio;
};

/// The shape of the points with d ≥ 1 among `damage` (per point), each at the centre of its `cells` entry
/// with its `area`.
[[nodiscard]] DelaminationShape delamination_shape(const std::vector<std::array<Eigen::Vector2d, 4>>& cells,
                                                   const std::vector<double>& area,
                                                   const std::vector<double>& damage);
/// The shape of every interface of `result`, in its order.
[[nodiscard]] std::vector<DelaminationShape> delamination_shapes(const DelaminationResult& result);

/// The angle between an axis and a fibre direction, folded into [0, 90] degrees (both are lines).
[[nodiscard]] double angle_between_lines_deg(double a_deg, double b_deg);

} // namespace plyimpact
