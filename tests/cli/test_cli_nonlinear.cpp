// The command line for large deflections (SPEC §8): `static --nonlinear` and the deck key
// `nonlinear = true` write `load_deflection`; bad values of the new keys point at the deck line.
#include "support/cli.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <string>

namespace cli_nonlinear_tests {

namespace {

using namespace plyimpact::test;

fs::path write_deck(const std::string& name, const std::string& top) {
  const fs::path dir = fs::temp_directory_path() / ("plyimpact-cli-nl-" + name);
  fs::remove_all(dir);
  fs::create_directories(dir);
  std::ofstream(dir / "deck.toml") << top << R"(
analysis = "static"
[materials.al]
E1 = 70e9
E2 = 70e9
G12 = 26.9e9
nu12 = 0.3
rho = 2700.0
[laminate]
material = "al"
layup = "[0]"
ply_thickness = 1e-3
[plate]
a = 0.1
b = 0.1
[mesh]
nx = 4
ny = 4
element = "q9"
[boundary]
x0 = "clamped"
xa = "clamped"
y0 = "clamped"
yb = "clamped"
[load]
pressure = 2.0e5
)";
  return dir;
}

TEST(CliNonlinear, StaticFlagWritesTheLoadDeflectionCurve) {
  const fs::path dir = write_deck("flag", "load_steps = 4");
  const CommandResult lin = run("static " + (dir / "deck.toml").string() + " -o " + (dir / "lin").string());
  ASSERT_EQ(lin.status, 0) << lin.out;
  const CommandResult nl =
      run("static --nonlinear " + (dir / "deck.toml").string() + " -o " + (dir / "out").string());
  ASSERT_EQ(nl.status, 0) << nl.out;
  const nlohmann::json j = read_json(dir / "out" / "summary.json");
  const nlohmann::json jl = read_json(dir / "lin" / "summary.json");
  ASSERT_TRUE(j.contains("load_deflection"));
  const auto& curve = j["load_deflection"];
  ASSERT_EQ(curve.size(), 5U); // [0, 0] and four load steps
  EXPECT_EQ(curve[0][0].get<double>(), 0.0);
  EXPECT_EQ(curve[4][0].get<double>(), 1.0);
  EXPECT_DOUBLE_EQ(curve[4][1].get<double>(), j["center_deflection"].get<double>());
  // w ≈ 0.9 h linear: membrane stiffening lowers the deflection, and the curve rises monotonically.
  EXPECT_LT(j["center_deflection"].get<double>(), 0.9 * jl["center_deflection"].get<double>());
  for (std::size_t i = 1; i < curve.size(); ++i)
    EXPECT_GT(curve[i][1].get<double>(), curve[i - 1][1].get<double>());
}

TEST(CliNonlinear, DeckKeySwitchesTheAnalysis) {
  const fs::path dir = write_deck("key", "nonlinear = true\nstrain_measure = \"green-lagrange\"");
  const CommandResult r = run((dir / "deck.toml").string() + " -o " + (dir / "out").string());
  ASSERT_EQ(r.status, 0) << r.out;
  const nlohmann::json j = read_json(dir / "out" / "summary.json");
  EXPECT_EQ(j["strain_measure"], "green-lagrange");
  EXPECT_EQ(j["load_deflection"].size(), 11U); // default 10 load steps
}

TEST(CliNonlinear, BadValuesAreReportedWithTheirLine) {
  const fs::path dir = write_deck("bad", "nonlinear = \"yes\"");
  const CommandResult r = run("static " + (dir / "deck.toml").string());
  EXPECT_EQ(r.status, 2) << r.out;
  EXPECT_NE(r.out.find("deck.toml:1:"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("true or false"), std::string::npos) << r.out;
  const fs::path dir2 = write_deck("bad2", "strain_measure = \"cubic\"");
  const CommandResult r2 = run("static " + (dir2 / "deck.toml").string());
  EXPECT_EQ(r2.status, 2) << r2.out;
  EXPECT_NE(r2.out.find("deck.toml:1:"), std::string::npos) << r2.out;
}

} // namespace

} // namespace cli_nonlinear_tests
