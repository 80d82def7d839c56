#include "plyimpact/laminate/fracture_plane.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace plyimpact {

FracturePlaneStrengths fracture_plane_strengths(const Strengths& strengths, double alpha0) {
  FracturePlaneStrengths f;
  f.Yt = *strengths.Yt;
  f.Yc = *strengths.Yc;
  f.SL = *strengths.S12;
  f.alpha0 = alpha0;
  const double c = std::cos(alpha0), s = std::sin(alpha0), t2 = std::tan(2.0 * alpha0);
  f.ST = f.Yc * c * (s + c / t2);                            // (FP3)
  f.eta_T = -1.0 / t2;                                       // (FP4)
  f.eta_L = -f.SL * std::cos(2.0 * alpha0) / (f.Yc * c * c); // (FP5)
  return f;
}

PlaneTractions tractions_on_plane(const MatrixStress& s, double alpha) {
  const double c = std::cos(alpha), n = std::sin(alpha);
  return {s.s22 * c * c + 2.0 * s.t23 * n * c, -s.s22 * n * c + s.t23 * (c * c - n * n),
          s.t12 * c + s.t13 * n}; // (FP1)
}

double fracture_plane_index(const PlaneTractions& t, const FracturePlaneStrengths& f) {
  const auto sq = [](double x) { return x * x; };
  if (t.normal >= 0.0) // (FP2), an open plane
    return sq(t.normal / f.Yt) + sq(t.transverse / f.ST) + sq(t.longitudinal / f.SL);
  return sq(t.transverse / (f.ST - f.eta_T * t.normal)) + sq(t.longitudinal / (f.SL - f.eta_L * t.normal));
}

FracturePlane critical_fracture_plane(const MatrixStress& s, const FracturePlaneStrengths& strengths) {
  constexpr double half_pi = 0.5 * std::numbers::pi;
  const bool even = s.t23 == 0.0 && s.t13 == 0.0;
  const double lowest = even ? 0.0 : -half_pi;
  const int intervals = even ? 30 : 60; // 3°
  const double step = (half_pi - lowest) / intervals;
  const auto index = [&](double a) { return fracture_plane_index(tractions_on_plane(s, a), strengths); };
  FracturePlane best{lowest, index(lowest)};
  for (int i = 1; i <= intervals; ++i) {
    const double a = lowest + i * step;
    const double f = index(a);
    if (f > best.index) best = {a, f};
  }
  // Golden-section search for the maximum in the grid's bracket about the best point.
  double lo = std::max(lowest, best.angle - step), hi = std::min(half_pi, best.angle + step);
  const double r = 0.5 * (std::sqrt(5.0) - 1.0);
  double a1 = hi - r * (hi - lo), a2 = lo + r * (hi - lo);
  double f1 = index(a1), f2 = index(a2);
  while (hi - lo > 1e-7) {
    if (f1 < f2) {
      lo = a1, a1 = a2, f1 = f2;
      a2 = lo + r * (hi - lo), f2 = index(a2);
    } else {
      hi = a2, a2 = a1, f2 = f1;
      a1 = hi - r * (hi - lo), f1 = index(a1);
    }
  }
  const double a = 0.5 * (lo + hi);
  const double f = index(a);
  if (f > best.index) best = {a, f};
  return best;
}

} // namespace plyimpact
