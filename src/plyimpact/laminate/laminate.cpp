#include "plyimpact/laminate/laminate.hpp"

#include <Eigen/LU>
#include <cmath>
#include <stdexcept>

namespace plyimpact {

Laminate::Laminate(std::vector<Material> materials, std::vector<Ply> plies, double shear_correction,
                   ReducedStiffnessModel model)
    : materials_(std::move(materials)), plies_(std::move(plies)), shear_correction_(shear_correction),
      model_(model) {
  if (plies_.empty()) throw std::invalid_argument("a laminate needs at least one ply");
  for (const Ply& p : plies_) {
    if (p.material >= materials_.size()) throw std::invalid_argument("ply refers to an unknown material");
    if (!(p.thickness > 0.0)) throw std::invalid_argument("ply thickness must be positive");
    thickness_ += p.thickness;
  }
  z_.reserve(plies_.size() + 1);
  z_.push_back(-0.5 * thickness_);
  for (const Ply& p : plies_)
    z_.push_back(z_.back() + p.thickness);
  z_.back() = 0.5 * thickness_; // exact face position, no accumulated round-off

  A_.setZero();
  B_.setZero();
  D_.setZero();
  F_.setZero();
  for (std::size_t k = 0; k < plies_.size(); ++k) {
    const Material& m = materials_[plies_[k].material];
    const double theta = plies_[k].angle_deg;
    qbar_.push_back(rotate_in_plane(reduced_stiffness(m, model_), theta));
    qbar_shear_.push_back(rotate_transverse_shear(transverse_shear_stiffness(m), theta));
    const double z0 = z_[k], z1 = z_[k + 1];
    const double d1 = z1 - z0, d2 = (z1 * z1 - z0 * z0) / 2.0, d3 = (z1 * z1 * z1 - z0 * z0 * z0) / 3.0;
    A_ += qbar_[k] * d1; // (1.24)
    B_ += qbar_[k] * d2;
    D_ += qbar_[k] * d3;
    F_ += shear_correction_ * qbar_shear_[k] * d1; // (1.25)
    inertia_[0] += m.rho * d1;                     // (2.109)
    inertia_[1] += m.rho * d2;
    inertia_[2] += m.rho * d3;
  }
}

EngineeringConstants Laminate::engineering_constants() const {
  const Eigen::Matrix3d a = A_.inverse();
  const double h = thickness_;
  return {1.0 / (a(0, 0) * h), 1.0 / (a(1, 1) * h), 1.0 / (a(2, 2) * h), -a(0, 1) / a(0, 0)};
}

bool Laminate::is_symmetric(double rel_tol) const {
  return B_.cwiseAbs().maxCoeff() <= rel_tol * A_.cwiseAbs().maxCoeff() * thickness_;
}

bool Laminate::is_balanced(double rel_tol) const {
  const double scale = A_.cwiseAbs().maxCoeff();
  return std::abs(A_(0, 2)) <= rel_tol * scale && std::abs(A_(1, 2)) <= rel_tol * scale;
}

double hertz_constant(double radius, double E_impactor, double nu_impactor, double E2_plate) {
  return (4.0 / 3.0) * std::sqrt(radius) / ((1.0 - nu_impactor * nu_impactor) / E_impactor + 1.0 / E2_plate);
}

} // namespace plyimpact
