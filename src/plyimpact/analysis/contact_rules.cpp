#include "plyimpact/analysis/contact_rules.hpp"

#include <cmath>

namespace plyimpact {

double automatic_contact_stiffness(const Impactor& impactor, const Laminate& laminate) {
  return hertz_constant(impactor.radius, impactor.E, impactor.nu, laminate.material_of(0).E2);
}

double hertz_contact_time(double mass, double velocity, double k) {
  const double alpha_max = std::pow(5.0 * mass * velocity * velocity / (4.0 * k), 0.4); // energy balance
  const double beta_2_5_1_2 = std::tgamma(0.4) * std::tgamma(0.5) / std::tgamma(0.9);   // B(2/5, 1/2)
  return 0.8 * beta_2_5_1_2 * alpha_max / velocity;                                     // 2.9432 α_m/v0
}

double expected_contact_radius(double mass, double velocity, double k, double radius) {
  const double alpha_max = std::pow(5.0 * mass * velocity * velocity / (4.0 * k), 0.4);
  return std::sqrt(radius * alpha_max);
}

double automatic_time_step(double mass, double k, double velocity) {
  const double contact_time = 3.21807 * std::pow(mass * mass / (k * k * velocity), 0.2);
  const double dt = contact_time / 1000.0;
  const double scale = std::pow(10.0, std::floor(std::log10(dt)) - 1.0);
  return std::floor(dt / scale) * scale;
}

} // namespace plyimpact
