// Input decks: the SPEC §10 vocabulary is read as written, bad input names file, line, column and
// the expected form.
#include "plyimpact/io/deck/deck.hpp"
#include "plyimpact/io/deck/table_reader.hpp"
#include "test_paths.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <numbers>
#include <sstream>
#include <string>

namespace plyimpact::deck_tests {
namespace {

// Line numbers matter: the error cases below refer to them.
const std::string base_deck = R"(analysis = "impact"
[materials.T300_976]
E1 = 144.8e9
E2 = 9.65e9
G12 = 7.10e9
G23 = 5.92e9
nu12 = 0.30
rho = 1389.2
[laminate]
material = "T300_976"
layup = "[0_2/90_4/0_2]"
ply_thickness = 0.465e-3
[plate]
a = 0.127
b = 0.0762
[mesh]
nx = 15
ny = 11
[boundary]
x0 = "ss"
xa = "ss"
y0 = "clamped"
yb = "10101"
[impactor]
mass = 6.14
radius = 12.7e-3
E = 207e9
nu = 0.3
velocity = 1.76
[contact]
k = 0.6e9
[time]
dt = 1.0e-6
end = "auto"
)";

std::string replace_line(const std::string& text, const std::string& from, const std::string& to) {
  const auto pos = text.find(from);
  EXPECT_NE(pos, std::string::npos) << from;
  std::string out = text;
  out.replace(pos, from.size(), to);
  return out;
}

TEST(Deck, ReadsTheSpecVocabulary) {
  const Deck d = parse_deck(base_deck, "deck.toml");
  EXPECT_EQ(d.analysis, AnalysisKind::impact);
  ASSERT_EQ(d.materials.size(), 1U);
  EXPECT_EQ(d.materials[0].G13, 7.10e9); // default G13 = G12
  ASSERT_TRUE(d.laminate);
  EXPECT_EQ(d.laminate->ply_count(), 8U);
  EXPECT_NEAR(d.laminate->thickness(), 3.72e-3, 1e-15);
  EXPECT_EQ(d.mesh->nx, 15);
  EXPECT_EQ(d.mesh->mass, MassMatrix::lumped);
  const auto code = [&](Edge e) { return parse_restraint(d.boundary->find(to_string(e))->type, e)->code(); };
  EXPECT_EQ(code(Edge::x0), "01101");
  EXPECT_EQ(code(Edge::y0), "11111");
  EXPECT_EQ(code(Edge::yb), "10101");
  EXPECT_EQ(d.impactor->mass, 6.14);
  EXPECT_NEAR(d.impactor->x, 0.0635, 1e-15); // default impact point: plate centre
  EXPECT_NEAR(d.impactor->y, 0.0381, 1e-15);
  EXPECT_EQ(*d.contact.k, 0.6e9);
  EXPECT_EQ(*d.time.dt, 1.0e-6);
  EXPECT_FALSE(d.time.end.has_value());
  EXPECT_EQ(d.time.end_rule, EventEnd::re_hit); // "auto": SPEC §4's rule
  EXPECT_EQ(d.time.newmark_beta, 0.25);
  EXPECT_NO_THROW(require_sections(d, AnalysisKind::impact));
}

TEST(Deck, EndSeparationChoosesTheSeparationRuleAndNoEndTime) {
  const Deck d = parse_deck(replace_line(base_deck, "end = \"auto\"", "end = \"separation\""), "deck.toml");
  EXPECT_FALSE(d.time.end.has_value());
  EXPECT_EQ(d.time.end_rule, EventEnd::separation);
}

TEST(Deck, ImpactorMassFromDensityIsTheSphereMass) {
  const Deck d = parse_deck(replace_line(base_deck, "mass = 6.14", "density = 7870.0"), "deck.toml");
  EXPECT_NEAR(d.impactor->mass, 7870.0 * 4.0 / 3.0 * 3.14159265358979 * std::pow(12.7e-3, 3), 1e-12);
}

TEST(Deck, PlyOverridesChangeMaterialAndThickness) {
  const std::string deck = base_deck + R"([materials.glass]
E1 = 40e9
E2 = 10e9
G12 = 4e9
nu12 = 0.25
rho = 2000
[[laminate.override]]
plies = [1, 8]
material = "glass"
thickness = 1e-3
)";
  const Deck d = parse_deck(deck, "deck.toml");
  EXPECT_EQ(d.laminate->material_of(0).name, "glass");
  EXPECT_EQ(d.laminate->material_of(1).name, "T300_976");
  EXPECT_EQ(d.laminate->material_of(7).name, "glass");
  EXPECT_NEAR(d.laminate->thickness(), 6 * 0.465e-3 + 2e-3, 1e-15);
}

