// Every front end drives the same engine (issue 15): a deck with nonlinear = true is non-linear in the
// threshold search and in sweeps too, and the non-linear loop gives the guard warnings of the linear one.
#include "support/cli.hpp"

#include <gtest/gtest.h>

#include <fmt/format.h>

#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace one_engine_tests {

namespace {

using namespace plyimpact::test;

/// A thin [0/90/0/90]s T300/976 plate (h = 1 mm) on a 5 × 3 q9 mesh struck by a 0.314 kg sphere: near
/// its matrix-cracking threshold the deflection is about the thickness, where membrane stiffening
/// changes the stresses.
std::string thin_plate_deck(const std::string& top, double velocity, const std::string& extra = "") {
  return top +
         fmt::format(R"(
[materials.T300_976]
E1 = 144.8e9
E2 = 9.65e9
G12 = 7.10e9
G23 = 5.92e9
nu12 = 0.30
rho = 1389.2
Yt = 55.2e6
Yc = 294.0e6
S12 = 101.1e6
S23 = 32.94e6
Da = 1.8
[laminate]
material = "T300_976"
layup = "[0/90/0/90]s"
ply_thickness = 0.125e-3
[plate]
a = 0.127
b = 0.0762
[mesh]
nx = 5
ny = 3
element = "q9"
[boundary]
x0 = "ss"
xa = "ss"
y0 = "ss"
yb = "ss"
[impactor]
mass = 0.314
radius = 12.7e-3
E = 207e9
velocity = {:.17g}
[contact]
k = 0.6e9
[damage]
criteria = ["choi-chang-matrix"]
[threshold]
criterion = "choi-chang-matrix"
tolerance = 0.01
)",
                     velocity) +
         extra;
}

std::string time_table(const std::string& dt, const std::string& end = "\"auto\"") {
  return "[time]\ndt = " + dt + "\nend = " + end + "\n";
}

/// Runs `plyimpact ARGS DIR/NAME.toml -o DIR/NAME` on `text` and returns summary.json.
nlohmann::json run_deck(const fs::path& dir, const std::string& name, const std::string& command,
                        const std::string& text) {
  const fs::path deck = dir / (name + ".toml");
  std::ofstream(deck) << text;
  const CommandResult r = run(command + " " + deck.string() + " -o " + (dir / name).string());
  EXPECT_TRUE(r.status == 0 || r.status == 3) << r.out; // 3: cut short (summary still written)
  return read_json(dir / name / "summary.json");
}

TEST(OneEngine, ThresholdOfANonlinearDeckBisectsOverNonlinearRuns) {
  const fs::path dir = scratch("engine-threshold");
  const std::string dt = time_table("2e-6");
  const nlohmann::json linear = run_deck(dir, "linear", "threshold", thin_plate_deck("", 1.0, dt));
  const nlohmann::json nonlinear =
      run_deck(dir, "nonlinear", "threshold", thin_plate_deck("nonlinear = true\n", 1.0, dt));
  const double v_lin = linear["threshold_velocity"].get<double>();
  const double upper = nonlinear["threshold_velocity"].get<double>();
  const double lower = nonlinear["lower_velocity"].get<double>();
  std::printf("  threshold: linear %.4f m/s, non-linear %.4f m/s (bracket [%.4f, %.4f])\n", v_lin, upper,
              lower, upper);
  EXPECT_GT(upper, 1.05 * v_lin); // membrane stiffening raises it (measured +15 %)
  EXPECT_LE(upper - lower, 0.01);
  // Single non-linear impact runs at the two ends of the bracket say the same: failure at the upper
  // velocity, none at the lower one.
  const nlohmann::json at_upper =
      run_deck(dir, "at-upper", "impact", thin_plate_deck("nonlinear = true\n", upper, dt));
  const nlohmann::json at_lower =
      run_deck(dir, "at-lower", "impact", thin_plate_deck("nonlinear = true\n", lower, dt));
  EXPECT_EQ(at_upper["nonlinear"], true);
  EXPECT_FALSE(at_upper["first_failures"].empty());
  EXPECT_TRUE(at_lower["first_failures"].empty());
  EXPECT_EQ(at_upper["first_failures"][0]["time"], nonlinear["first_failure"]["time"]);
}

