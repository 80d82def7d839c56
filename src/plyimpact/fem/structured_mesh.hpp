#pragma once
// The structured rectangle: the a × b plate meshed by nx × ny 9-node quadrilaterals (SPEC §3), the
// thesis's mesh. Node and element numbering along x first (the thesis's element 83 of the 15×11 mesh,
// 1-based, is the centre element ex = 7, ey = 5):
//   node(i, j) = j (2nx + 1) + i,   element(ex, ey) = ey nx + ex.
// Named sets: edge sets x0, xa, y0, yb (the edges x = 0, x = a, y = 0, y = b) and the node set corners.
#include "plyimpact/fem/mesh.hpp"
#include "plyimpact/fem/mesh_spec.hpp"

#include <limits>
#include <vector>

namespace plyimpact {

/// Uniform nx × ny mesh of the a × b rectangle.
[[nodiscard]] Mesh structured_rectangle(const PlateGeometry& plate, int nx, int ny);

/// The same with the element boundaries along x at `x_lines` (nx + 1 increasing values from 0 to a)
/// and along y at `y_lines`; mid-side nodes halfway. Throws std::invalid_argument for lines that do not
/// increase or do not span the plate.
[[nodiscard]] Mesh structured_rectangle(const PlateGeometry& plate, const std::vector<double>& x_lines,
                                        const std::vector<double>& y_lines);

/// Element boundaries on [0, L] graded toward x0: the element holding x0 has the size h0 and holds x0 at
/// the fraction `offset` of its length (0.5: at its centre; 0: x0 is an element boundary); the sizes
/// grow by the factor `growth` per element away from it, up to `max_size`; the outermost element on
/// each side ends on the plate edge (stretched up to 1.5 times its size, or merged with the edge when
/// x0 lies closer to it than a quarter element). Throws std::invalid_argument for h0 ≤ 0, growth < 1,
/// x0 outside (0, L) or offset outside [0, 1).
[[nodiscard]] std::vector<double> graded_lines(double L, double x0, double h0, double growth, double offset,
                                               double max_size = std::numeric_limits<double>::infinity());

} // namespace plyimpact