TEST(Deck, ReferenceDirectionTurnsTheLayupInThePlatesPlane) {
  // [laminate] reference_direction: the layup's 0° along (1, 1, 0) lays [0/90]s at 45°/135°, which is
  // the [45/-45]s laminate in the plate's axes (a ply at 135° is the ply at −45°).
  const auto with = [](const std::string& layup, const std::string& direction) {
    return parse_deck(
        replace_line(base_deck, "layup = \"[0_2/90_4/0_2]\"", "layup = \"" + layup + "\"" + direction),
        "deck.toml");
  };
  const Deck turned = with("[0/90]s", "\nreference_direction = [1, 1, 0]");
  const Deck plain = with("[45/-45]s", "");
  EXPECT_NEAR(turned.laminate_spec->reference_angle, 45.0, 1e-12);
  EXPECT_LT((turned.laminate->D() - plain.laminate->D()).norm(), 1e-12 * plain.laminate->D().norm());
  EXPECT_LT((turned.laminate->A() - plain.laminate->A()).norm(), 1e-12 * plain.laminate->A().norm());
  const auto error = [&](const std::string& direction) {
    try {
      (void)with("[0/90]s", "\nreference_direction = " + direction);
    } catch (const DeckError& e) {
      return std::string(e.what());
    }
    return std::string("(no error)");
  };
  EXPECT_NE(error("[1, 0, 0.5]").find("leaves the plate's plane (z = 0)"), std::string::npos);
  EXPECT_NE(error("[0, 0, 0]").find("the zero vector"), std::string::npos);
  EXPECT_NE(error("[1, 0]").find("must be a vector [x, y, z]"), std::string::npos);
}

struct BadDeck {
  const char* name;
  std::string from, to; // line edit applied to base_deck ("" = append `to`)
  std::string expected; // substring of the message, with location
};

class DeckErrors : public ::testing::TestWithParam<BadDeck> {};

TEST_P(DeckErrors, NameFileLineColumnAndWhatWasExpected) {
  const BadDeck& c = GetParam();
  const std::string text = c.from.empty() ? base_deck + c.to : replace_line(base_deck, c.from, c.to);
  try {
    const Deck d = parse_deck(text, "deck.toml");
    require_sections(d, AnalysisKind::impact);
    FAIL() << "accepted";
  } catch (const DeckError& e) {
    EXPECT_NE(std::string(e.what()).find(c.expected), std::string::npos) << e.what();
  }
}

