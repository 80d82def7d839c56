#include "plyimpact/fem/mesh.hpp"

#include "plyimpact/fem/quadrature.hpp"
#include "plyimpact/fem/shape_functions.hpp"

#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace plyimpact {

double BoundingBox::size() const {
  return std::max(x_max - x_min, y_max - y_min);
}

Mesh::Mesh(std::vector<Eigen::Vector2d> nodes, std::vector<ElementNodes> elements)
    : nodes_(std::move(nodes)), elements_(std::move(elements)) {
  for (const ElementNodes& conn : elements_)
    for (const int n : conn)
      if (n < 0 || n >= node_count())
        throw std::invalid_argument("mesh: element node " + std::to_string(n) + " does not exist (" +
                                    std::to_string(node_count()) + " nodes)");
  classify_shapes();
  build_locator();
}

ElementCoordinates Mesh::element_coordinates(int e) const {
  ElementCoordinates xy;
  const ElementNodes& conn = element_nodes(e);
  for (int a = 0; a < 9; ++a)
    xy.row(a) = node(conn[static_cast<std::size_t>(a)]).transpose();
  return xy;
}

void Mesh::add_node_set(const std::string& name, std::vector<int> nodes) {
  for (const int n : nodes)
    if (n < 0 || n >= node_count())
      throw std::invalid_argument("mesh: node set '" + name + "' names node " + std::to_string(n) +
                                  ", which does not exist");
  std::sort(nodes.begin(), nodes.end());
  nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
  if (!node_sets_.emplace(name, std::move(nodes)).second)
    throw std::invalid_argument("mesh: node set '" + name + "' is defined twice");
}

void Mesh::add_edge_set(const std::string& name, std::vector<EdgeSegment> edges) {
  std::vector<int> nodes;
  for (const EdgeSegment& s : edges)
    nodes.insert(nodes.end(), s.begin(), s.end());
  add_node_set(name, std::move(nodes));
  edge_sets_.emplace(name, std::move(edges));
}

namespace {

template <class Map>
std::string known_names(const Map& sets) {
  std::string names;
  for (const auto& [name, value] : sets)
    names += (names.empty() ? "" : ", ") + name;
  return names.empty() ? "none" : names;
}

} // namespace

const std::vector<int>& Mesh::node_set(const std::string& name) const {
  const auto it = node_sets_.find(name);
  if (it == node_sets_.end())
    throw std::out_of_range("the mesh has no node set '" + name + "' (it has: " + known_names(node_sets_) +
                            ")");
  return it->second;
}

const std::vector<EdgeSegment>& Mesh::edge_set(const std::string& name) const {
  const auto it = edge_sets_.find(name);
  if (it == edge_sets_.end())
    throw std::out_of_range("the mesh has no edge set '" + name + "' (it has: " + known_names(edge_sets_) +
                            ")");
  return it->second;
}

std::vector<std::string> Mesh::node_set_names() const {
  std::vector<std::string> names;
  for (const auto& [name, nodes] : node_sets_)
    names.push_back(name);
  return names;
}

void Mesh::move_node(int n, const Eigen::Vector2d& xy) {
  nodes_[static_cast<std::size_t>(n)] = xy;
  classify_shapes();
  build_locator();
}

void Mesh::classify_shapes() {
  // Node coordinates relative to the element's first node, compared within 1e-12 of the mesh size
  // (rounding of the node coordinates must not split a uniform grid into classes).
  bounds_ = BoundingBox{INFINITY, -INFINITY, INFINITY, -INFINITY};
  for (const Eigen::Vector2d& p : nodes_) {
    bounds_.x_min = std::min(bounds_.x_min, p.x()), bounds_.x_max = std::max(bounds_.x_max, p.x());
    bounds_.y_min = std::min(bounds_.y_min, p.y()), bounds_.y_max = std::max(bounds_.y_max, p.y());
  }
  const double tol = 1e-12 * bounds_.size();
  const auto relative = [this](int e) {
    ElementCoordinates xy = element_coordinates(e);
    const Eigen::RowVector2d origin = xy.row(0);
    xy.rowwise() -= origin;
    return xy;
  };
  shape_class_.assign(elements_.size(), -1);
  representative_.clear();
  std::vector<ElementCoordinates> shapes;
  for (int e = 0; e < element_count(); ++e) {
    const ElementCoordinates xy = relative(e);
    int found = -1;
    // Most meshes have few shapes; search the latest classes first (neighbours are alike).
    for (int c = static_cast<int>(shapes.size()) - 1; c >= 0 && found < 0; --c)
      if ((shapes[static_cast<std::size_t>(c)] - xy).cwiseAbs().maxCoeff() <= tol) found = c;
    if (found < 0) {
      found = static_cast<int>(shapes.size());
      shapes.push_back(xy);
      representative_.push_back(e);
    }
    shape_class_[static_cast<std::size_t>(e)] = found;
  }
}

