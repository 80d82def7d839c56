// The shape of a delaminated area (analysis/thresholds/delamination_shape.hpp): on an ellipse sampled on a
// fine grid the long axis is the ellipse's, the aspect ratio its a/b (second moments πab³/4 and πa³b/4), a
// disc has ratio 1; no delaminated point gives no axis; angles between lines fold into [0, 90].
#include "plyimpact/analysis/thresholds/delamination_shape.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace plyimpact::delamination_shape_tests {
namespace {

/// Square cells of side h over [−L, L]², damage 1 inside the ellipse of semi-axes a, b whose a-axis makes
/// `angle_deg` with x, 0.5 outside (a process zone, not delaminated).
struct SampledEllipse {
  std::vector<std::array<Eigen::Vector2d, 4>> cells;
  std::vector<double> area, damage;
  SampledEllipse(double a, double b, double angle_deg, double L = 10e-3, double h = 0.1e-3) {
    const double c = std::cos(angle_deg * std::numbers::pi / 180.0);
    const double s = std::sin(angle_deg * std::numbers::pi / 180.0);
    const int n = static_cast<int>(std::lround(2.0 * L / h));
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) {
        const double x0 = -L + i * h, y0 = -L + j * h;
        cells.push_back({Eigen::Vector2d(x0, y0), Eigen::Vector2d(x0 + h, y0),
                         Eigen::Vector2d(x0 + h, y0 + h), Eigen::Vector2d(x0, y0 + h)});
        area.push_back(h * h);
        const double x = x0 + 0.5 * h, y = y0 + 0.5 * h;
        const double u = c * x + s * y, v = -s * x + c * y; // the ellipse's own axes
        damage.push_back(u * u / (a * a) + v * v / (b * b) <= 1.0 ? 1.0 : 0.5);
      }
  }
};

TEST(DelaminationShape, AnEllipsesLongAxisAndRatioOfSemiAxes) {
  for (const double angle : {0.0, 30.0, 90.0, -60.0}) {
    const SampledEllipse e(6e-3, 2e-3, angle);
    const DelaminationShape s = delamination_shape(e.cells, e.area, e.damage);
    ASSERT_TRUE(s.axis_deg && s.aspect_ratio);
    EXPECT_NEAR(s.area, std::numbers::pi * 6e-3 * 2e-3, 0.01 * s.area) << angle;
    EXPECT_LT(s.centroid.norm(), 1e-5) << angle;
    EXPECT_NEAR(angle_between_lines_deg(*s.axis_deg, angle), 0.0, 0.5) << angle << ": " << *s.axis_deg;
    EXPECT_NEAR(*s.aspect_ratio, 3.0, 0.03) << angle;
  }
  const SampledEllipse disc(5e-3, 5e-3, 0.0);
  EXPECT_NEAR(*delamination_shape(disc.cells, disc.area, disc.damage).aspect_ratio, 1.0, 0.01);
}

TEST(DelaminationShape, OneCellsMomentsAreItsOwn) {
  // A single 3 × 1 mm cell: area 3 mm², centre (1.5, 0.5) mm, long axis x, ratio √(I_yy/I_xx) = 3 (its
  // second moments w³h/12 and wh³/12); a row of cells is not a line.
  const std::vector<std::array<Eigen::Vector2d, 4>> cell{
      {Eigen::Vector2d(0.0, 0.0), Eigen::Vector2d(3e-3, 0.0), Eigen::Vector2d(3e-3, 1e-3),
       Eigen::Vector2d(0.0, 1e-3)}};
  const DelaminationShape s = delamination_shape(cell, {3e-6}, {1.0});
  EXPECT_NEAR(s.area, 3e-6, 1e-18);
  EXPECT_NEAR((s.centroid - Eigen::Vector2d(1.5e-3, 0.5e-3)).norm(), 0.0, 1e-15);
  EXPECT_NEAR(*s.axis_deg, 0.0, 1e-9);
  EXPECT_NEAR(*s.aspect_ratio, 3.0, 1e-9);
}

TEST(DelaminationShape, NoDelaminatedPointHasNoAxis) {
  SampledEllipse e(6e-3, 2e-3, 0.0, 2e-3, 0.5e-3);
  for (double& d : e.damage)
    d = 0.999;
  const DelaminationShape s = delamination_shape(e.cells, e.area, e.damage);
  EXPECT_EQ(s.area, 0.0);
  EXPECT_FALSE(s.axis_deg);
  EXPECT_FALSE(s.aspect_ratio);
}

TEST(DelaminationShape, AnglesBetweenLinesFoldIntoZeroToNinety) {
  EXPECT_DOUBLE_EQ(angle_between_lines_deg(90.0, -90.0), 0.0);
  EXPECT_DOUBLE_EQ(angle_between_lines_deg(30.0, -45.0), 75.0);
  EXPECT_DOUBLE_EQ(angle_between_lines_deg(170.0, 0.0), 10.0);
  EXPECT_DOUBLE_EQ(angle_between_lines_deg(-80.0, 80.0), 20.0);
}

} // namespace
} // namespace plyimpact::delamination_shape_tests