INSTANTIATE_TEST_SUITE_P(
    Deck, DeckErrors,
    ::testing::Values(
        BadDeck{"InvalidToml", "nu12 = 0.30", "nu12 = = 0.30", "deck.toml:7:"},
        BadDeck{"UnknownKey", "a = 0.127", "aa = 0.127",
                "deck.toml:14:1: error: unknown key 'aa' in [plate] (did you mean 'a'?)"},
        BadDeck{"UnknownSection", "[impactor]", "[impacter]",
                "unknown key 'impacter' in [] (did you mean 'impactor'?)"},
        BadDeck{"UnknownKeyFarFromAll", "a = 0.127", "zzzzzz = 1", "expected one of: a, b"},
        BadDeck{"MissingKey", "E1 = 144.8e9\n", "",
                "deck.toml:2:1: error: missing key materials.T300_976.E1 (a number in Pa)"},
        BadDeck{"WrongType", "E1 = 144.8e9", "E1 = \"big\"",
                "deck.toml:3:6: error: materials.T300_976.E1 must be a number in Pa, got a string"},
        BadDeck{"NegativeSize", "a = 0.127", "a = -0.127", "deck.toml:14:5: error: plate.a must be positive"},
        BadDeck{"ZeroThickness", "ply_thickness = 0.465e-3", "ply_thickness = 0",
                "laminate.ply_thickness must be positive"},
        BadDeck{"NonPhysicalPoisson", "nu12 = 0.30", "nu12 = 4.0",
                "deck.toml:7:8: error: material 'T300_976' is not physical: 1 - nu12*nu21"},
        BadDeck{"NegativeModulus", "E2 = 9.65e9", "E2 = -9.65e9", "materials.T300_976.E2 must be positive"},
        BadDeck{"NonFinite", "E2 = 9.65e9", "E2 = inf", "must be a finite number"},
        BadDeck{
            "BadLayup", "layup = \"[0_2/90_4/0_2]\"", "layup = \"[0_2/90_4/0_2\"",
            "deck.toml:11:23: error: layup \"[0_2/90_4/0_2\", column 14: expected '/' between plies or ']'"},
        BadDeck{"UnknownMaterial", "material = \"T300_976\"", "material = \"T300_967\"",
                "unknown material 'T300_967' (did you mean 'T300_976'?)"},
        BadDeck{"ZeroElements", "nx = 15", "nx = 0",
                "deck.toml:17:6: error: mesh.nx must be an element count from 1 to 2000"},
        BadDeck{"FractionalElements", "nx = 15", "nx = 15.5", "mesh.nx must be an integer, got a number"},
        BadDeck{"AbsurdMesh", "nx = 15", "nx = 1000000000",
                "mesh.nx must be an element count from 1 to 2000"},
        BadDeck{"BadEdge", "x0 = \"ss\"", "x0 = \"simply\"",
                "deck.toml:20:6: error: boundary.x0 must be ss | ss-soft | clamped | free | unilateral or a "
                "5-character code"},
        BadDeck{"BadEdgeCode", "yb = \"10101\"", "yb = \"10201\"", "boundary.yb must be"},
        BadDeck{"NegativeMass", "mass = 6.14", "mass = -6.14",
                "deck.toml:25:8: error: impactor.mass must be positive"},
        BadDeck{"ZeroVelocity", "velocity = 1.76", "velocity = 0.0", "impactor.velocity must be positive"},
        BadDeck{"MassAndDensity", "mass = 6.14", "mass = 6.14\ndensity = 7870",
                "give impactor.mass or impactor.density, not both"},
        BadDeck{"ImpactOutsidePlate", "velocity = 1.76", "velocity = 1.76\nx = 0.2",
                "deck.toml:30:5: error: impact point x = 0.2 m lies outside the plate"},
        BadDeck{"ZeroTimeStep", "dt = 1.0e-6", "dt = 0.0", "deck.toml:33:6: error: time.dt must be positive"},
        BadDeck{"MassScalingWithImplicitSteps", "dt = 1.0e-6", "dt = 1.0e-6\nmass_scaling = \"rotary\"",
                "deck.toml:34:16: error: time.mass_scaling scales the lumped mass of explicit steps, but the "
                "plate's steps are implicit"},
        BadDeck{"TargetStepWithoutMassScaling", "dt = 1.0e-6", "dt = 1.0e-6\ntarget_dt = 1e-6",
                "deck.toml:34:13: error: time.target_dt is the stable step that mass scaling aims at"},
        BadDeck{"NodalMassScalingWithoutTarget", "dt = 1.0e-6",
                "dt = 1.0e-6\nintegration = \"explicit\"\nmass_scaling = \"nodal\"",
                "deck.toml:35:16: error: time.mass_scaling = \"nodal\" adds mass up to a stable step that "
                "the deck "
                "gives: add target_dt"},
        BadDeck{"StopAtEnergyErrorInPercent", "dt = 1.0e-6", "dt = 1.0e-6\nstop_at_energy_error = 5",
                "deck.toml:34:24: error: time.stop_at_energy_error is a fraction of the impact energy from 0 "
                "to 1 "
                "(0.05 stops the run at an error of 5 %), got 5"},
        BadDeck{"StopAtEnergyErrorZero", "dt = 1.0e-6", "dt = 1.0e-6\nstop_at_energy_error = 0",
                "time.stop_at_energy_error must be positive"},
        BadDeck{"MassScalingMisspelt", "dt = 1.0e-6", "dt = 1.0e-6\nmass_scaling = \"rotational\"",
                "time.mass_scaling"},
        BadDeck{"NegativeTimeStep", "dt = 1.0e-6", "dt = -1e-6", "time.dt must be positive"},
        BadDeck{"AutoMisspelt", "end = \"auto\"", "end = \"atuo\"",
                "time.end must be a positive number in s, \"auto\" or \"separation\", got \"atuo\" (did you "
                "mean \"auto\"?)"},
        BadDeck{"SeparationMisspelt", "end = \"auto\"", "end = \"seperation\"",
                "(did you mean \"separation\"?)"},
        BadDeck{"AbsurdStepCount", "end = \"auto\"", "end = 1e6", "more than the limit of 100000000 steps"},
        // Absurd sizes are refused up front (docs/robustness.md): 4e6 elements, 1e12 steps, 1e10 plies.
        BadDeck{"AbsurdElementCount", "nx = 15\nny = 11", "nx = 2000\nny = 2000",
                "deck.toml:16:1: error: mesh of 2000 x 2000 elements exceeds the limit of 1000000 elements"},
        BadDeck{"AbsurdMaxSteps", "end = \"auto\"", "max_steps = 1000000000000",
                "deck.toml:34:13: error: time.max_steps must lie between 1 and 100000000, got 1000000000000"},
        BadDeck{"AbsurdPlyCount", "layup = \"[0_2/90_4/0_2]\"", "layup = \"[0_99999/90]_99999\"",
                "column 14: expected a repeat count giving at most 100000 plies (100000 plies x 99999)"},
        BadDeck{"BadNewmarkGamma", "end = \"auto\"", "newmark_gamma = 0.4",
                "time.newmark_gamma must be at least 0.5"},
        BadDeck{"BadAnalysis", "analysis = \"impact\"", "analysis = \"explode\"",
                "deck.toml:1:12: error: analysis must be one of impact"},
        BadDeck{"MissingSection",
                "[impactor]\nmass = 6.14\nradius = 12.7e-3\nE = 207e9\nnu = 0.3\nvelocity = 1.76\n", "",
                "deck.toml: error: the impact analysis needs [impactor]"},
        BadDeck{"BadChoice", "nx = 15", "nx = 15\nmass = \"diagonal\"",
                "mesh.mass must be one of lumped | consistent, got \"diagonal\""},
        BadDeck{"BadOverride", "", "[[laminate.override]]\nplies = [9]\n",
                "laminate.override.plies: expected ply numbers from 1 to 8"},
        BadDeck{
            "RunThreadsZero", "", "[run]\nthreads = 0\n",
            "deck.toml:36:11: error: run.threads must be a whole number of threads from 1 to 1024, got 0"},
        BadDeck{"RunThreadsFraction", "", "[run]\nthreads = 1.5\n",
                "deck.toml:36:11: error: run.threads must be an integer, got a number"},
        BadDeck{"RunUnknownKey", "", "[run]\njobs = 2\n", "unknown key 'jobs' in [run]"},
        BadDeck{"VtkEveryZero", "", "[output]\nvtk_every = 0\n",
                "deck.toml:36:13: error: output.vtk_every must be a positive step count, got 0"},
        BadDeck{"VtkNotBool", "", "[output]\nvtk = \"yes\"\n",
                "deck.toml:36:7: error: output.vtk must be true or false"},
        BadDeck{"VtkPlyOutOfRange", "", "[output]\nvtk_plies = [1, 9]\n",
                "deck.toml:36:17: error: output.vtk_plies: expected a ply number from 1 to 8"},
        BadDeck{"VtkPlyHugeFloat", "", "[output]\nvtk_plies = [5e87]\n",
                "deck.toml:36:14: error: output.vtk_plies: expected a ply number from 1 to 8"},
        BadDeck{"VtkInterfaceOutOfRange", "", "[output]\nvtk_interfaces = [8]\n",
                "deck.toml:36:19: error: output.vtk_interfaces: expected an interface number from 1 to 7"},
        BadDeck{"VtkAtNegative", "", "[output]\nvtk_at = [1e-6, -2e-6]\n",
                "deck.toml:36:17: error: output.vtk_at: expected a time in s (a number >= 0)"},
        BadDeck{"VtkScaleZero", "", "[output]\nvtk_thickness_scale = 0\n",
                "output.vtk_thickness_scale must be positive"},
        BadDeck{
            "RegionUnknownLaminate", "", "[[region]]\nlaminate = \"pad\"\nx = [0.0, 0.05]\ny = [0.0, 0.03]\n",
            "deck.toml:36:12: error: region.laminate = \"pad\": no [laminates.pad] table (defined: none)"},
        BadDeck{"RegionOutsidePlate", "",
                "[laminates.pad]\nmaterial = \"T300_976\"\nlayup = \"[0/90]s\"\nply_thickness = 0.465e-3\n"
                "[[region]]\nlaminate = \"pad\"\nx = [0.0, 0.2]\ny = [0.0, 0.03]\n",
                "deck.toml:41:5: error: region.x = [0, 0.2] m reaches outside the plate (0 to 0.127 m)"},
        BadDeck{"RegionBoundsReversed", "",
                "[laminates.pad]\nmaterial = \"T300_976\"\nlayup = \"[0/90]s\"\nply_thickness = 0.465e-3\n"
                "[[region]]\nlaminate = \"pad\"\nx = [0.05, 0.0]\ny = [0.0, 0.03]\n",
                "region.x must be [x0, x1] in m with x0 < x1"},
        BadDeck{"NamedLaminateBadLayup", "",
                "[laminates.pad]\nmaterial = \"T300_976\"\nlayup = \"[0/9x]s\"\nply_thickness = 0.465e-3\n",
                "deck.toml:37:"}),
    [](const ::testing::TestParamInfo<BadDeck>& p) { return p.param.name; });

