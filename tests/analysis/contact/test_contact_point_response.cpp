// The linear plate seen from the contact point (analysis/contact/contact_point_response.hpp): the linear
// Newmark step is linear and time-invariant in the contact forces, so a run through the impulse response at
// the contact point (CP1) must give the full run's contact history to rounding, for every impactor that
// shares the plate; the plate's energy from the trapezoidal rule's work identity must close the balance.
#include "plyimpact/analysis/contact/contact_point_response.hpp"
#include "support/impact_decks.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

namespace plyimpact::contact_point_response_tests {
namespace {

using test::thesis_3_6_deck;

/// The §3.6 plate on 8 × 6 elements under a point force, Tan–Sun contact with permanent indentation
/// (the unloading branch makes the history depend on the whole path), the end-of-event rule.
ImpactCaseDescription point_load_case(const std::string& extra = "") {
  const std::string text = thesis_3_6_deck("mass = 0.314\nvelocity = 2.92", R"(
[contact]
k = 0.6e9
alpha_cr = 1.7e-5
load = "point"
[time]
dt = 1.0e-6
)" + extra,
                                           "8, 6");
  return impact_case_description(parse_deck(text, "test.toml"));
}

/// A run that keeps no history (nothing but the contact point is needed).
RunRequest request(bool contact_point) {
  RunRequest r;
  r.history_every = 0;
  r.contact_point_response = contact_point;
  return r;
}

/// The run of `impact` with the impactor's mass and velocity replaced, full or through (CP1).
ImpactResult run_with(const ImpactCase& impact, double mass, double velocity, bool contact_point) {
  RunRequest r = request(contact_point);
  Impactor imp = impact.settings().impactor;
  imp.mass = mass;
  imp.velocity = velocity;
  r.impactor = imp;
  return impact.run(r);
}

void expect_same_event(const ImpactResult& full, const ImpactResult& convolved) {
  EXPECT_FALSE(full.contact_point_response);
  EXPECT_TRUE(convolved.contact_point_response);
  EXPECT_TRUE(full.complete);
  EXPECT_TRUE(convolved.complete);
  EXPECT_EQ(convolved.steps, full.steps); // the same end-of-event step
  EXPECT_EQ(convolved.episodes.size(), full.episodes.size());
  EXPECT_EQ(convolved.time_of_peak_force, full.time_of_peak_force);
  EXPECT_EQ(convolved.contact_duration, full.contact_duration);
  EXPECT_NEAR(convolved.peak_force, full.peak_force, 1e-10 * full.peak_force);
  EXPECT_NEAR(convolved.peak_contact_deflection, full.peak_contact_deflection,
              1e-10 * full.peak_contact_deflection);
  EXPECT_NEAR(convolved.max_indentation, full.max_indentation, 1e-10 * full.max_indentation);
  EXPECT_NEAR(convolved.permanent_indentation, full.permanent_indentation, 1e-10 * full.max_indentation);
  ASSERT_TRUE(full.rebound_velocity && convolved.rebound_velocity);
  EXPECT_NEAR(*convolved.rebound_velocity, *full.rebound_velocity, 1e-10 * *full.rebound_velocity);
  EXPECT_NEAR(*convolved.absorbed_energy, *full.absorbed_energy, 1e-9 * *full.absorbed_energy);
  // The plate's energy from the work of the contact force (β = ¼, γ = ½) closes the balance as the
  // kinetic and strain energies of the full run do.
  EXPECT_NEAR(convolved.energy_balance_error, full.energy_balance_error, 1e-9);
  EXPECT_EQ(convolved.dofs, full.dofs);
  std::printf("  %ld steps: peak force %.12g N (full) and %.12g N (CP1), rebound differs by %.2e\n",
              full.steps, full.peak_force, convolved.peak_force,
              *convolved.rebound_velocity / *full.rebound_velocity - 1.0);
}

TEST(ContactPointResponse, ConvolutionGivesTheFullRunsContactHistory) {
  const ImpactCase impact(point_load_case());
  const ImpactResult full = run_with(impact, 0.314, 2.92, false);
  const ImpactResult convolved = run_with(impact, 0.314, 2.92, true);
  expect_same_event(full, convolved);
  EXPECT_GT(full.peak_force, 100.0);
  EXPECT_GT(full.steps, 1000); // a whole event with the plate ringing after separation
}

TEST(ContactPointResponse, OneResponseServesEveryImpactorOnThePlate) {
  // The impulse response does not depend on the impactor's mass or speed: runs of other impactors on the
  // same case reuse it and still give their own full runs' events.
  const ImpactCase impact(point_load_case());
  for (const auto& [mass, velocity] : {std::pair{0.314, 2.92}, {2.0, 1.0}, {0.05, 6.0}}) {
    SCOPED_TRACE(mass);
    expect_same_event(run_with(impact, mass, velocity, false), run_with(impact, mass, velocity, true));
  }
}

TEST(ContactPointResponse, FullRunWhereTheConvolutionIsNotExactOrTheFieldIsWatched) {
  // The Hertz pressure's load depends on the indentation (not a convolution), another Newmark rule has
  // no exact energy from the contact point, and a run with history looks at the plate.
  for (const char* extra :
       {"[contact]\nload = \"hertz-pressure\"\n",
        "[contact]\nload = \"point\"\n[time]\nnewmark_beta = 0.3\nnewmark_gamma = 0.6\n"}) {
    SCOPED_TRACE(extra);
    const std::string text = thesis_3_6_deck("mass = 0.314\nvelocity = 2.92", extra, "8, 6");
    const ImpactCase impact(impact_case_description(parse_deck(text, "test.toml")));
    EXPECT_FALSE(run_with(impact, 0.314, 2.92, true).contact_point_response);
  }
  const ImpactCase impact(point_load_case());
  RunRequest with_history = request(true);
  with_history.history_every = 1;
  EXPECT_FALSE(impact.run(with_history).contact_point_response);
}

TEST(ContactPointResponse, TheImpulseRunStartsWithTheUnitForceAndGrowsInChunks) {
  std::vector<double> forces;
  const ContactPointResponse g([&forces](double force) {
    forces.push_back(force);
    return static_cast<double>(forces.size());
  });
  EXPECT_EQ(g.at_least(3)->size(), 256U);
  EXPECT_EQ(forces.front(), 1.0);
  EXPECT_EQ(std::count(forces.begin(), forces.end(), 0.0), 255);
  EXPECT_EQ(g.at_least(200)->size(), 256U); // no new step
  EXPECT_EQ(g.at_least(257)->size(), 512U);
  EXPECT_EQ(g.at_least(5000)->size(), 5000U);
  EXPECT_EQ(g.at_least(5001)->size(), 5312U); // a sixteenth of 5000 ahead
  EXPECT_EQ(forces.size(), 5312U);
  EXPECT_EQ((*g.at_least(1))[5311], 5312.0);
}

} // namespace
} // namespace plyimpact::contact_point_response_tests
