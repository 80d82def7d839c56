#pragma once
// Regions of a panel with their own laminate (reinforcing pads, ply drops): an axis-aligned box and the
// index of its laminate. An element belongs to the last region that holds its centre (ξ = η = 0);
// elements in no region keep laminate 0, the plate's own.
#include "plyimpact/fem/mesh.hpp"

#include <string>
#include <vector>

namespace plyimpact {

struct Region {
  std::string name; ///< for messages and reports (the laminate's name)
  int laminate = 0; ///< index into PlateSections::laminates
  double x_min = 0.0, x_max = 0.0, y_min = 0.0, y_max = 0.0; ///< [m], bounds included

  /// (x, y) in the box, its bounds widened by `tol` [m].
  [[nodiscard]] bool contains(double x, double y, double tol = 0.0) const {
    return x >= x_min - tol && x <= x_max + tol && y >= y_min - tol && y <= y_max + tol;
  }
  friend bool operator==(const Region&, const Region&) = default;
};

/// The laminate index of every element; empty when `regions` is empty.
[[nodiscard]] std::vector<int> element_laminates(const Mesh& mesh, const std::vector<Region>& regions);

} // namespace plyimpact