TEST(Deck, NamedLaminatesAndRegionsAreRead) {
  const Deck d = parse_deck(base_deck + R"([laminates.pad]
material = "T300_976"
layup = "[0_2/90_4/0_2]2"
ply_thickness = 0.465e-3
[[region]]
laminate = "pad"
x = [0.05, 0.08]
y = [0.02, 0.05]
)",
                            "deck.toml");
  ASSERT_EQ(d.laminates.size(), 1U);
  EXPECT_EQ(d.laminates[0].name, "pad");
  EXPECT_EQ(d.laminates[0].laminate.ply_count(), 16U);
  ASSERT_EQ(d.regions.size(), 1U);
  EXPECT_EQ(d.regions[0].laminate, 1); // all_laminates(): [laminate] first, then [laminates.NAME]
  EXPECT_EQ(d.regions[0].x_min, 0.05);
  EXPECT_EQ(d.regions[0].y_max, 0.05);
  EXPECT_EQ(all_laminates(d).size(), 2U);
}

TEST(Deck, ThresholdProbesAndDamageKeysAreRead) {
  std::string text = base_deck;
  text.replace(text.find("E1 = 144.8e9"), 12,
               "E1 = 144.8e9\nYt = 55.2e6\nYc = 294e6\nS23 = 32.94e6\nDa = 1.8");
  text += R"([damage]
criteria = ["choi-chang-matrix", "choi-chang-delamination"]
delamination_ply_n = "lower"
[threshold]
criterion = "choi-chang-matrix"
tolerance = 0.02
[[output.probe]]
x = 0.0635
y = 0.0381
interface = 7
)";
  const Deck d = parse_deck(text, "deck.toml");
  EXPECT_EQ(d.threshold.criterion, "choi-chang-matrix");
  EXPECT_EQ(d.threshold.tolerance, 0.02);
  EXPECT_TRUE(d.damage.delamination_ply_n_lower);
  ASSERT_EQ(d.probes.size(), 1U);
  EXPECT_EQ(d.probes[0].name, "interface7");
  // A criterion whose strengths the material lacks is refused when the deck is read.
  std::string no_strength = base_deck + "[damage]\ncriteria = [\"tsai-wu\"]\n";
  EXPECT_THROW((void)parse_deck(no_strength, "deck.toml"), DeckError);
}

