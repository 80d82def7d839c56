// Explicit central differences on a lumped mass (central_difference.hpp: CD1 to CD6).
#include "plyimpact/analysis/central_difference.hpp"

#include "plyimpact/analysis/modal_analysis.hpp"
#include "plyimpact/analysis/nonlinear_static.hpp"

#include <fmt/format.h>

#include <cmath>
#include <stdexcept>
#include <utility>

namespace plyimpact {

namespace {

/// The largest Δt accepted, as a fraction of the undamaged plate's stable step 2/ω_max (CD5).
constexpr double stable_step_fraction = 0.9;

/// The lumped mass as a diagonal; throws where M is not diagonal or a DOF carries no mass.
Eigen::VectorXd diagonal_mass(const MassOperator& M, const std::string& key) {
  if (M.diagonal().size() == 0 || !(M.diagonal().minCoeff() > 0.0))
    throw std::invalid_argument(fmt::format(
        "{} needs a diagonal mass with every DOF carrying mass: set [mesh] mass = \"lumped\"; a laminate "
        "that is not symmetric couples its lumped mass (I1 != 0), use integration = \"lagged\" for it",
        key));
  return M.diagonal();
}

} // namespace

double stable_time_step(double omega_max) {
  return stable_step_fraction * 2.0 / omega_max;
}

double explicit_highest_frequency(const SparseMatrix& K0, const MassOperator& M, const std::string& key) {
  return highest_angular_frequency(K0, diagonal_mass(M, key));
}

CentralDifference::CentralDifference(const SparseMatrix& K0, const MassOperator& M,
                                     const NewmarkCoefficients& newmark, std::string key,
                                     std::optional<double> omega_max)
    : key_(std::move(key)), dt_(newmark.dt), mass_(diagonal_mass(M, key_)),
      inverse_mass_(mass_.cwiseInverse()) {
  if (newmark.gamma != 0.5)
    throw std::invalid_argument(
        fmt::format("{} is central differences (gamma = 0.5), got [time] gamma = {}", key_, newmark.gamma));
  omega_max_ = omega_max ? *omega_max : highest_angular_frequency(K0, mass_);
  const double largest = stable_time_step(omega_max_);
  if (dt_ > largest)
    throw std::invalid_argument(
        fmt::format("{}: time.dt = {:.4g} s is above the stable step of this plate and mesh: set time.dt <= "
                    "{:.4g} s, or dt = \"auto\" ({} x 2/omega_max, omega_max = {:.4g} rad/s; finer elements "
                    "lower it)",
                    key_, dt_, largest, stable_step_fraction, omega_max_));
}

void CentralDifference::predict(const PlateState& s, Eigen::VectorXd& u_next) const {
  u_next = s.u + dt_ * s.v + (0.5 * dt_ * dt_) * s.a; // CD1
}

void CentralDifference::accelerate(const Eigen::VectorXd& force, long step, double t,
                                   Eigen::VectorXd& a) const {
  a = inverse_mass_.cwiseProduct(force); // CD3
  if (!std::isfinite(a.squaredNorm()))
    throw NewtonFailure(
        fmt::format("{}: non-finite acceleration in step {} (t = {:.6g} s); reduce time.dt", key_, step, t));
}

void CentralDifference::check_contact(long step, double t, const ContactSolution& cs,
                                      const ContactStep& contact, double flexibility) const {
  const double d_alpha = cs.alpha - contact.previous_indentation();
  if (cs.force <= 0.0 || contact.previous_force() <= 0.0 || d_alpha == 0.0) return;
  const double k_secant = std::abs((cs.force - contact.previous_force()) / d_alpha);
  const double omega2 = omega_max_ * omega_max_ + k_secant * flexibility; // CD6
  if (dt_ * std::sqrt(omega2) <= 2.0) return;
  throw NewtonFailure(fmt::format(
      "{}: in step {} (t = {:.6g} s) the contact spring (secant stiffness {:.4g} N/m on the impact point's "
      "lumped mass) makes time.dt = {:.4g} s unstable: set time.dt <= {:.4g} s",
      key_, step, t, k_secant, dt_, stable_time_step(std::sqrt(omega2))));
}

} // namespace plyimpact
