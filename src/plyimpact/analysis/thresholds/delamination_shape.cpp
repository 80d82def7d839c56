#include "plyimpact/analysis/thresholds/delamination_shape.hpp"

#include <cmath>
#include <numbers>

namespace plyimpact {

namespace {

/// ∫dA, ∫x dA, ∫y dA, ∫x² dA, ∫y² dA, ∫xy dA over a polygon (vertices counter-clockwise), by the shoelace
/// sums of Green's theorem.
struct AreaMoments {
  double A = 0.0, Sx = 0.0, Sy = 0.0, Sxx = 0.0, Syy = 0.0, Sxy = 0.0;
  void add(const AreaMoments& m, double scale) {
    A += scale * m.A, Sx += scale * m.Sx, Sy += scale * m.Sy;
    Sxx += scale * m.Sxx, Syy += scale * m.Syy, Sxy += scale * m.Sxy;
  }
};

AreaMoments polygon_moments(const std::array<Eigen::Vector2d, 4>& p) {
  AreaMoments m;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const Eigen::Vector2d& a = p[i];
    const Eigen::Vector2d& b = p[(i + 1) % p.size()];
    const double c = a.x() * b.y() - b.x() * a.y();
    m.A += c / 2.0;
    m.Sx += (a.x() + b.x()) * c / 6.0;
    m.Sy += (a.y() + b.y()) * c / 6.0;
    m.Sxx += (a.x() * a.x() + a.x() * b.x() + b.x() * b.x()) * c / 12.0;
    m.Syy += (a.y() * a.y() + a.y() * b.y() + b.y() * b.y()) * c / 12.0;
    m.Sxy += (a.x() * b.y() + 2.0 * a.x() * a.y() + 2.0 * b.x() * b.y() + b.x() * a.y()) * c / 24.0;
  }
  return m;
}

} // namespace

DelaminationShape delamination_shape(const std::vector<std::array<Eigen::Vector2d, 4>>& cells,
                                     const std::vector<double>& area, const std::vector<double>& damage) {
  // Each delaminated cell's own moments, scaled to the area its point stands for (the cell's polygon
  // and the point's weight agree on straight-sided elements).
  AreaMoments total;
  for (std::size_t q = 0; q < damage.size(); ++q)
    if (damage[q] >= 1.0) {
      const AreaMoments cell = polygon_moments(cells[q]);
      if (cell.A > 0.0) total.add(cell, area[q] / cell.A);
    }
  DelaminationShape s;
  if (!(total.A > 0.0)) return s;
  s.area = total.A;
  s.centroid = Eigen::Vector2d(total.Sx, total.Sy) / total.A;
  // About the centroid: I_yy = ∫(x − x̄)², I_xx = ∫(y − ȳ)², I_xy = ∫(x − x̄)(y − ȳ).
  const double Iyy = total.Sxx - total.A * s.centroid.x() * s.centroid.x();
  const double Ixx = total.Syy - total.A * s.centroid.y() * s.centroid.y();
  const double Ixy = total.Sxy - total.A * s.centroid.x() * s.centroid.y();
  double phi = 0.5 * std::atan2(2.0 * Ixy, Iyy - Ixx) * 180.0 / std::numbers::pi; // DS1
  if (phi <= -90.0) phi += 180.0;
  s.axis_deg = phi + 0.0; // no −0
  const double mean = 0.5 * (Iyy + Ixx), half_gap = std::hypot(0.5 * (Iyy - Ixx), Ixy);
  s.aspect_ratio = std::sqrt((mean + half_gap) / (mean - half_gap));
  return s;
}

std::vector<DelaminationShape> delamination_shapes(const DelaminationResult& result) {
  std::vector<DelaminationShape> shapes;
  for (const std::vector<double>& damage : result.point_damage)
    shapes.push_back(delamination_shape(result.point_cells, result.point_area, damage));
  return shapes;
}

double angle_between_lines_deg(double a_deg, double b_deg) {
  const double d = std::fmod(std::abs(a_deg - b_deg), 180.0);
  return d > 90.0 ? 180.0 - d : d;
}

} // namespace plyimpact