/// The base deck with a [damage] table of `keys`.
/// base_deck with [damage] `keys`, its material given the strengths and toughnesses the progressive model
/// needs (docs/progressive_damage.md's T300/976).
Deck damage_deck(const std::string& keys) {
  std::string deck = base_deck;
  deck.replace(
      deck.find("rho = 1389.2\n"), 13,
      "rho = 1389.2\nXt = 1.5e9\nXc = 1.2e9\nYt = 55.2e6\nYc = 294.0e6\nS12 = 101.1e6\nS23 = 32.94e6\n"
      "G_ft = 91.6e3\nG_fc = 79.9e3\nG_mt = 277.0\nG_mc = 788.0\n");
  return parse_deck(deck + "[damage]\n" + keys, "deck.toml");
}

/// The message damage_deck(keys) is refused with ("no error" when it is read).
std::string damage_deck_error(const std::string& keys) {
  try {
    (void)damage_deck(keys);
  } catch (const DeckError& e) {
    return std::string(e.what());
  }
  return std::string("no error");
}

TEST(Deck, DamageIntegrationChoosesTheIteratedOrTheLaggedSecant) {
  // [damage] integration: "implicit" (default) or "lagged"; only with the progressive model.
  EXPECT_EQ(damage_deck("model = \"progressive\"\n").time.laws, Integrator::implicit);
  EXPECT_EQ(damage_deck("model = \"progressive\"\nintegration = \"lagged\"\n").time.laws, Integrator::lagged);
  const std::string misspelt = damage_deck_error("model = \"progressive\"\nintegration = \"lag\"\n");
  EXPECT_NE(misspelt.find("lagged"), std::string::npos) << misspelt;
  const std::string onset = damage_deck_error("integration = \"lagged\"\n");
  EXPECT_NE(onset.find("damage.integration belongs to the progressive damage model"), std::string::npos)
      << onset;
}

