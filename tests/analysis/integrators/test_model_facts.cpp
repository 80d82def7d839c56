// What a model's run state and a policy's stepper tell the integrator and the observers as values set
// once, not as hooks (issue 78): the iteration matrix of the trials (IterationMatrixFacts, from
// ModelState::set_law_trials), the parts observers read (ModelResults), and whether a stepper follows the
// contact point alone (StepperFacts). Each is a fact of the physics: damage iterated with the step gives
// an unsymmetric tangent only where interfaces soften under mixed mode; held damage gives the matrix of the
// last trial, so a refresh waits for it; the contact point alone is exact only for the linear plate under
// a point load with the trapezoidal rule (contact_point_response.hpp).
#include "plyimpact/analysis/integrators/step_policy.hpp"
#include "plyimpact/fem/mechanical_model.hpp"
#include "support/impact_decks.hpp"

#include <gtest/gtest.h>

#include <memory>
#include <string>

namespace plyimpact::model_facts_tests {
namespace {

/// The plate of a shipped example, with the physics it names (less what the test drops).
struct ExamplePlate {
  explicit ExamplePlate(const std::string& example, bool drop_ply_damage = false)
      : description(impact_case_description(parse_deck(test::example_text(example), example))) {
    if (drop_ply_damage) description.progressive_damage.reset();
    impact = std::make_unique<ImpactCase>(description);
  }
  [[nodiscard]] std::unique_ptr<MechanicalModel> model() const {
    PlatePhysics physics;
    physics.ply_damage = description.progressive_damage;
    physics.interfaces = description.delamination;
    return mechanical_model(impact->model(), physics);
  }

  ImpactCaseDescription description;
  std::unique_ptr<ImpactCase> impact;
};

bool operator==(const IterationMatrixFacts& a, const IterationMatrixFacts& b) {
  return a.symmetric == b.symmetric && a.refresh_at_next_trial == b.refresh_at_next_trial;
}

constexpr IterationMatrixFacts symmetric_at_once{true, false};
constexpr IterationMatrixFacts symmetric_after_the_next_trial{true, true};
constexpr IterationMatrixFacts unsymmetric_after_the_next_trial{false, true};

TEST(ModelFacts, TheElasticPlateHasASymmetricMatrixAndNothingForObservers) {
  const ExamplePlate plate("thesis-3.6-v268.toml");
  const std::unique_ptr<MechanicalModel> model = plate.model(); // the state refers to it
  const std::unique_ptr<ModelState> state = model->virgin_state();
  EXPECT_TRUE(state->set_law_trials(LawTrials::advance) == symmetric_at_once);
  EXPECT_TRUE(state->set_law_trials(LawTrials::hold) == symmetric_at_once);
  EXPECT_EQ(state->results().ply_damage, nullptr);
  EXPECT_EQ(state->results().interfaces, nullptr);
  EXPECT_EQ(state->results().dissipated_energy(), 0.0);
}

TEST(ModelFacts, HeldPlyDamageRefreshesAfterTheNextTrialAndItsPliesAreObserved) {
  const ExamplePlate plate("damage-progressive.toml");
  const std::unique_ptr<MechanicalModel> model = plate.model(); // the state refers to it
  const std::unique_ptr<ModelState> state = model->virgin_state();
  EXPECT_TRUE(state->set_law_trials(LawTrials::advance) == symmetric_at_once);
  EXPECT_TRUE(state->set_law_trials(LawTrials::hold) == symmetric_after_the_next_trial);
  EXPECT_NE(state->results().ply_damage, nullptr);
  EXPECT_EQ(state->results().interfaces, nullptr);
  EXPECT_EQ(state->results().dissipated_energy(), 0.0); // virgin
}

TEST(ModelFacts, InterfacesIteratedWithTheStepGiveAnUnsymmetricTangentAndHeldOnesDoNot) {
  const ExamplePlate plate("impact-delamination-damage.toml", true);
  const std::unique_ptr<MechanicalModel> model = plate.model(); // the state refers to it
  const std::unique_ptr<ModelState> state = model->virgin_state();
  EXPECT_TRUE(state->set_law_trials(LawTrials::advance) == unsymmetric_after_the_next_trial);
  EXPECT_TRUE(state->set_law_trials(LawTrials::hold_step_mean) == symmetric_after_the_next_trial);
  EXPECT_EQ(state->results().ply_damage, nullptr);
  EXPECT_NE(state->results().interfaces, nullptr);
}

TEST(ModelFacts, AStackWithCrackingPliesShowsBothItsPliesAndItsInterfaces) {
  const ExamplePlate plate("impact-delamination-damage.toml");
  const std::unique_ptr<MechanicalModel> model = plate.model(); // the state refers to it
  const std::unique_ptr<ModelState> state = model->virgin_state();
  EXPECT_TRUE(state->set_law_trials(LawTrials::hold_step_mean) == symmetric_after_the_next_trial);
  EXPECT_NE(state->results().ply_damage, nullptr);
  EXPECT_NE(state->results().interfaces, nullptr);
}

TEST(StepperFacts, TheContactPointAloneWhereItSufficesAndIsExact) {
  const ExamplePlate plate("thesis-3.6-v268.toml");
  const Impactor& impactor = plate.description.impactor;
  StepPolicyOptions trapezoid; // β = ¼, γ = ½, a point load
  const std::unique_ptr<StepPolicy> linear = step_policy(plate.impact->model(), trapezoid, PlatePhysics{});
  EXPECT_TRUE(linear->start(impactor, true)->contact_point_only());
  EXPECT_FALSE(linear->start(impactor, false)->contact_point_only());
  StepPolicyOptions damped = trapezoid;
  damped.newmark = NewmarkCoefficients(1e-6, 0.3025, 0.6); // not the trapezoid: the energy is not known
  EXPECT_FALSE(step_policy(plate.impact->model(), damped, PlatePhysics{})
                   ->start(impactor, true)
                   ->contact_point_only());
  PlatePhysics large_deflection;
  large_deflection.large_deflection = NonlinearImpactSettings{};
  const std::unique_ptr<StepPolicy> newton = step_policy(plate.impact->model(), trapezoid, large_deflection);
  const std::unique_ptr<PlateStepper> stepper = newton->start(impactor, true);
  EXPECT_FALSE(stepper->contact_point_only());
  EXPECT_TRUE(stepper->statistics().has_value()); // Newton's counts, kept by the stepper
  EXPECT_FALSE(linear->start(impactor, false)->statistics().has_value());
}

} // namespace
} // namespace plyimpact::model_facts_tests
