#include "plyimpact/analysis/contact/hertz_contact.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace plyimpact {

HertzContact::HertzContact(double k, const ContactLawParameters& law, double exponent)
    : k_(k), law_(law), n_(exponent) {
  if (law_.unloading == UnloadingLaw::elastic) {
    law_.q = n_; // unload along the loading curve, no permanent indentation
    law_.beta = 0.0;
  }
}

double HertzContact::loading(double alpha) const {
  return n_ == 1.5 ? k_ * alpha * std::sqrt(alpha) : k_ * std::pow(alpha, n_);
}

double HertzContact::force(double alpha) const {
  if (alpha <= alpha_0_) return 0.0;
  if (alpha >= alpha_m_) return loading(alpha); // (2.5) loading
  const double ratio = (alpha - alpha_0_) / (alpha_m_ - alpha_0_);
  return force_m_ * std::pow(ratio, reloading_ ? n_ : law_.q); // (2.7) reloading / (2.6) unloading
}

double HertzContact::stiffness(double alpha) const {
  if (alpha <= alpha_0_) return 0.0;
  if (alpha >= alpha_m_) return n_ == 1.5 ? 1.5 * k_ * std::sqrt(alpha) : n_ * k_ * std::pow(alpha, n_ - 1.0);
  const double span = alpha_m_ - alpha_0_;
  const double e = reloading_ ? n_ : law_.q;
  return force_m_ * e * std::pow((alpha - alpha_0_) / span, e - 1.0) / span; // SPEC §4 misprint of (2.30)
}

double HertzContact::work_to(double alpha) const {
  if (alpha <= alpha_0_) return 0.0;
  const double c = n_ == 1.5 ? 0.4 * k_ : k_ / (n_ + 1.0); // ∫ k α^n dα = k α^(n+1)/(n+1)
  const double m = n_ + 1.0;
  if (alpha_m_ <= alpha_0_) return c * (std::pow(alpha, m) - std::pow(alpha_0_, m));
  const double span = alpha_m_ - alpha_0_;
  const double e = reloading_ ? n_ : law_.q;
  const double curve = force_m_ * span / (e + 1.0); // ∫ Fm ((α − α0)/span)^e dα from α0 to αm
  if (alpha < alpha_m_) return curve * std::pow((alpha - alpha_0_) / span, e + 1.0);
  return curve + c * (std::pow(alpha, m) - std::pow(alpha_m_, m));
}

double HertzContact::work(double from, double to) const {
  return work_to(to) - work_to(from);
}

void HertzContact::commit(double alpha) {
  if (alpha > alpha_m_) {
    alpha_m_ = alpha;
    force_m_ = loading(alpha);
    alpha_0_ = alpha_m_ > law_.alpha_cr ? law_.beta * (alpha_m_ - law_.alpha_cr) : 0.0; // Tan & Sun
    reloading_ = false;
  } else if (alpha <= alpha_0_ && alpha_m_ > 0.0) {
    reloading_ = true; // full unload: the next contact reloads along Yang & Sun's curve
  }
}

ContactSolution solve_contact_force(const HertzContact& law, double alpha_free, double compliance) {
  ContactSolution s;
  const double f_max = law.force(alpha_free);
  if (f_max <= 0.0) { // no indentation even without contact force: separated
    s.alpha = alpha_free;
    return s;
  }
  // g(F) = F − law(α̂ − C F) is increasing; its root lies in [0, law(α̂)].
  double lo = 0.0, hi = f_max;
  double F = f_max;
  for (int it = 1; it <= 200; ++it) {
    const double alpha = alpha_free - compliance * F;
    const double g = F - law.force(alpha);
    if (g > 0.0)
      hi = F;
    else
      lo = F;
    const double dg = 1.0 + compliance * law.stiffness(alpha);
    double next = F - g / dg;
    if (!(next > lo && next < hi)) next = 0.5 * (lo + hi); // keep Newton inside the bracket
    const double step = std::abs(next - F);
    F = next;
    s.iterations = it;
    if (step <= 1e-13 * F || hi - lo <= 1e-14 * hi) break; // well inside the required 1e-12
  }
  s.force = F;
  s.alpha = alpha_free - compliance * F;
  return s;
}

} // namespace plyimpact