TEST(Deck, PlyLawChoosesHashinOrTheFracturePlaneAndItsDataAreChecked) {
  // [damage] ply_law: "hashin" (default) or "fracture-plane"; the latter needs G_ms and bk_exponent, and
  // reads fracture_angle in degrees.
  EXPECT_EQ(damage_deck("model = \"progressive\"\n").damage.progressive->law.law, PlyLawKind::hashin);
  const std::string missing = damage_deck_error("model = \"progressive\"\nply_law = \"fracture-plane\"\n");
  EXPECT_NE(missing.find("G_ms"), std::string::npos) << missing;
  EXPECT_NE(missing.find("bk_exponent"), std::string::npos) << missing;
  std::string deck = base_deck;
  deck.replace(deck.find("rho = 1389.2\n"), 13,
               "rho = 1389.2\nXt = 1.5e9\nXc = 1.2e9\nYt = 55.2e6\nYc = 294.0e6\nS12 = 101.1e6\n"
               "G_ft = 91.6e3\nG_fc = 79.9e3\nG_mt = 277.0\nG_ms = 788.0\nbk_exponent = 1.45\n"
               "fracture_angle = 53.0\n");
  const Deck d =
      parse_deck(deck + "[damage]\nmodel = \"progressive\"\nply_law = \"fracture-plane\"\n", "deck.toml");
  EXPECT_EQ(d.damage.progressive->law.law, PlyLawKind::fracture_plane);
  const Material& m = d.laminate->material_of(0);
  EXPECT_EQ(*m.toughness.G_ms, 788.0);
  EXPECT_EQ(*m.toughness.bk_exponent, 1.45);
  EXPECT_NEAR(*m.strength.fracture_angle, 53.0 * std::numbers::pi / 180.0, 1e-15);
  std::string flat = deck;
  flat.replace(flat.find("fracture_angle = 53.0"), 21, "fracture_angle = 0.92");
  try {
    (void)parse_deck(flat, "deck.toml");
    FAIL() << "a fracture angle in radians was read";
  } catch (const DeckError& e) {
    EXPECT_NE(std::string(e.what()).find("between 45 and 90 deg"), std::string::npos) << e.what();
  }
  const std::string misspelt = damage_deck_error("model = \"progressive\"\nply_law = \"puck\"\n");
  EXPECT_NE(misspelt.find("fracture-plane"), std::string::npos) << misspelt;
}

