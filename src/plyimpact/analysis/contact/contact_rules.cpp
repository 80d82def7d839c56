#include "plyimpact/analysis/contact/contact_rules.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace plyimpact {

double contact_radius(const Impactor& impactor, double alpha) {
  const double a = std::max(alpha, 0.0);
  switch (impactor.nose) {
  case NoseShape::hemisphere:
    return std::sqrt(impactor.radius * a);
  case NoseShape::flat: // the whole end from the first touch on (and the load's shape, even at F = 0)
    return impactor.radius;
  case NoseShape::cone:
    return 2.0 / std::numbers::pi * a * std::tan(impactor.half_angle);
  }
  return 0.0;
}

double automatic_contact_stiffness(const Impactor& impactor, const Laminate& laminate) {
  const double E2 = laminate.material_of(0).E2;
  if (impactor.nose == NoseShape::hemisphere)
    return hertz_constant(impactor.radius, impactor.E, impactor.nu, E2);
  const double E_star = 1.0 / ((1.0 - impactor.nu * impactor.nu) / impactor.E + 1.0 / E2);
  if (impactor.nose == NoseShape::flat) return 2.0 * impactor.radius * E_star;
  return 2.0 / std::numbers::pi * std::tan(impactor.half_angle) * E_star;
}

double rigid_target_indentation(double mass, double velocity, double k, double exponent) {
  if (exponent == 1.5) return std::pow(5.0 * mass * velocity * velocity / (4.0 * k), 0.4); // energy balance
  return std::pow((exponent + 1.0) * mass * velocity * velocity / (2.0 * k), 1.0 / (exponent + 1.0));
}

double hertz_contact_time(double mass, double velocity, double k, double exponent) {
  const double alpha_max = rigid_target_indentation(mass, velocity, k, exponent);
  if (exponent == 1.5) {
    const double beta_2_5_1_2 = std::tgamma(0.4) * std::tgamma(0.5) / std::tgamma(0.9); // B(2/5, 1/2)
    return 0.8 * beta_2_5_1_2 * alpha_max / velocity;                                   // 2.9432 α_m/v0
  }
  const double p = 1.0 / (exponent + 1.0);
  const double beta = std::tgamma(p) * std::tgamma(0.5) / std::tgamma(p + 0.5); // B(1/(n+1), 1/2)
  return 2.0 * p * beta * alpha_max / velocity;
}

double expected_contact_radius(const Impactor& impactor, double k) {
  return contact_radius(impactor, rigid_target_indentation(impactor.mass, impactor.velocity, k,
                                                           contact_exponent(impactor.nose)));
}

double automatic_time_step(double mass, double k, double velocity, double exponent) {
  const double contact_time = exponent == 1.5 ? 3.21807 * std::pow(mass * mass / (k * k * velocity), 0.2)
                                              : hertz_contact_time(mass, velocity, k, exponent);
  const double dt = contact_time / 1000.0;
  const double scale = std::pow(10.0, std::floor(std::log10(dt)) - 1.0);
  return std::floor(dt / scale) * scale;
}

} // namespace plyimpact
