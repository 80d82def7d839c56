#include "plyimpact/fem/loads.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace plyimpact {

Eigen::VectorXd point_load(const DiscretePlate& model, double x, double y, double force) {
  return force * model.sampler(x, y).as_vector(model.size());
}

Eigen::VectorXd pressure_load(const DiscretePlate& model, double q) {
  Eigen::VectorXd f = Eigen::VectorXd::Zero(model.size());
  for (int e = 0; e < model.mesh().element_count(); ++e)
    scatter_add(f, model.element_equations(e),
                PlateElement::pressure_load(model.mesh().element_coordinates(e), q));
  return f;
}

namespace {

/// True when the element's corners and mid-side nodes form an axis-aligned rectangle.
bool axis_aligned_rectangle(const ElementCoordinates& xy) {
  const double lx = xy(1, 0) - xy(0, 0), ly = xy(3, 1) - xy(0, 1);
  const double tol = 1e-12 * std::max(std::abs(lx), std::abs(ly));
  for (int a = 0; a < 9; ++a) {
    const auto& c = q9_node_coordinates[static_cast<std::size_t>(a)];
    const double x = xy(0, 0) + 0.5 * (c[0] + 1.0) * lx, y = xy(0, 1) + 0.5 * (c[1] + 1.0) * ly;
    if (std::abs(xy(a, 0) - x) > tol || std::abs(xy(a, 1) - y) > tol) return false;
  }
  return lx > 0.0 && ly > 0.0;
}

} // namespace

Eigen::VectorXd patch_load(const DiscretePlate& model, const PatchLoad& patch) {
  const double q = patch.force / (patch.dx * patch.dy);
  const BoundingBox& box = model.mesh().bounds();
  const double x0 = std::max(box.x_min, patch.x - patch.dx / 2),
               x1 = std::min(box.x_max, patch.x + patch.dx / 2);
  const double y0 = std::max(box.y_min, patch.y - patch.dy / 2),
               y1 = std::min(box.y_max, patch.y + patch.dy / 2);
  Eigen::VectorXd f = Eigen::VectorXd::Zero(model.size());
  for (int e = 0; e < model.mesh().element_count(); ++e) {
    const ElementCoordinates xy = model.mesh().element_coordinates(e);
    const double ex0 = xy.col(0).minCoeff(), ex1 = xy.col(0).maxCoeff(), ey0 = xy.col(1).minCoeff(),
                 ey1 = xy.col(1).maxCoeff();
    const double ox0 = std::max(x0, ex0), ox1 = std::min(x1, ex1), oy0 = std::max(y0, ey0),
                 oy1 = std::min(y1, ey1);
    if (ox1 <= ox0 || oy1 <= oy0) continue;
    if (!axis_aligned_rectangle(xy))
      throw std::invalid_argument("patch loads need axis-aligned rectangular elements under the patch");
    // 3×3 Gauss over the overlap rectangle; local coordinates by the element's affine map.
    ElementVector fe = ElementVector::Zero();
    for (const QuadraturePoint& p : gauss3x3) {
      const double x = 0.5 * (ox0 + ox1) + 0.5 * (ox1 - ox0) * p.xi;
      const double y = 0.5 * (oy0 + oy1) + 0.5 * (oy1 - oy0) * p.eta;
      const double w = p.weight * 0.25 * (ox1 - ox0) * (oy1 - oy0);
      const Q9Shape sh = q9_shape(2 * (x - ex0) / (ex1 - ex0) - 1, 2 * (y - ey0) / (ey1 - ey0) - 1);
      for (int a = 0; a < 9; ++a)
        fe(5 * a + 2) += w * q * sh.N(a);
    }
    scatter_add(f, model.element_equations(e), fe);
  }
  return f;
}

Eigen::VectorXd static_load_vector(const DiscretePlate& model, const StaticLoad& load) {
  Eigen::VectorXd f = Eigen::VectorXd::Zero(model.size());
  if (load.pressure != 0.0) f += pressure_load(model, load.pressure);
  if (load.point) f += point_load(model, load.point->x, load.point->y, load.point->force);
  if (load.patch) f += patch_load(model, *load.patch);
  return f;
}

} // namespace plyimpact
