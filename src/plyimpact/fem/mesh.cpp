#include "plyimpact/fem/mesh.hpp"

#include "plyimpact/fem/shape_functions.hpp"

#include <Eigen/LU>
#include <algorithm>
#include <cmath>

namespace plyimpact {

PlateMesh::PlateMesh(PlateGeometry plate, int nx, int ny) : plate_(plate), nx_(nx), ny_(ny) {
  const int cols = grid_columns(), rows = grid_rows();
  nodes_.reserve(static_cast<std::size_t>(cols) * static_cast<std::size_t>(rows));
  for (int j = 0; j < rows; ++j)
    for (int i = 0; i < cols; ++i)
      nodes_.emplace_back(plate.a * i / (cols - 1), plate.b * j / (rows - 1));
  elements_.reserve(static_cast<std::size_t>(nx) * static_cast<std::size_t>(ny));
  for (int ey = 0; ey < ny; ++ey)
    for (int ex = 0; ex < nx; ++ex) {
      std::array<int, 9> conn{};
      for (int a = 0; a < 9; ++a) {
        const auto& c = q9_node_coordinates[static_cast<std::size_t>(a)];
        const int i = 2 * ex + 1 + static_cast<int>(c[0]);
        const int j = 2 * ey + 1 + static_cast<int>(c[1]);
        conn[static_cast<std::size_t>(a)] = node_id(i, j);
      }
      elements_.push_back(conn);
    }
}

ElementCoordinates PlateMesh::element_coordinates(int e) const {
  ElementCoordinates xy;
  const auto& conn = element_nodes(e);
  for (int a = 0; a < 9; ++a)
    xy.row(a) = node(conn[static_cast<std::size_t>(a)]).transpose();
  return xy;
}

bool PlateMesh::is_regular() const {
  const double dx = plate_.a / nx_, dy = plate_.b / ny_;
  const double tol = 1e-12 * std::max(plate_.a, plate_.b);
  for (int j = 0; j < grid_rows(); ++j)
    for (int i = 0; i < grid_columns(); ++i) {
      const Eigen::Vector2d& p = node(node_id(i, j));
      if (std::abs(p.x() - 0.5 * dx * i) > tol || std::abs(p.y() - 0.5 * dy * j) > tol) return false;
    }
  return true;
}

bool PlateMesh::on_edge(int n, Edge e) const {
  const int i = n % grid_columns(), j = n / grid_columns();
  switch (e) {
  case Edge::x0:
    return i == 0;
  case Edge::xa:
    return i == grid_columns() - 1;
  case Edge::y0:
    return j == 0;
  case Edge::yb:
    return j == grid_rows() - 1;
  }
  return false;
}

Eigen::Vector2d PlateMesh::map(int e, double xi, double eta) const {
  return element_coordinates(e).transpose() * q9_shape(xi, eta).N;
}

std::optional<PointLocation> PlateMesh::locate(double x, double y) const {
  const Eigen::Vector2d target(x, y);
  const double tol = 1e-10;
  // Newton on x(ξ, η) = target inside element e; converges in one step on undistorted elements.
  auto try_element = [&](int e) -> std::optional<PointLocation> {
    const ElementCoordinates xy = element_coordinates(e);
    Eigen::Vector2d s(0.0, 0.0);
    for (int it = 0; it < 30; ++it) {
      const Q9Shape sh = q9_shape(s.x(), s.y());
      const Eigen::Vector2d r = xy.transpose() * sh.N - target;
      Eigen::Matrix2d J;
      J.col(0) = xy.transpose() * sh.dN_dxi;
      J.col(1) = xy.transpose() * sh.dN_deta;
      const Eigen::Vector2d ds = J.fullPivLu().solve(r);
      s -= ds;
      if (!s.allFinite() || s.cwiseAbs().maxCoeff() > 3.0) return std::nullopt;
      if (ds.norm() < 1e-14) break;
    }
    if (std::abs(s.x()) > 1.0 + tol || std::abs(s.y()) > 1.0 + tol) return std::nullopt;
    return PointLocation{e, std::clamp(s.x(), -1.0, 1.0), std::clamp(s.y(), -1.0, 1.0)};
  };
  // Structured guess first, then its neighbours, then every element (distorted meshes only).
  const int ex = std::clamp(static_cast<int>(std::floor(x / plate_.a * nx_)), 0, nx_ - 1);
  const int ey = std::clamp(static_cast<int>(std::floor(y / plate_.b * ny_)), 0, ny_ - 1);
  if (auto loc = try_element(ey * nx_ + ex)) return loc;
  for (int e = 0; e < element_count(); ++e)
    if (auto loc = try_element(e)) return loc;
  return std::nullopt;
}

} // namespace plyimpact
