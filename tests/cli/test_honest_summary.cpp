// Honest summaries (issue 17): a run cut short by time.end says so (complete: false, a reason,
// rebound_velocity and absorbed_energy null, a warning naming [time] end); an energy balance error above
// 1 % marks a run suspect; time.end shorter than dt is refused; a linear run deflected beyond 0.3 h
// suggests nonlinear = true; quantities that do not apply are null; history.csv numbers are the
// shortest round-trip text.
#include "support/cli.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdlib>
#include <sstream>
#include <string>

namespace honest_summary_tests {

namespace {

using namespace plyimpact::test;

const fs::path examples = fs::path(PLYIMPACT_SOURCE_DIR) / "examples";

/// The text of examples/NAME.toml with the first line starting with `key =` replaced by `key = value`.
/// (Plain string search: std::regex trips GCC 12's -Wmaybe-uninitialized in the sanitizer build.)
std::string example_with(const std::string& name, const std::string& key, const std::string& value) {
  std::string text = read_text(examples / (name + ".toml"));
  for (std::size_t start = 0; start < text.size();) {
    const std::size_t end = std::min(text.find('\n', start), text.size());
    const std::size_t after = text.find_first_not_of(' ', start + key.size());
    if (text.compare(start, key.size(), key) == 0 && after < end && text[after] == '=')
      return text.replace(start, end - start, key + " = " + value);
    start = end + 1;
  }
  return text;
}

/// `text` with its `criteria = [...]` list emptied.
std::string without_criteria(std::string text) {
  const std::size_t start = text.find("criteria = [");
  if (start == std::string::npos) return text;
  return text.replace(start, text.find(']', start) + 1 - start, "criteria = []");
}

/// Runs `impact DECK -o DIR/out` on `text` and returns the exit status, the output and summary.json.
struct ImpactRun {
  CommandResult result;
  nlohmann::json summary;
};
ImpactRun impact(const fs::path& dir, const std::string& text, const std::string& options = "") {
  const fs::path deck = write(dir, text);
  ImpactRun r;
  r.result = run("impact " + deck.string() + " -o " + (dir / "out").string() + options);
  if (fs::exists(dir / "out" / "summary.json")) r.summary = read_json(dir / "out" / "summary.json");
  return r;
}

// thesis-4.3 and thesis-4.6 stop at time.end = 68 µs in contact (Annex 2's "IMPACT DURATION"). The full
// decks are held by tests/reference/examples (complete false, nulls); here the same decks end at 20 µs,
// also in contact, without damage tracking, so that the test is quick.
class CutShortExample : public ::testing::TestWithParam<const char*> {};

TEST_P(CutShortExample, ReportsIncompleteWithNullReboundAndAbsorbedEnergy) {
  const std::string name = GetParam();
  const fs::path dir = scratch("cut-short-" + name);
  std::string text = example_with(name, "end", "20e-6");
  text = without_criteria(text);
  const ImpactRun r = impact(dir, text);
  ASSERT_EQ(r.result.status, 0) << r.result.out; // the run did what the deck asked; the summary says more
  const nlohmann::json& j = r.summary;
  EXPECT_FALSE(j["complete"].get<bool>());
  EXPECT_TRUE(j["rebound_velocity"].is_null()) << j["rebound_velocity"];
  EXPECT_TRUE(j["absorbed_energy"].is_null()) << j["absorbed_energy"];
  EXPECT_TRUE(j["fundamental_period"].is_null()) << j["fundamental_period"]; // not computed: end given
  EXPECT_FALSE(j.contains("stop_reason")); // it was not stopped: it reached the end it was given
  const std::string reason = j["incomplete_reason"].get<std::string>();
  EXPECT_NE(reason.find("the run ended at time.end = 2e-05 s"), std::string::npos) << reason;
  EXPECT_NE(reason.find("while the impactor is still in contact with the plate"), std::string::npos)
      << reason;
  EXPECT_NE(reason.find("Set [time] end = \"auto\""), std::string::npos) << reason;
  EXPECT_NE(r.result.out.find("plyimpact: warning: the run ended at time.end = 2e-05 s"), std::string::npos)
      << r.result.out;
  EXPECT_NE(r.result.out.find("rebound velocity           not given (the impactor has not left the plate)"),
            std::string::npos)
      << r.result.out;
  EXPECT_FALSE(j["suspect"].get<bool>());
  EXPECT_TRUE(j["suspect_reason"].is_null());
}

INSTANTIATE_TEST_SUITE_P(Thesis, CutShortExample, ::testing::Values("thesis-4.3", "thesis-4.6"),
                         [](const auto& p) {
                           return std::string(p.param).substr(7, 1) + "_" + std::string(p.param).substr(9);
                         });

TEST(HonestSummary, CoarseTimeStepOnTheSection36DeckIsSuspect) {
  // examples/thesis-3.6-v268.toml with dt = 0.1 s (the Hertz contact lasts 1.68 ms): 3 steps, a rebound
  // of 8.03 m/s from 2.68 m/s. The trapezoidal contact work balances it (-175.88 J); the contact law's
  // own work does not: an energy balance error of 176 J, 798 % of 22.05 J.
  const fs::path dir = scratch("suspect");
  const ImpactRun r = impact(dir, example_with("thesis-3.6-v268", "dt", "0.1"));
  ASSERT_EQ(r.result.status, 0) << r.result.out;
  const nlohmann::json& j = r.summary;
  EXPECT_TRUE(j["suspect"].get<bool>());
  EXPECT_NEAR(j["absorbed_energy"].get<double>(), -175.88, 0.01); // reported, and flagged
  EXPECT_NEAR(j["energy_balance_error"].get<double>(), 7.98, 1e-9);
  const std::string reason = j["suspect_reason"].get<std::string>();
  EXPECT_NE(
      reason.find("energy balance error 176 J, 798 % of the initial kinetic energy 22.05 J (tolerance 1 %)"),
      std::string::npos)
      << reason;
  EXPECT_NE(reason.find("lower [time] dt to t_c/50 = 3.365e-05 s"), std::string::npos) << reason;
  EXPECT_NE(r.result.out.find("plyimpact: warning: energy balance error 176 J"), std::string::npos)
      << r.result.out;
  EXPECT_NE(r.result.out.find("plyimpact: warning: time.dt = 0.1 s gives only 0.0168 steps"),
            std::string::npos)
      << r.result.out;
  EXPECT_NE(r.result.out.find("SUSPECT"), std::string::npos) << r.result.out;
}

TEST(HonestSummary, EndShorterThanOneTimeStepIsRefused) {
  // Refused, not clamped: Δt is fixed by the factorization of K + c0 M; nothing is run or written.
  const fs::path dir = scratch("end-before-dt");
  const ImpactRun r = impact(dir, small_deck("impact", steel_ball_impactor("dt = 1e-6\nend = 0.5e-6\n")));
  EXPECT_EQ(r.result.status, 1) << r.result.out;
  EXPECT_NE(r.result.out.find("plyimpact: error: impact: time.end = 5e-07 s is shorter than one time step, "
                              "time.dt = 1e-06 s: the first step would end past time.end"),
            std::string::npos)
      << r.result.out;
  EXPECT_FALSE(fs::exists(dir / "out" / "summary.json"));
}

/// A 0.5 mm [0/90]s plate of the small deck struck by `mass` kg at 3 m/s, to the end of the event.
std::string thin_plate(const std::string& mass) {
  std::string text = small_deck("impact", "[impactor]\nmass = " + mass + R"(
radius = 12.7e-3
E = 207e9
velocity = 3.0
[time]
dt = 2e-6
)");
  text.replace(text.find("[0_2/90_4/0_2]"), 14, "[0/90]s");
  text.replace(text.find("0.465e-3"), 8, "0.125e-3");
  return text;
}

TEST(HonestSummary, LinearRunDeflectedBeyondPointThreeThicknessesSuggestsNonlinear) {
  const fs::path dir = scratch("large-deflection");
  const ImpactRun heavy = impact(dir, thin_plate("2.0"));
  ASSERT_EQ(heavy.result.status, 0) << heavy.result.out;
  const double w = heavy.summary["peak_contact_deflection"].get<double>();
  EXPECT_GT(w, 0.3 * 0.5e-3);
  const std::string said = heavy.result.out;
  EXPECT_NE(said.find("plyimpact: warning: the peak deflection"), std::string::npos) << said;
  EXPECT_NE(said.find("times the laminate thickness h = 0.5 mm in a linear run"), std::string::npos) << said;
  EXPECT_NE(said.find("Set nonlinear = true"), std::string::npos) << said;
  bool in_summary = false;
  for (const auto& warning : heavy.summary["warnings"])
    in_summary = in_summary || warning.get<std::string>().find("laminate thickness") != std::string::npos;
  EXPECT_TRUE(in_summary);
  EXPECT_TRUE(heavy.summary["complete"].get<bool>());
  EXPECT_GT(heavy.summary["fundamental_period"].get<double>(), 0.0); // computed for the end-of-event rule

  // The Annex 2 plate (h = 3.72 mm) under a light impact stays below 0.3 h: no such warning.
  const fs::path dir2 = scratch("small-deflection");
  const ImpactRun light = impact(dir2, small_deck("impact", R"([impactor]
mass = 0.0084
radius = 6.35e-3
E = 207e9
velocity = 1.0
[time]
dt = 0.5e-6
)"));
  ASSERT_EQ(light.result.status, 0) << light.result.out;
  EXPECT_LT(light.summary["peak_contact_deflection"].get<double>(), 0.3 * 3.72e-3);
  EXPECT_EQ(light.result.out.find("laminate thickness"), std::string::npos) << light.result.out;
}

TEST(HonestSummary, HistoryNumbersAreTheShortestRoundTripText) {
  const fs::path dir = scratch("history-digits");
  const ImpactRun r = impact(dir, small_deck("impact", R"([impactor]
mass = 0.314
radius = 12.7e-3
E = 207e9
velocity = 2.5
[time]
dt = 1e-6
end = 3e-6
)"));
  std::istringstream csv(read_text(dir / "out" / "history.csv"));
  std::string header, first, second;
  std::getline(csv, header);
  std::getline(csv, first);
  std::getline(csv, second);
  EXPECT_EQ(first.substr(0, 6), "0,0,0,") << first;   // t = 0: no "0.000000000e+00"
  EXPECT_EQ(second.substr(0, 6), "1e-06,") << second; // t = 1 · dt
  // Every field is a number whose shortest round-trip text it is (formatting it again gives it back).
  std::istringstream fields(second);
  int count = 0;
  for (std::string f; std::getline(fields, f, ','); ++count) {
    char* end = nullptr;
    const double x = std::strtod(f.c_str(), &end);
    EXPECT_EQ(*end, '\0') << f;
    EXPECT_EQ(fmt::format("{}", x), f);
  }
  EXPECT_EQ(count, 10);
}

} // namespace

} // namespace honest_summary_tests
