#pragma once
// Structured mesh of 9-node quadrilaterals over the a × b plate (SPEC §3).
#include "plyimpact/fem/boundary.hpp"
#include "plyimpact/fem/mesh_spec.hpp"

#include <Eigen/Core>
#include <array>
#include <optional>
#include <vector>

namespace plyimpact {

using ElementCoordinates = Eigen::Matrix<double, 9, 2>; ///< (x, y) of the nine element nodes

/// Where a point lies: element and local coordinates (ξ, η) ∈ [−1, 1]².
struct PointLocation {
  int element = -1;
  double xi = 0.0;
  double eta = 0.0;
};

/// Nodes on a (2nx+1) × (2ny+1) grid, numbered along x first: node(i, j) = j (2nx+1) + i.
/// Elements numbered along x first: element(ex, ey) = ey nx + ex (the thesis's element 83 of the
/// 15×11 mesh, 1-based, is the centre element ex = 7, ey = 5).
class PlateMesh {
public:
  PlateMesh(PlateGeometry plate, int nx, int ny);

  [[nodiscard]] int nx() const { return nx_; }
  [[nodiscard]] int ny() const { return ny_; }
  [[nodiscard]] const PlateGeometry& plate() const { return plate_; }
  [[nodiscard]] int node_count() const { return static_cast<int>(nodes_.size()); }
  [[nodiscard]] int element_count() const { return nx_ * ny_; }
  [[nodiscard]] int grid_columns() const { return 2 * nx_ + 1; }
  [[nodiscard]] int grid_rows() const { return 2 * ny_ + 1; }
  [[nodiscard]] int node_id(int i, int j) const { return j * grid_columns() + i; }
  [[nodiscard]] const Eigen::Vector2d& node(int n) const { return nodes_[static_cast<std::size_t>(n)]; }
  [[nodiscard]] const std::array<int, 9>& element_nodes(int e) const {
    return elements_[static_cast<std::size_t>(e)];
  }
  [[nodiscard]] ElementCoordinates element_coordinates(int e) const;

  /// Moves a node (tests: distorted patches). Keeps the grid topology and the edge membership.
  void move_node(int n, const Eigen::Vector2d& xy) { nodes_[static_cast<std::size_t>(n)] = xy; }
  /// True while every element is an axis-aligned rectangle of the same size (element matrices shared).
  [[nodiscard]] bool is_regular() const;

  [[nodiscard]] bool on_edge(int n, Edge e) const;
  /// Locates (x, y) in the mesh; nullopt when outside.
  [[nodiscard]] std::optional<PointLocation> locate(double x, double y) const;
  /// Maps local (ξ, η) of element e to (x, y).
  [[nodiscard]] Eigen::Vector2d map(int e, double xi, double eta) const;

private:
  PlateGeometry plate_;
  int nx_, ny_;
  std::vector<Eigen::Vector2d> nodes_;
  std::vector<std::array<int, 9>> elements_;
};

} // namespace plyimpact
