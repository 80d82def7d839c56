#pragma once
// A general mesh of 9-node quadrilaterals in the plate's mid-plane (SPEC §3): nodes, connectivity,
// named node sets and named edge sets. Boundary conditions and loads refer to the sets by name; the
// structured rectangle (structured_mesh.hpp) is one way to make a mesh, a gmsh file another. Nothing
// that uses a Mesh may assume a grid.
#include <Eigen/Core>
#include <array>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace plyimpact {

using ElementCoordinates = Eigen::Matrix<double, 9, 2>; ///< (x, y) of the nine element nodes
using ElementNodes = std::array<int, 9>;                ///< local node order of shape_functions.hpp

/// Where a point lies: element and local coordinates (ξ, η) ∈ [−1, 1]².
struct PointLocation {
  int element = -1;
  double xi = 0.0;
  double eta = 0.0;
};

/// One side of an element on a boundary: its three nodes (corner, mid-side, corner).
using EdgeSegment = std::array<int, 3>;

/// The axis-aligned box around the nodes.
struct BoundingBox {
  double x_min = 0.0, x_max = 0.0, y_min = 0.0, y_max = 0.0;
  [[nodiscard]] Eigen::Vector2d centre() const { return {0.5 * (x_min + x_max), 0.5 * (y_min + y_max)}; }
  [[nodiscard]] double size() const;
};

class Mesh {
public:
  /// Throws std::invalid_argument for a node index out of range.
  Mesh(std::vector<Eigen::Vector2d> nodes, std::vector<ElementNodes> elements);

  [[nodiscard]] int node_count() const { return static_cast<int>(nodes_.size()); }
  [[nodiscard]] int element_count() const { return static_cast<int>(elements_.size()); }
  [[nodiscard]] const Eigen::Vector2d& node(int n) const { return nodes_[static_cast<std::size_t>(n)]; }
  [[nodiscard]] const ElementNodes& element_nodes(int e) const {
    return elements_[static_cast<std::size_t>(e)];
  }
  [[nodiscard]] ElementCoordinates element_coordinates(int e) const;
  [[nodiscard]] const BoundingBox& bounds() const { return bounds_; }

  /// Named sets. A name may be used once per kind; an edge set also defines the node set of its nodes.
  /// The same nodes, elements and named sets (what the mesh is built from).
  friend bool operator==(const Mesh& a, const Mesh& b) {
    return a.nodes_ == b.nodes_ && a.elements_ == b.elements_ && a.node_sets_ == b.node_sets_ &&
           a.edge_sets_ == b.edge_sets_;
  }
  void add_node_set(const std::string& name, std::vector<int> nodes);
  void add_edge_set(const std::string& name, std::vector<EdgeSegment> edges);
  [[nodiscard]] bool has_node_set(const std::string& name) const { return node_sets_.contains(name); }
  [[nodiscard]] bool has_edge_set(const std::string& name) const { return edge_sets_.contains(name); }
  /// Throws std::out_of_range naming the set and the sets that exist.
  [[nodiscard]] const std::vector<int>& node_set(const std::string& name) const;
  [[nodiscard]] const std::vector<EdgeSegment>& edge_set(const std::string& name) const;
  [[nodiscard]] std::vector<std::string> node_set_names() const;

  /// Moves a node (tests: distorted patches). Keeps the topology and the named sets.
  void move_node(int n, const Eigen::Vector2d& xy);

  /// Elements of the same shape (equal node coordinates up to a translation) have equal element
  /// matrices: class c's matrices are computed once, on its first element representative(c).
  [[nodiscard]] int shape_class(int e) const { return shape_class_[static_cast<std::size_t>(e)]; }
  [[nodiscard]] int shape_class_count() const { return static_cast<int>(representative_.size()); }
  [[nodiscard]] int representative(int shape_class) const {
    return representative_[static_cast<std::size_t>(shape_class)];
  }

  /// Locates (x, y); nullopt when outside. A point on an edge or node shared by several elements
  /// belongs to the one with the highest index (on a structured mesh numbered along x first: the
  /// element above and to the right).
  [[nodiscard]] std::optional<PointLocation> locate(double x, double y) const;
  /// Maps local (ξ, η) of element e to (x, y).
  [[nodiscard]] Eigen::Vector2d map(int e, double xi, double eta) const;
  /// Element e's area ∫ det J dξ dη (3×3 Gauss, exact for the bilinear-in-shape Jacobian of a Q9
  /// with straight sides; close otherwise).
  [[nodiscard]] double element_area(int e) const;

  /// The element counts along x and y when the mesh came from the structured factory (reports).
  struct Grid {
    int nx = 0, ny = 0;
  };
  void set_grid(Grid g) { grid_ = g; }
  [[nodiscard]] const std::optional<Grid>& grid() const { return grid_; }

private:
  void classify_shapes();
  void build_locator();

  std::vector<Eigen::Vector2d> nodes_;
  std::vector<ElementNodes> elements_;
  std::map<std::string, std::vector<int>> node_sets_;
  std::map<std::string, std::vector<EdgeSegment>> edge_sets_;
  std::vector<int> shape_class_, representative_;
  BoundingBox bounds_;
  std::optional<Grid> grid_;
  // Uniform bucket grid over the bounding box: the elements whose box overlaps each bucket.
  int buckets_x_ = 1, buckets_y_ = 1;
  std::vector<std::vector<int>> buckets_;
};

} // namespace plyimpact
