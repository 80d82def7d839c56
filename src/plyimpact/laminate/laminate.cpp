#include "plyimpact/laminate/laminate.hpp"

#include <Eigen/LU>
#include <fmt/format.h>

#include <cmath>
#include <stdexcept>
#include <utility>

namespace plyimpact {

namespace {

/// The ply's compliance must be positive definite (thesis (1.3)): positive moduli and
/// 1 − ν12 ν21 > 0, i.e. ν12² < E1/E2. Otherwise Q and hence A, D, K are indefinite.
void check_positive_definite(const Material& m, std::size_t ply) {
  for (const auto& [name, value] : {std::pair{"E1", m.E1}, std::pair{"E2", m.E2}, std::pair{"G12", m.G12},
                                    std::pair{"G13", m.G13}, std::pair{"G23", m.G23}})
    if (!(value > 0.0 && std::isfinite(value)))
      throw std::invalid_argument(fmt::format("material '{}' of ply {}: {} = {} Pa; the moduli must be "
                                              "positive and finite for a positive-definite ply stiffness",
                                              m.name, ply + 1, name, value));
  const double nu21 = m.nu21();
  if (!(1.0 - m.nu12 * nu21 > 0.0))
    throw std::invalid_argument(fmt::format(
        "material '{}' of ply {} is not positive definite: 1 - nu12*nu21 = {:.4g} <= 0 (nu12 = {}, nu21 = "
        "nu12*E2/E1 = {:.4g}); nu12 must satisfy |nu12| < sqrt(E1/E2) = {:.4g}: lower nu12 or check E1 and "
        "E2",
        m.name, ply + 1, 1.0 - m.nu12 * nu21, m.nu12, nu21, std::sqrt(m.E1 / m.E2)));
}

} // namespace

Laminate::Laminate(std::vector<Material> materials, std::vector<Ply> plies, double shear_correction,
                   ReducedStiffnessModel model)
    : materials_(std::move(materials)), plies_(std::move(plies)), shear_correction_(shear_correction),
      model_(model) {
  if (plies_.empty()) throw std::invalid_argument("a laminate needs at least one ply");
  for (std::size_t k = 0; k < plies_.size(); ++k) {
    const Ply& p = plies_[k];
    if (p.material >= materials_.size()) throw std::invalid_argument("ply refers to an unknown material");
    if (!(p.thickness > 0.0 && std::isfinite(p.thickness)))
      throw std::invalid_argument(fmt::format("ply {} has thickness {} m: a zero or negative thickness makes "
                                              "the stiffness singular; give every ply a positive thickness "
                                              "(laminate.ply_thickness, [[laminate.override]] thickness)",
                                              k + 1, p.thickness));
    check_positive_definite(materials_[p.material], k);
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