void Mesh::build_locator() {
  const double w = bounds_.x_max - bounds_.x_min, h = bounds_.y_max - bounds_.y_min;
  const double cells = std::max(1.0, static_cast<double>(element_count()));
  const double side = std::sqrt(std::max(w * h, 1e-300) / cells);
  buckets_x_ = std::clamp(static_cast<int>(std::ceil(w / side)), 1, 4096);
  buckets_y_ = std::clamp(static_cast<int>(std::ceil(h / side)), 1, 4096);
  buckets_.assign(static_cast<std::size_t>(buckets_x_) * static_cast<std::size_t>(buckets_y_), {});
  const double tol = 1e-9 * bounds_.size();
  const auto bucket_x = [&](double x) {
    return std::clamp(static_cast<int>(std::floor((x - bounds_.x_min) / std::max(w, 1e-300) * buckets_x_)), 0,
                      buckets_x_ - 1);
  };
  const auto bucket_y = [&](double y) {
    return std::clamp(static_cast<int>(std::floor((y - bounds_.y_min) / std::max(h, 1e-300) * buckets_y_)), 0,
                      buckets_y_ - 1);
  };
  for (int e = 0; e < element_count(); ++e) {
    const ElementCoordinates xy = element_coordinates(e);
    const int i0 = bucket_x(xy.col(0).minCoeff() - tol), i1 = bucket_x(xy.col(0).maxCoeff() + tol);
    const int j0 = bucket_y(xy.col(1).minCoeff() - tol), j1 = bucket_y(xy.col(1).maxCoeff() + tol);
    for (int j = j0; j <= j1; ++j)
      for (int i = i0; i <= i1; ++i)
        buckets_[static_cast<std::size_t>(j) * static_cast<std::size_t>(buckets_x_) +
                 static_cast<std::size_t>(i)]
            .push_back(e);
  }
  for (auto& b : buckets_)
    std::sort(b.rbegin(), b.rend()); // highest index first (see locate)
}

Eigen::Vector2d Mesh::map(int e, double xi, double eta) const {
  return element_coordinates(e).transpose() * q9_shape(xi, eta).N;
}

double Mesh::element_area(int e) const {
  const ElementCoordinates xy = element_coordinates(e);
  double area = 0.0;
  for (const QuadraturePoint& p : gauss3x3) {
    const Q9Shape s = q9_shape(p.xi, p.eta);
    Eigen::Matrix2d J;
    J.row(0) = s.dN_dxi.transpose() * xy;
    J.row(1) = s.dN_deta.transpose() * xy;
    area += p.weight * J.determinant();
  }
  return area;
}

std::optional<PointLocation> Mesh::locate(double x, double y) const {
  const Eigen::Vector2d target(x, y);
  const double tol = 1e-10;
  // Newton on x(ξ, η) = target inside element e; converges in one step on undistorted elements.
  const auto try_element = [&](int e) -> std::optional<PointLocation> {
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
  const double w = bounds_.x_max - bounds_.x_min, h = bounds_.y_max - bounds_.y_min;
  const double margin = 1e-9 * bounds_.size();
  if (x < bounds_.x_min - margin || x > bounds_.x_max + margin || y < bounds_.y_min - margin ||
      y > bounds_.y_max + margin)
    return std::nullopt;
  const int i =
      std::clamp(static_cast<int>(std::floor((x - bounds_.x_min) / std::max(w, 1e-300) * buckets_x_)), 0,
                 buckets_x_ - 1);
  const int j =
      std::clamp(static_cast<int>(std::floor((y - bounds_.y_min) / std::max(h, 1e-300) * buckets_y_)), 0,
                 buckets_y_ - 1);
  for (const int e : buckets_[static_cast<std::size_t>(j) * static_cast<std::size_t>(buckets_x_) +
                              static_cast<std::size_t>(i)])
    if (auto loc = try_element(e)) return loc;
  // Curved element sides may bulge out of their nodes' box: try every element, highest index first.
  for (int e = element_count() - 1; e >= 0; --e)
    if (auto loc = try_element(e)) return loc;
  return std::nullopt;
}

} // namespace plyimpact
