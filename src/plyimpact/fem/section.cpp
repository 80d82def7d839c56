#include "plyimpact/fem/section.hpp"

#include "plyimpact/fem/quadrature.hpp"

namespace plyimpact {

SectionStiffness section_stiffness(const Laminate& laminate) {
  SectionStiffness s;
  s.C_mb.topLeftCorner<3, 3>() = laminate.A();
  s.C_mb.topRightCorner<3, 3>() = laminate.B();
  s.C_mb.bottomLeftCorner<3, 3>() = laminate.B();
  s.C_mb.bottomRightCorner<3, 3>() = laminate.D();
  s.F = laminate.F();
  return s;
}

Section section_of(const Laminate& laminate) {
  return {section_stiffness(laminate), laminate.inertia()};
}

Eigen::Matrix2d ElementSection::shear_for_other_rules() const {
  if (uniform_ != nullptr) return uniform_->F;
  Eigen::Matrix2d F = Eigen::Matrix2d::Zero();
  for (std::size_t p = 0; p < gauss3x3.size(); ++p)
    F += (gauss3x3[p].weight / 4.0) * points_[p].F; // weights sum to 4 on the parent square
  return F;
}

} // namespace plyimpact