TEST(Deck, OversizeElementsChooseBetweenTheErrorAndLoweredStrengths) {
  // [damage] oversize: "error" (default) or "reduce-strength"; only with the progressive model.
  EXPECT_FALSE(
      damage_deck("model = \"progressive\"\n").damage.progressive->reduce_strengths_above_band_limit);
  EXPECT_TRUE(damage_deck("model = \"progressive\"\noversize = \"reduce-strength\"\n")
                  .damage.progressive->reduce_strengths_above_band_limit);
  const std::string misspelt = damage_deck_error("model = \"progressive\"\noversize = \"reduce\"\n");
  EXPECT_NE(misspelt.find("reduce-strength"), std::string::npos) << misspelt;
  const std::string onset = damage_deck_error("oversize = \"reduce-strength\"\n");
  EXPECT_NE(onset.find("damage.oversize belongs to the progressive damage model"), std::string::npos)
      << onset;
}

std::string threshold_example() {
  std::ifstream in(std::string(PLYIMPACT_SOURCE_DIR) + "/examples/threshold-matrix-damage.toml");
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

/// The error parse_deck gives for `text`, or "(no error)".
std::string deck_error(const std::string& text) {
  try {
    (void)parse_deck(text, "deck.toml");
  } catch (const DeckError& e) {
    return e.what();
  }
  return "(no error)";
}

/// "deck.toml:N:" for the 1-based line N of `text` that starts with `start`.
std::string line_of(const std::string& text, const std::string& start) {
  const auto at = text.find("\n" + start);
  EXPECT_NE(at, std::string::npos) << start;
  return "deck.toml:" +
         std::to_string(std::count(text.begin(), text.begin() + static_cast<long>(at) + 1, '\n') + 1) + ":";
}

TEST(Deck, DamageThresholdCriteriaAreReadAndChecked) {
  const std::string text = threshold_example();
  EXPECT_EQ(parse_deck(text, "deck.toml").threshold.criterion, "matrix-damage");
  // With the onset model the plies never crack: an error at the criterion that says what to set.
  const std::string onset = replace_line(text, "model = \"progressive\"", "model = \"onset\"");
  const std::string e = deck_error(onset);
  EXPECT_NE(e.find(line_of(onset, "criterion = ")), std::string::npos) << e;
  EXPECT_NE(e.find("threshold.criterion = \"matrix-damage\" looks for ply damage, which only the progressive "
                   "damage model computes: set [damage] model = \"progressive\""),
            std::string::npos)
      << e;
  // "damage-area" needs its limit, and a limit needs "damage-area".
  const std::string no_limit =
      replace_line(text, "criterion = \"matrix-damage\"", "criterion = \"damage-area\"");
  EXPECT_NE(
      deck_error(no_limit).find("threshold.criterion = \"damage-area\" needs threshold.damage_area, the "
                                "projected damaged area to exceed (in m^2)"),
      std::string::npos)
      << deck_error(no_limit);
  const std::string limit = no_limit + "damage_area = 5e-6\n";
  EXPECT_EQ(parse_deck(limit, "deck.toml").threshold.damage_area, 5e-6);
  const std::string stray = text + "damage_area = 5e-6\n";
  const std::string s = deck_error(stray);
  EXPECT_NE(s.find(line_of(stray, "damage_area = ")), std::string::npos) << s;
  EXPECT_NE(s.find("threshold.damage_area is the limit of criterion = \"damage-area\", but the criterion is "
                   "\"matrix-damage\""),
            std::string::npos)
      << s;
  // A misspelt name is offered the damage criteria too.
  const std::string typo = replace_line(text, "\"matrix-damage\"", "\"matrix-damag\"");
  EXPECT_NE(deck_error(typo).find("unknown criterion \"matrix-damag\" (did you mean \"matrix-damage\"?)"),
            std::string::npos)
      << deck_error(typo);
}

TEST(Deck, TheDamageAreaLimitIsInSquareMillimetresInMillimetreDecks) {
  const Deck d = parse_deck(R"(units = "mm-N-MPa-tonne"
[damage]
model = "progressive"
[threshold]
criterion = "damage-area"
damage_area = 5.0
)",
                            "deck.toml");
  EXPECT_DOUBLE_EQ(d.threshold.damage_area.value(), 5e-6);
}

