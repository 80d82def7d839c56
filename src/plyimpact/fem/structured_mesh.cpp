#include "plyimpact/fem/structured_mesh.hpp"

#include "plyimpact/fem/shape_functions.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace plyimpact {

namespace {

/// Grid coordinates: 2n + 1 values, the element boundaries and the mid-side nodes between them.
std::vector<double> node_lines(const std::vector<double>& lines) {
  std::vector<double> c;
  for (std::size_t k = 0; k + 1 < lines.size(); ++k) {
    c.push_back(lines[k]);
    c.push_back(0.5 * (lines[k] + lines[k + 1]));
  }
  c.push_back(lines.back());
  return c;
}

void check_lines(const std::vector<double>& lines, double length, const char* axis) {
  if (lines.size() < 2 || lines.front() != 0.0 || lines.back() != length)
    throw std::invalid_argument(std::string("structured mesh: the ") + axis +
                                " lines must run from 0 to the plate's side");
  for (std::size_t k = 1; k < lines.size(); ++k)
    if (!(lines[k] > lines[k - 1]))
      throw std::invalid_argument(std::string("structured mesh: the ") + axis + " lines must increase");
}

Mesh grid_mesh(const std::vector<double>& xs, const std::vector<double>& ys) {
  const int cols = static_cast<int>(xs.size()), rows = static_cast<int>(ys.size());
  const int nx = (cols - 1) / 2, ny = (rows - 1) / 2;
  const auto node_id = [cols](int i, int j) { return j * cols + i; };
  std::vector<Eigen::Vector2d> nodes;
  nodes.reserve(static_cast<std::size_t>(cols) * static_cast<std::size_t>(rows));
  for (int j = 0; j < rows; ++j)
    for (int i = 0; i < cols; ++i)
      nodes.emplace_back(xs[static_cast<std::size_t>(i)], ys[static_cast<std::size_t>(j)]);
  std::vector<ElementNodes> elements;
  elements.reserve(static_cast<std::size_t>(nx) * static_cast<std::size_t>(ny));
  for (int ey = 0; ey < ny; ++ey)
    for (int ex = 0; ex < nx; ++ex) {
      ElementNodes conn{};
      for (int a = 0; a < 9; ++a) {
        const auto& c = q9_node_coordinates[static_cast<std::size_t>(a)];
        conn[static_cast<std::size_t>(a)] =
            node_id(2 * ex + 1 + static_cast<int>(c[0]), 2 * ey + 1 + static_cast<int>(c[1]));
      }
      elements.push_back(conn);
    }
  Mesh mesh(std::move(nodes), std::move(elements));
  // Edge sets: the element sides on x = 0, x = a (running along y) and y = 0, y = b (along x).
  std::vector<EdgeSegment> x0, xa, y0, yb;
  for (int ey = 0; ey < ny; ++ey) {
    x0.push_back({node_id(0, 2 * ey), node_id(0, 2 * ey + 1), node_id(0, 2 * ey + 2)});
    xa.push_back({node_id(cols - 1, 2 * ey), node_id(cols - 1, 2 * ey + 1), node_id(cols - 1, 2 * ey + 2)});
  }
  for (int ex = 0; ex < nx; ++ex) {
    y0.push_back({node_id(2 * ex, 0), node_id(2 * ex + 1, 0), node_id(2 * ex + 2, 0)});
    yb.push_back({node_id(2 * ex, rows - 1), node_id(2 * ex + 1, rows - 1), node_id(2 * ex + 2, rows - 1)});
  }
  mesh.add_edge_set("x0", std::move(x0));
  mesh.add_edge_set("xa", std::move(xa));
  mesh.add_edge_set("y0", std::move(y0));
  mesh.add_edge_set("yb", std::move(yb));
  mesh.add_node_set("corners",
                    {node_id(0, 0), node_id(cols - 1, 0), node_id(cols - 1, rows - 1), node_id(0, rows - 1)});
  mesh.set_grid({nx, ny});
  return mesh;
}

} // namespace

Mesh structured_rectangle(const PlateGeometry& plate, int nx, int ny) {
  if (nx < 1 || ny < 1) throw std::invalid_argument("structured mesh: nx and ny must be at least 1");
  // x_i = a i / (2nx): the grid the thesis's program used, node by node.
  const int cols = 2 * nx + 1, rows = 2 * ny + 1;
  std::vector<double> xs, ys;
  for (int i = 0; i < cols; ++i)
    xs.push_back(plate.a * i / (cols - 1));
  for (int j = 0; j < rows; ++j)
    ys.push_back(plate.b * j / (rows - 1));
  return grid_mesh(xs, ys);
}

Mesh structured_rectangle(const PlateGeometry& plate, const std::vector<double>& x_lines,
                          const std::vector<double>& y_lines) {
  check_lines(x_lines, plate.a, "x");
  check_lines(y_lines, plate.b, "y");
  return grid_mesh(node_lines(x_lines), node_lines(y_lines));
}

std::vector<double> graded_lines(double L, double x0, double h0, double growth, double offset,
                                 double max_size) {
  if (!(h0 > 0.0) || !(growth >= 1.0) || !(x0 > 0.0 && x0 < L) || !(offset >= 0.0 && offset < 1.0) ||
      !(max_size >= h0))
    throw std::invalid_argument("graded mesh: needs h0 > 0, growth >= 1, 0 < x0 < L, 0 <= offset < 1 and "
                                "max_size >= h0");
  double start = x0 - offset * h0, end = x0 + (1.0 - offset) * h0;
  if (offset == 0.0) end = x0; // x0 on an element boundary: the elements grow from it on both sides
  if (start < 0.25 * h0) start = 0.0;
  if (end > L - 0.25 * h0) end = L;
  std::vector<double> right{end}, left{start};
  for (double h = std::min(h0 * growth, max_size); right.back() < L && right.back() + h < L - 0.5 * h;
       h = std::min(h * growth, max_size))
    right.push_back(right.back() + h);
  for (double h = std::min(h0 * growth, max_size); left.back() > 0.0 && left.back() - h > 0.5 * h;
       h = std::min(h * growth, max_size))
    left.push_back(left.back() - h);
  right.back() = L;
  left.back() = 0.0;
  std::vector<double> lines(left.rbegin(), left.rend());
  lines.insert(lines.end(), right.begin() + (lines.back() == right.front() ? 1 : 0), right.end());
  return lines;
}

} // namespace plyimpact
