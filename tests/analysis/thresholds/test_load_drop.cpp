// The first load drop of a force history (analysis/thresholds/load_drop.hpp), the delamination threshold load
// F_d as a lab reads it, on histories whose answer is known by construction.
#include "plyimpact/analysis/thresholds/load_drop.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <numbers>
#include <vector>

namespace plyimpact::load_drop_tests {
namespace {

constexpr double T = 2e-3; // contact duration [s]; the loading phase is its first half
constexpr int samples = 2001;

/// A contact of duration T: the impactor moves in by W sin(πt/T), the force is `force(t)`; then 200
/// samples without contact.
std::vector<ImpactSample> contact(const std::function<double(double)>& force) {
  std::vector<ImpactSample> h;
  for (int i = 0; i < samples + 200; ++i) {
    ImpactSample s;
    s.t = T * i / (samples - 1);
    s.impactor_w = 1e-3 * std::sin(std::numbers::pi * std::min(s.t, T) / T);
    s.force = s.t < T ? force(s.t) : 0.0;
    h.push_back(s);
  }
  return h;
}

double half_sine(double t) {
  return 1e4 * std::sin(std::numbers::pi * t / T);
}

TEST(FirstLoadDrop, AnElasticHalfSineHasNone) {
  EXPECT_FALSE(first_load_drop(contact(half_sine)).has_value());
  EXPECT_FALSE(first_load_drop({}).has_value());
  EXPECT_FALSE(first_load_drop(contact([](double) { return 0.0; })).has_value()); // no contact
}

TEST(FirstLoadDrop, ThePlatesVibrationIsSmoothedAway) {
  // ±4 % of the force (the plate's response to it) at a period of a tenth of the loading phase: the raw
  // force falls by up to 8 % of what it reached (a drop by the unsmoothed rule); the window of one period
  // takes its median, the force without the vibration.
  const auto vibrating = [](double t) {
    return half_sine(t) * (1.0 + 0.04 * std::sin(2.0 * std::numbers::pi * t / (0.05 * T)));
  };
  const std::vector<ImpactSample> h = contact(vibrating);
  double reached = 0.0, deepest_fall = 0.0;
  for (const ImpactSample& s : h)
    if (s.t <= 0.5 * T) {
      reached = std::max(reached, s.force);
      deepest_fall = std::max(deepest_fall, 1.0 - s.force / reached);
    }
  EXPECT_GT(deepest_fall, 0.05);
  EXPECT_FALSE(first_load_drop(h).has_value());
}

TEST(FirstLoadDrop, ASuddenDropGivesTheForceBeforeIt) {
  // A ramp to 6 kN at 0.3 T, a fall by 30 % (a delamination), the ramp again at a third of the stiffness:
  // F_d = 6 kN at 0.3 T, found within half a window (a twentieth of the loading phase) of the fall.
  const auto dropping = [](double t) { return t <= 0.3 * T ? 1e7 * t : 4200.0 + 0.333e7 * (t - 0.3 * T); };
  const std::optional<LoadDrop> d = first_load_drop(contact(dropping));
  ASSERT_TRUE(d.has_value());
  EXPECT_NEAR(d->force, 6000.0, 1e-9 * 6000.0);
  EXPECT_NEAR(d->time, 0.3 * T, 1e-12);
  EXPECT_GT(d->detected, d->time);
  EXPECT_LE(d->detected, 0.3 * T + 0.025 * T + 1e-12);
}

TEST(FirstLoadDrop, TheFractionSaysHowLargeAFallIsADrop) {
  // A plateau at 6 kN from 0.2 T (the plate yielding), a fall of 3 % at 0.3 T, the plateau again: a drop
  // by a 2 % rule, not by the 5 % one.
  const auto plateau = [](double t) { return t <= 0.2 * T ? 1.5e7 * t : (t <= 0.3 * T ? 6000.0 : 5820.0); };
  EXPECT_FALSE(first_load_drop(contact(plateau)).has_value());
  const std::optional<LoadDrop> d = first_load_drop(contact(plateau), 0.02);
  ASSERT_TRUE(d.has_value());
  EXPECT_DOUBLE_EQ(d->force, 6000.0);
}

TEST(FirstDelamination, IsTheFirstSampleBeyondTheSeed) {
  std::vector<ImpactSample> h = contact(half_sine);
  for (ImpactSample& s : h)
    s.delaminated_area = 2e-4 + (s.t > 0.4 * T ? 1e-6 : 0.0); // a seed of 2 cm², growth at 0.4 T
  const std::optional<FirstDelamination> f = first_delamination(h);
  ASSERT_TRUE(f.has_value());
  EXPECT_GT(f->time, 0.4 * T);
  EXPECT_LT(f->time, 0.4 * T + 1.01 * T / (samples - 1));
  EXPECT_DOUBLE_EQ(f->force, half_sine(f->time));
  for (ImpactSample& s : h)
    s.delaminated_area = 2e-4;
  EXPECT_FALSE(first_delamination(h).has_value());
}

} // namespace
} // namespace plyimpact::load_drop_tests