TEST(OneEngine, SweepRowOfANonlinearDeckIsItsImpactRunBitForBit) {
  const fs::path dir = scratch("engine-sweep");
  const std::string dt = time_table("2e-6");
  const fs::path deck = dir / "sweep.toml";
  std::ofstream(deck) << thin_plate_deck("nonlinear = true\nanalysis = \"impact\"\n", 1.0, dt);
  const CommandResult s = run("sweep " + deck.string() + " --set impactor.velocity=0.8,1.2 --jobs 1 -o " +
                              (dir / "sweep").string());
  ASSERT_EQ(s.status, 0) << s.out;
  const std::string table = read_text(dir / "sweep" / "sweep.csv");
  const nlohmann::json alone =
      run_deck(dir, "alone", "impact", thin_plate_deck("nonlinear = true\n", 1.2, dt));
  EXPECT_EQ(alone["nonlinear"], true);
  // Row 2 (v = 1.2): the peak force column is the third after the case and the swept value.
  const std::string row = table.substr(table.find("\n1,") + 1);
  std::vector<std::string> cells;
  std::stringstream ss(row.substr(0, row.find('\n')));
  for (std::string cell; std::getline(ss, cell, ',');)
    cells.push_back(cell);
  ASSERT_GE(cells.size(), 4U) << row;
  EXPECT_EQ(cells[2], "ok");
  EXPECT_EQ(std::stod(cells[3]), alone["peak_force"].get<double>()) << table;
}

TEST(OneEngine, NonlinearRunGivesTheGuardWarningsOfTheLinearOne) {
  // Δt = 0.1 ms over a contact of about 1 ms, impact point on the corner of four elements of a 4 × 4
  // mesh, elements 15 times the contact radius, end = 0.3 ms during the contact: both runs warn about
  // all four, on stderr and in summary.json.
  const fs::path dir = scratch("engine-warnings");
  const std::string coarse = time_table("1e-4", "3e-4");
  std::string even = thin_plate_deck("", 1.0, coarse);
  even.replace(even.find("nx = 5\nny = 3"), 13, "nx = 4\nny = 4");
  even.replace(even.find("k = 0.6e9"), 9,
               "k = 0.6e9\nload = \"point\""); // the corner warning is the point load's
  const nlohmann::json linear = run_deck(dir, "linear", "impact", even);
  const nlohmann::json nonlinear = run_deck(dir, "nonlinear", "impact", "nonlinear = true\n" + even);
  ASSERT_EQ(linear["warnings"].size(), 4U) << linear.dump(1);
  ASSERT_EQ(nonlinear["warnings"].size(), 4U) << nonlinear.dump(1);
  for (std::size_t i = 0; i < 3; ++i) // the fourth gives each run's own contact force at the end
    EXPECT_EQ(nonlinear["warnings"][i], linear["warnings"][i]);
  EXPECT_NE(nonlinear["warnings"][3].get<std::string>().find("is still in contact"), std::string::npos);
  EXPECT_NE(linear["warnings"][0].get<std::string>().find("time.dt = 0.0001 s gives only"),
            std::string::npos);
  EXPECT_NE(linear["warnings"][1].get<std::string>().find("lies on an element corner"), std::string::npos);
  EXPECT_NE(linear["warnings"][2].get<std::string>().find("the contact is not resolved"), std::string::npos);
  EXPECT_NE(linear["warnings"][3].get<std::string>().find("is still in contact"), std::string::npos);
  const CommandResult r = run("impact --nonlinear " + (dir / "linear.toml").string() + " -o " +
                              (dir / "nonlinear-option").string());
  EXPECT_NE(r.out.find("plyimpact: warning: time.dt"), std::string::npos) << r.out;
}

} // namespace

} // namespace one_engine_tests