TEST(Deck, UnreadableFileIsAClearError) {
  try {
    (void)load_deck("/nonexistent/deck.toml");
    FAIL();
  } catch (const DeckError& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent/deck.toml: error: cannot open"), std::string::npos);
  }
}

TEST(Deck, EditDistanceCountsSingleEdits) {
  EXPECT_EQ(edit_distance("impacter", "impactor"), 1U);
  EXPECT_EQ(edit_distance("E1", "e1"), 0U);
  EXPECT_EQ(edit_distance("", "abc"), 3U);
}

TEST(Deck, ParaViewAndReportKeysAreRead) {
  const Deck none = parse_deck(base_deck, "deck.toml");
  EXPECT_FALSE(none.vtk.enabled);
  const Deck d =
      parse_deck(base_deck + "[output]\nvtk = true\nreport_displacements_at = 2e-5\n", "deck.toml");
  EXPECT_TRUE(d.vtk.enabled);
  EXPECT_EQ(d.vtk.every, VtkOutputSettings::default_every); // vtk = true alone: every 100 steps
  EXPECT_EQ(*d.report_displacements_at, 2e-5);
  const Deck at = parse_deck(base_deck + "[output]\nvtk_at = [1e-5, 3e-5]\nvtk_plies = [1, "
                                         "8]\nvtk_interfaces = [7]\nvtk_thickness_scale = 10\n",
                             "deck.toml");
  EXPECT_TRUE(at.vtk.enabled); // asking for times switches the output on
  EXPECT_EQ(at.vtk.every, 0);  // ... and only those times
  EXPECT_EQ(at.vtk.at, (std::vector<double>{1e-5, 3e-5}));
  EXPECT_EQ(at.vtk.plies, (std::vector<int>{1, 8}));
  EXPECT_EQ(at.vtk.interfaces, (std::vector<int>{7}));
  EXPECT_EQ(at.vtk.thickness_scale, 10.0);
}

} // namespace
} // namespace plyimpact::deck_tests
