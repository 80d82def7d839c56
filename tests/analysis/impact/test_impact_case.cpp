// Which inputs make the plate of an impact case (same_plate, analysis/impact/impact_case.hpp): the cases a
// sweep may run on one plate and one factorization are those that differ only in what a run may change.
#include "plyimpact/analysis/impact/impact_case.hpp"
#include "plyimpact/fem/structured_mesh.hpp"
#include "plyimpact/io/deck/case_from_deck.hpp"
#include "plyimpact/io/deck/deck.hpp"
#include "support/impact_decks.hpp"

#include <gtest/gtest.h>

#include <memory>
#include <string>

namespace plyimpact::impact_case_tests {
namespace {

ImpactCaseDescription thesis_case(const std::string& extra = "[time]\ndt = 1.0e-6\n") {
  return impact_case_description(
      parse_deck(test::thesis_3_6_deck("mass = 0.314\nvelocity = 2.92", extra), "t.toml"));
}

TEST(SamePlate, TheImpactorAndTheContactStiffnessAreARunsToChangeAndTheMemoryGuardNone) {
  const ImpactCaseDescription a = thesis_case();
  ImpactCaseDescription b = a;
  b.impactor.mass = 1.0;
  b.impactor.velocity = 5.0;
  b.impactor.radius *= 2.0;
  b.impactor.x += 0.02; // a uniform mesh does not follow the impact point
  b.contact.k = 1e9;
  b.memory_limit_bytes = 1e9; // measured as each deck is read: a guard, not the plate
  EXPECT_TRUE(same_plate(a, b));
}

TEST(SamePlate, TheLaminateTheLawsAndTheTimeStepMakeThePlate) {
  const ImpactCaseDescription a = thesis_case();
  ImpactCaseDescription thicker = a;
  thicker.laminates.front() = Laminate(a.laminates.front().materials(), [&] {
    auto plies = a.laminates.front().plies();
    plies.front().thickness *= 1.5;
    return plies;
  }());
  EXPECT_FALSE(same_plate(a, thicker));
  ImpactCaseDescription nonlinear = a;
  nonlinear.nonlinear = NonlinearImpactSettings{};
  EXPECT_FALSE(same_plate(a, nonlinear));
  ImpactCaseDescription shorter = a;
  shorter.time.dt = 0.5e-6;
  EXPECT_FALSE(same_plate(a, shorter));
}

TEST(SamePlate, TheAutomaticTimeStepIsTheImpactorsAndSoThePlates) {
  // dt = "auto" is the contact time / 1000 of the rigid-target estimate: another velocity, another step.
  const ImpactCaseDescription a = thesis_case("");
  ImpactCaseDescription faster = a;
  faster.impactor.velocity *= 2.0;
  EXPECT_FALSE(same_plate(a, faster));
}

TEST(SamePlate, AGradedMeshFollowsTheImpactPoint) {
  ImpactCaseDescription a = thesis_case();
  a.mesh.grading = MeshGrading{};
  a.mesh.grading->size_at_impact = 2.0e-3;
  ImpactCaseDescription moved = a;
  moved.impactor.x += 0.02;
  EXPECT_FALSE(same_plate(a, moved));
  ImpactCaseDescription heavier = a;
  heavier.impactor.mass *= 2.0;
  EXPECT_TRUE(same_plate(a, heavier));
}

TEST(SamePlate, MeshesReadAgainAreComparedByContent) {
  ImpactCaseDescription a = thesis_case();
  ImpactCaseDescription b = a;
  a.mesh_from_file = std::make_shared<const Mesh>(structured_rectangle(a.plate, 6, 4));
  b.mesh_from_file = std::make_shared<const Mesh>(structured_rectangle(a.plate, 6, 4));
  EXPECT_TRUE(same_plate(a, b));
  b.mesh_from_file = std::make_shared<const Mesh>(structured_rectangle(a.plate, 6, 5));
  EXPECT_FALSE(same_plate(a, b));
}

} // namespace
} // namespace plyimpact::impact_case_tests
