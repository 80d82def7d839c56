// Parameter sweeps (docs/sweep.md): the [sweep] table and --set options, case numbering, the
// documented random sequence, errors before any case runs, and cases computed in-process against
// the Hertz closed form and against a stand-alone run of the same deck; progressive-damage cases
// (absorbed energy, damage dissipation and damaged area columns) against stand-alone runs; the sweep's
// report.html (its table against the closed form, its plots, failed cases, Monte Carlo scatter).
#include "plyimpact/analysis/impact/impact_case.hpp"
#include "plyimpact/io/deck/case_from_deck.hpp"
#include "plyimpact/io/results/impact_report.hpp"
#include "plyimpact/io/sweeps/sweep_runner.hpp"
#include "support/cli.hpp"
#include "test_paths.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

namespace plyimpact::sweep_tests {
namespace {

namespace fs = std::filesystem;

/// A rigid target (closed-form Hertz impact) with a [sweep] table appended.
std::string rigid_deck(const std::string& sweep) {
  return R"(analysis = "impact"
[materials.m]
E1 = 129.0e9
E2 = 7.5e9
G12 = 3.5e9
nu12 = 0.33
rho = 1540.0
[laminate]
material = "m"
layup = "[0]"
ply_thickness = 1e-3
[plate]
a = 0.1
b = 0.1
rigid = true
[impactor]
mass = 0.314
radius = 12.7e-3
E = 207e9
velocity = 2.92
[contact]
k = 0.6e9
unloading = "elastic"
[time]
dt = 0.05e-6
)" + sweep;
}

/// A small elastic plate (6 x 4 elements) struck at its centre.
std::string plate_deck(const std::string& sweep) {
  return R"([materials.T300_976]
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
nx = 6
ny = 4
[boundary]
x0 = "ss"
xa = "ss"
y0 = "ss"
yb = "ss"
[impactor]
mass = 0.314
radius = 12.7e-3
E = 207e9
velocity = 2.92
[time]
dt = 2e-6
)" + sweep;
}

std::string error_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const DeckError& e) {
    return e.what();
  }
  return "(no error)";
}

TEST(SweepSpec, ProductCountsWithTheLastKeyFastestAndBuildsEachDeck) {
  const Sweep s = Sweep::from_text(plate_deck(R"(
[sweep.values]
"impactor.velocity" = [1.0, 2.0, 3.0]
laminate.layup = ["[0/90]s", "[0_2/90_4/0_2]"]
)"),
                                   "deck.toml");
  ASSERT_EQ(s.size(), 6U);
  EXPECT_EQ(s.keys(), (std::vector<std::string>{"impactor.velocity", "laminate.layup"}));
  const SweepCase c3 = s.case_at(3); // velocity index 1, layup index 1
  EXPECT_EQ(to_text(c3.values[0]), "2");
  EXPECT_EQ(to_text(c3.values[1]), "[0_2/90_4/0_2]");
  const Deck d3 = s.deck_for(c3);
  EXPECT_EQ(d3.impactor->velocity, 2.0);
  EXPECT_EQ(d3.laminate->ply_count(), 8U);
  const Deck d4 = s.deck_for(s.case_at(4)); // velocity 3.0, [0/90]s
  EXPECT_EQ(d4.impactor->velocity, 3.0);
  EXPECT_EQ(d4.laminate->ply_count(), 4U);
  EXPECT_EQ(d4.impactor->mass, 0.314); // untouched keys keep the base deck's values
}

TEST(SweepSpec, ZipTakesListsInStepAndSetOptionsReplaceDeckAxes) {
  const Sweep s = Sweep::from_text(plate_deck(R"(
[sweep]
mode = "zip"
[sweep.values]
"impactor.velocity" = [1.0, 2.0]
"impactor.mass" = [0.5, 1.5]
)"),
                                   "deck.toml", {"impactor.mass=0.25,0.75"});
  ASSERT_EQ(s.size(), 2U);
  EXPECT_EQ(s.deck_for(s.case_at(1)).impactor->mass, 0.75);
  EXPECT_EQ(s.deck_for(s.case_at(1)).impactor->velocity, 2.0);
  const std::string e = error_of([] {
    (void)Sweep::from_text(
        plate_deck("[sweep]\nmode = \"zip\"\n[sweep.values]\n\"impactor.velocity\" = [1.0, "
                   "2.0]\n\"impactor.mass\" = [0.5]\n"),
        "deck.toml");
  });
  EXPECT_NE(
      e.find("deck.toml:34:1: error: zip sweep: impactor.mass has 1 values but impactor.velocity has 2"),
      std::string::npos)
      << e;
}

TEST(SweepSpec, RangesGiveEquallySpacedValuesWithExactEnds) {
  const auto v = parse_range("0.5:3.0:11", "x");
  ASSERT_EQ(v.size(), 11U);
  EXPECT_EQ(std::get<double>(v[0]), 0.5);
  EXPECT_EQ(std::get<double>(v[1]), 0.75); // 0.5 + 2.5/10, exact in binary
  EXPECT_EQ(std::get<double>(v[10]), 3.0);
  const auto n = parse_range("6:18:4", "x"); // integers stay integers (mesh.nx)
  ASSERT_EQ(n.size(), 4U);
  EXPECT_EQ(std::get<long>(n[1]), 10);
  EXPECT_EQ(std::get<long>(n[3]), 18);
  for (const char* bad : {"0.5:3.0", "a:3.0:11", "0.5:3.0:1", "0.5:3.0:x", "0.5:3.0:11:2", "0.5::11"}) {
    const std::string e = error_of([&] { (void)parse_range(bad, "--set 'k'"); });
    EXPECT_NE(e.find("--set 'k': error: malformed range"), std::string::npos) << bad << ": " << e;
  }
}

TEST(SweepSpec, RangeValuesAreTheShortestDecimalsNotTheirSumsFloatNoise) {
  // 0.1 + 2 (0.5 − 0.1)/4 is 0.30000000000000004 in doubles; the range gives the decimal 0.3.
  const auto v = parse_range("0.1:0.5:5", "x");
  ASSERT_EQ(v.size(), 5U);
  const char* text[] = {"0.1", "0.2", "0.3", "0.4", "0.5"};
  for (std::size_t i = 0; i < v.size(); ++i) {
    EXPECT_EQ(to_text(v[i]), text[i]);
    EXPECT_EQ(std::get<double>(v[i]), std::strtod(text[i], nullptr));
  }
  // No short decimal within a few ulps: the value as computed (1/3 to 15 digits).
  const auto third = parse_range("0:1:4", "x");
  EXPECT_NEAR(std::get<double>(third[1]), 1.0 / 3.0, 1e-15);
  EXPECT_EQ(to_text(third[1]), "0.333333333333333");
}

TEST(SweepSpec, RandomDrawsFollowTheDocumentedSequence) {
  // std::mt19937_64 with seed 5489 (its default) first returns 14514284786278117030 (C++ standard);
  // the uniform draw is that >> 11 times 2^-53.
  const std::vector<RandomParameter> u{{"k", Distribution::uniform, 10.0, 12.0, ""}};
  const auto d = random_draws(u, 1, 5489);
  EXPECT_EQ(d[0], 10.0 + 2.0 * 0.7868209548678019);
  // Box–Muller by hand from the first two numbers of seed 7.
  std::mt19937_64 e(7);
  const double u1 = 1.0 - static_cast<double>(e() >> 11U) * 0x1p-53,
               u2 = static_cast<double>(e() >> 11U) * 0x1p-53;
  const std::vector<RandomParameter> n{{"k", Distribution::normal, 100.0, 5.0, ""}};
  EXPECT_EQ(random_draws(n, 1, 7)[0],
            100.0 + 5.0 * std::sqrt(-2.0 * std::log(u1)) * std::cos(2.0 * M_PI * u2));
  // Moments of 40000 normal draws: mean within 4 standard errors, standard deviation within 2 %.
  const auto many = random_draws(n, 40000, 11);
  double mean = 0.0, var = 0.0;
  for (const double x : many)
    mean += x / 40000.0;
  for (const double x : many)
    var += (x - mean) * (x - mean) / 39999.0;
  EXPECT_NEAR(mean, 100.0, 4.0 * 5.0 / 200.0);
  EXPECT_NEAR(std::sqrt(var), 5.0, 0.1);
}

TEST(SweepSpec, MonteCarloCasesAreReproducibleAndShareDrawsAcrossGridPoints) {
  const std::string text = plate_deck(R"(
[sweep.values]
"impactor.velocity" = [1.0, 2.0]
[sweep.random]
samples = 3
seed = 42
"materials.T300_976.E2" = { normal = [9.65e9, 0.3e9] }
)");
  const Sweep a = Sweep::from_text(text, "deck.toml");
  const Sweep b = Sweep::from_text(text, "deck.toml");
  ASSERT_EQ(a.size(), 6U);
  for (std::size_t i = 0; i < a.size(); ++i)
    EXPECT_EQ(to_text(a.case_at(i).values[1]), to_text(b.case_at(i).values[1]));
  EXPECT_EQ(to_text(a.case_at(1).values[1]), to_text(a.case_at(4).values[1])); // same sample, other velocity
  const double e2 = std::get<double>(a.case_at(2).values[1]);
  EXPECT_EQ(e2, random_draws(a.spec().random, 3, 42)[2]);
  EXPECT_EQ(a.deck_for(a.case_at(5)).materials.front().E2, e2);
  EXPECT_EQ(a.fingerprint(), b.fingerprint());
  std::string other = text;
  other.replace(other.find("seed = 42"), 9, "seed = 43");
  EXPECT_NE(Sweep::from_text(other, "deck.toml").fingerprint(), a.fingerprint());
  std::string commented = "# a comment changes nothing\n" + text;
  EXPECT_EQ(Sweep::from_text(commented, "deck.toml").fingerprint(), a.fingerprint());
}

TEST(SweepSpec, BadSpecsAreRejectedWithTheirLocation) {
  const auto deck_error = [](const std::string& sweep, const std::vector<std::string>& set = {}) {
    return error_of([&] { (void)Sweep::from_text(plate_deck(sweep), "deck.toml", set); });
  };
  // plate_deck has 29 lines; the [sweep...] header is line 30, its first key line 31.
  EXPECT_NE(
      deck_error("[sweep.values]\n\"impactor.velocty\" = [1.0, 2.0]\n")
          .find(
              "deck.toml:31:1: error: sweep key 'impactor.velocty': unknown key 'velocty' in [impactor] (did "
              "you mean 'velocity'?)"),
      std::string::npos);
  EXPECT_NE(deck_error("[sweep.values]\n\"impactor.velocity\" = []\n")
                .find("deck.toml:31:1: error: sweep.values.impactor.velocity: empty list of values"),
            std::string::npos);
  EXPECT_NE(deck_error("[sweep.values]\n\"impactor.velocity\" = \"0.5:3.0\"\n")
                .find("deck.toml:31:1: error: malformed range \"0.5:3.0\""),
            std::string::npos);
  EXPECT_NE(deck_error("[sweep.values]\n\"materials.T300.E2\" = [1e9]\n")
                .find("the base deck has no table [materials.T300]"),
            std::string::npos);
  EXPECT_NE(
      deck_error("[sweep]\nmodes = \"zip\"\n").find("deck.toml:31:1: error: unknown key 'modes' in [sweep]"),
      std::string::npos);
  EXPECT_NE(deck_error("").find("nothing to sweep"), std::string::npos);
  EXPECT_NE(error_of([] {
              (void)Sweep::from_text("analysis = \"modal\"\n" + plate_deck(""), "deck.toml",
                                     {"plate.a=0.1,0.2"});
            }).find("deck.toml: error: a sweep runs the impact or the threshold analysis, not modal"),
            std::string::npos);
  EXPECT_NE(
      deck_error("", {"impactor.velocty=1,2"})
          .find("--set 'impactor.velocty=1,2': error: sweep key 'impactor.velocty': unknown key 'velocty'"),
      std::string::npos);
  EXPECT_NE(deck_error("", {"impactor.velocity="}).find("--set 'impactor.velocity=': error: empty list"),
            std::string::npos);
  EXPECT_NE(deck_error("", {"impactor.velocity=1,,2"}).find("empty value"), std::string::npos);
  EXPECT_NE(deck_error("", {"impactor.velocity=0.5:x:3"}).find("malformed range"), std::string::npos);
  EXPECT_NE(deck_error("", {"velocity=1,2"}).find("is not a deck value"), std::string::npos);
  EXPECT_NE(
      deck_error("[sweep.random]\nsamples = 10\n\"plate.a\" = { normal = [0.1, -0.01] }\n")
          .find("deck.toml:32:1: error: sweep.random.plate.a: the standard deviation must not be negative"),
      std::string::npos);
}

TEST(SweepSpec, ABadCombinationFailsOnlyItsOwnCase) {
  const Sweep s = Sweep::from_text(plate_deck(""), "deck.toml", {"impactor.velocity=1.0,-1.0"});
  EXPECT_NO_THROW((void)s.deck_for(s.case_at(0)));
  EXPECT_NE(error_of([&] { (void)s.deck_for(s.case_at(1)); }).find("impactor.velocity must be positive"),
            std::string::npos);
}

/// Whether cases `i` and `j` of `s` share their plate (same_plate of their descriptions).
bool share_plate(const Sweep& s, std::size_t i, std::size_t j) {
  return same_plate(impact_case_description(s.deck_for(s.case_at(i))),
                    impact_case_description(s.deck_for(s.case_at(j))));
}

TEST(SweepSpec, ImpactorOnlyCasesShareThePlate) {
  // Cases 0 and 3 differ in the impactor alone, with the time step given; 4 has another layup.
  const Sweep s = Sweep::from_text(
      plate_deck(""), "deck.toml",
      {"laminate.layup=[0/90]s,[0_2/90_4/0_2]", "impactor.velocity=1,2", "impactor.radius=0.005,0.01"});
  EXPECT_TRUE(share_plate(s, 0, 3));
  EXPECT_FALSE(share_plate(s, 0, 4));
}

/// The text of examples/`name`.
std::string example_text(const std::string& name) {
  std::ifstream in(std::string(PLYIMPACT_SOURCE_DIR) + "/examples/" + name);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

TEST(SweepSpec, TheProgressiveDamageModelIsPartOfThePlate) {
  // The progressive model makes the plate's step policy: cases that differ in it cannot share a case.
  // The onset keys (criteria, every) only watch a run: cases that differ in them can.
  const Sweep s = Sweep::from_text(example_text("damage-progressive.toml"), "deck.toml",
                                   {"damage.alpha=0,0.5", "damage.every=1,2"});
  EXPECT_TRUE(share_plate(s, 0, 1));
  EXPECT_FALSE(share_plate(s, 0, 2));
}

std::string read_text_file(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

fs::path scratch(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("plyimpact-sweep-" + name);
  fs::remove_all(dir);
  return dir;
}

std::vector<nlohmann::json> run_in_process(const Sweep& s, const fs::path& dir, int jobs, bool share,
                                           int* factorizations) {
  const SweepFolder folder(dir, s);
  EXPECT_FALSE(folder.check(false)); // a fresh folder: no warning
  folder.write_manifest();
  const auto pending = folder.pending();
  std::atomic<std::size_t> next{0};
  SweepOptions o;
  o.share_factorization = share;
  *factorizations = run_sweep_cases(
      s, folder, pending, jobs,
      [&]() -> std::optional<std::size_t> {
        const std::size_t p = next++;
        return p < pending.size() ? std::optional<std::size_t>(p) : std::nullopt;
      },
      o);
  std::vector<nlohmann::json> records;
  for (std::size_t i = 0; i < s.size(); ++i)
    records.push_back(folder.read_record(i).value());
  EXPECT_EQ(folder.write_table().missing, 0U);
  return records;
}

TEST(SweepRun, RigidTargetCasesMatchTheHertzClosedForm) {
  // F_max = k^(2/5) (5 m v0²/4)^(3/5) for each (mass, velocity) of the sweep (Δt = 0.05 µs).
  const Sweep s =
      Sweep::from_text(rigid_deck(""), "deck.toml", {"impactor.mass=0.314,1.2", "impactor.velocity=1,2.92"});
  int factorizations = 0;
  const auto records = run_in_process(s, scratch("rigid"), 2, true, &factorizations);
  ASSERT_EQ(records.size(), 4U);
  for (const auto& r : records) {
    const double m = std::stod(r["values"][0].get<std::string>()),
                 v0 = std::stod(r["values"][1].get<std::string>());
    const double F_max = std::pow(0.6e9, 0.4) * std::pow(1.25 * m * v0 * v0, 0.6);
    EXPECT_EQ(r["status"], "ok");
    std::printf("  m = %.3f kg, v0 = %.2f m/s: F_max %.4f N, closed form %.4f N\n", m, v0,
                r["results"]["peak_force"].get<double>(), F_max);
    EXPECT_NEAR(r["results"]["peak_force"].get<double>() / F_max, 1.0, 1e-6) << r.dump(); // measured 3e-8
    EXPECT_NEAR(r["results"]["rebound_velocity"].get<double>() / v0, 1.0, 1e-3);
  }
}

TEST(SweepRun, SharedFactorizationGivesTheStandAloneNumbersBitForBit) {
  const Sweep s = Sweep::from_text(plate_deck(""), "deck.toml",
                                   {"impactor.velocity=1,2,3", "impactor.radius=0.005,0.0127"});
  int shared = 0, unshared = 0;
  const auto a = run_in_process(s, scratch("shared"), 1, true, &shared);
  const auto b = run_in_process(s, scratch("unshared"), 1, false, &unshared);
  EXPECT_EQ(shared, 1);   // six impactors, one plate and time step: K̄ factored once
  EXPECT_EQ(unshared, 6); // k "auto" differs with the radius: run(impactor, k) on the shared factor
  for (std::size_t i = 0; i < a.size(); ++i)
    EXPECT_EQ(a[i]["results"], b[i]["results"]) << i;
  // Case 5 (v = 3, R = 12.7 mm) run alone as an ordinary deck.
  const Deck deck = s.deck_for(s.case_at(5));
  const ImpactResult alone = ImpactCase(impact_case_description(deck)).run();
  EXPECT_EQ(a[5]["results"]["peak_force"].get<double>(), alone.peak_force);
  EXPECT_EQ(a[5]["results"]["absorbed_energy"].get<double>(), alone.absorbed_energy);
  EXPECT_GT(alone.peak_force, 0.0);
  std::printf("  case 5 alone: F_max %.17g N; in the sweep %.17g N\n", alone.peak_force,
              a[5]["results"]["peak_force"].get<double>());
}

TEST(SweepRun, ContactPointResponseGivesTheFullRunsNumbersToRounding) {
  // A point load with the trapezoidal rule: the impactor cases follow the plate through its impulse
  // response at the impact point (analysis/contact/contact_point_response.hpp) unless plate_response =
  // "full"; the two tables agree to rounding and each record says which was used. A moved impact point gets
  // its own response.
  const std::string point = "[contact]\nload = \"point\"\n";
  const std::vector<std::string> set = {"impactor.velocity=1,3", "impactor.mass=0.1,1.0",
                                        "impactor.x=0.05,0.0635"};
  const Sweep automatic = Sweep::from_text(plate_deck(point), "deck.toml", set);
  const Sweep full =
      Sweep::from_text(plate_deck(point + "[sweep]\nplate_response = \"full\"\n"), "deck.toml", set);
  int fa = 0, ff = 0;
  const auto a = run_in_process(automatic, scratch("contact-point"), 1, true, &fa);
  const auto b = run_in_process(full, scratch("contact-point-full"), 1, true, &ff);
  ASSERT_EQ(a.size(), 8U);
  for (std::size_t i = 0; i < a.size(); ++i) {
    SCOPED_TRACE(i);
    EXPECT_EQ(a[i]["results"]["plate_response"], "contact point");
    EXPECT_EQ(b[i]["results"]["plate_response"], "full");
    EXPECT_EQ(a[i]["results"]["steps"], b[i]["results"]["steps"]);
    EXPECT_EQ(a[i]["results"]["time_of_peak_force"], b[i]["results"]["time_of_peak_force"]);
    for (const char* key : {"peak_force", "peak_contact_deflection", "max_indentation", "rebound_velocity"}) {
      const double x = a[i]["results"][key].get<double>(), y = b[i]["results"][key].get<double>();
      EXPECT_NEAR(x, y, 1e-10 * std::abs(y)) << key;
    }
  }
}

TEST(SweepRun, ThreadsShareOnePlateAndItsContactPointResponse) {
  // Eight impactors on one plate, on two threads: the plate is built, K̄ factored and the contact-point
  // response computed once for both workers (one factorization, where each worker used to make its own),
  // and every record is the serial run's bit for bit (the response is the same sequence whichever
  // worker extends it).
  const Sweep s = Sweep::from_text(plate_deck("[contact]\nload = \"point\"\n"), "deck.toml",
                                   {"impactor.velocity=1,1.5,2,3", "impactor.mass=0.1,1.0"});
  int serial = 0, threads = 0;
  const auto a = run_in_process(s, scratch("threads-serial"), 1, true, &serial);
  const auto b = run_in_process(s, scratch("threads-shared"), 2, true, &threads);
  EXPECT_EQ(serial, 1);
  EXPECT_EQ(threads, 1);
  ASSERT_EQ(a.size(), 8U);
  for (std::size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(a[i]["results"]["plate_response"], "contact point") << i;
    EXPECT_EQ(a[i]["results"], b[i]["results"]) << i;
  }
}

std::vector<std::vector<std::string>> csv_rows(const std::string& text) {
  std::vector<std::vector<std::string>> rows;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) {
    std::vector<std::string> cells;
    std::istringstream l(line);
    for (std::string c; std::getline(l, c, ',');)
      cells.push_back(c);
    if (line.ends_with(',')) cells.emplace_back();
    rows.push_back(cells);
  }
  return rows;
}

std::size_t column(const std::vector<std::string>& header, const std::string& name) {
  const auto it = std::find(header.begin(), header.end(), name);
  EXPECT_NE(it, header.end()) << name;
  return static_cast<std::size_t>(it - header.begin());
}

TEST(SweepRun, ProgressiveColumnsAreThoseOfStandAloneRuns) {
  // 16 mJ first, then 4 mJ on the same (shared) case: the damaged run leaves nothing behind, the 4 mJ
  // case (0.516 m/s, below the matrix-damage threshold 0.5625 m/s of this plate) has no damage. Each
  // case against a stand-alone run of its deck: absorbed energy = ½ m v0² − ½ m v_rebound², damage
  // dissipation and projected damaged area the run's own.
  const Sweep s = Sweep::from_text(example_text("sweep-damage-progressive.toml"), "deck.toml",
                                   {"impactor.energy=0.016,0.004"});
  const fs::path dir = scratch("progressive");
  int factorizations = 0;
  const auto records = run_in_process(s, dir, 1, true, &factorizations);
  EXPECT_EQ(factorizations, 1);
  const auto rows = csv_rows(read_text_file(dir / "sweep.csv"));
  ASSERT_EQ(rows.size(), 3U);
  const auto& header = rows[0];
  // The columns of before keep their places; the damage columns follow `error`.
  EXPECT_EQ(column(header, "threshold_velocity_m_per_s"), 16U);
  EXPECT_EQ(column(header, "error"), 17U);
  EXPECT_EQ(column(header, "damage_dissipation_J"), 18U);
  EXPECT_EQ(column(header, "damage_area_m2"), 19U);
  const double m = 0.03;
  for (std::size_t i = 0; i < 2; ++i) {
    const auto& row = rows[i + 1];
    ASSERT_EQ(row.size(), header.size()) << i;
    const Deck deck = s.deck_for(s.case_at(i));
    const ImpactResult alone = ImpactCase(impact_case_description(deck)).run();
    ASSERT_TRUE(alone.rebound_velocity && alone.progressive);
    const double v0 = std::sqrt(2.0 * std::stod(row[1]) / m), vr = *alone.rebound_velocity;
    const double absorbed = std::stod(row[column(header, "absorbed_energy_J")]);
    std::printf("  E = %s J: absorbed %.6g J (1/2 m (v0^2 - vr^2) = %.6g J), dissipation %s J, area %s m^2\n",
                row[1].c_str(), absorbed, 0.5 * m * v0 * v0 - 0.5 * m * vr * vr,
                row[column(header, "damage_dissipation_J")].c_str(),
                row[column(header, "damage_area_m2")].c_str());
    EXPECT_NEAR(absorbed, 0.5 * m * v0 * v0 - 0.5 * m * vr * vr, 1e-12 * 0.5 * m * v0 * v0);
    EXPECT_EQ(std::stod(row[column(header, "damage_dissipation_J")]), alone.progressive->dissipated.sum());
    EXPECT_EQ(std::stod(row[column(header, "damage_area_m2")]), alone.progressive->projected_damage_area);
  }
  EXPECT_GT(std::stod(rows[1][column(header, "damage_area_m2")]), 0.0); // 16 mJ cracks the bottom ply
  EXPECT_EQ(rows[2][column(header, "damage_dissipation_J")], "0");      // 4 mJ does not
  EXPECT_EQ(rows[2][column(header, "damage_area_m2")], "0");
}

TEST(SweepRun, CasesAtOtherImpactPointsOfAGradedMeshRunOnTheirOwnMesh) {
  // A graded mesh is refined around its impact point: a case struck elsewhere is another plate
  // (same_plate), built and factored anew, and gives the peak force of its own stand-alone run.
  std::string deck = plate_deck("");
  deck.replace(deck.find("nx = 6\nny = 4"), 13, "size_at_impact = 0.01\nmax_size = 0.03");
  const Sweep s = Sweep::from_text(deck, "deck.toml", {"impactor.x=0.0635,0.04", "impactor.velocity=1,2"});
  int factorizations = 0;
  const auto records = run_in_process(s, scratch("graded-points"), 1, true, &factorizations);
  EXPECT_EQ(factorizations, 2); // one plate per impact point; the velocities share it
  for (std::size_t i = 0; i < s.size(); ++i) {
    const ImpactResult alone = ImpactCase(impact_case_description(s.deck_for(s.case_at(i)))).run();
    EXPECT_EQ(records[i]["results"]["peak_force"].get<double>(), alone.peak_force) << i;
  }
}

TEST(SweepRun, OnsetRunsLeaveTheDamageColumnsEmpty) {
  // An elastic plate computes no dissipation or damaged area: empty, not 0 (which would claim no damage).
  const Sweep s = Sweep::from_text(rigid_deck(""), "deck.toml", {"impactor.velocity=1,2"});
  const fs::path dir = scratch("onset-columns");
  int factorizations = 0;
  (void)run_in_process(s, dir, 1, true, &factorizations);
  const auto rows = csv_rows(read_text_file(dir / "sweep.csv"));
  ASSERT_EQ(rows.size(), 3U);
  for (std::size_t r = 1; r < rows.size(); ++r) {
    ASSERT_EQ(rows[r].size(), rows[0].size());
    EXPECT_NE(rows[r][column(rows[0], "absorbed_energy_J")], "");
    EXPECT_EQ(rows[r][column(rows[0], "damage_dissipation_J")], "");
    EXPECT_EQ(rows[r][column(rows[0], "damage_area_m2")], "");
  }
}

// --- report.html (io/sweeps/sweep_report.hpp) -----------------------------------------------------------

/// The cells of the report's case table, row by row (tags stripped).
std::vector<std::vector<std::string>> case_table(const std::string& html) {
  std::vector<std::vector<std::string>> rows;
  const std::size_t from = html.find("<table class=\"cases\">"), to = html.find("</table>", from);
  std::istringstream lines(html.substr(from, to - from));
  for (std::string line; std::getline(lines, line);) {
    if (!line.starts_with("<tr")) continue;
    std::vector<std::string> cells;
    for (std::size_t at = line.find("<t"); at != std::string::npos; at = line.find("<t", at + 1)) {
      if (line.compare(at, 3, "<tr") == 0) continue;
      const std::size_t open = line.find('>', at) + 1;
      cells.push_back(line.substr(open, line.find('<', open) - open));
    }
    rows.push_back(cells);
  }
  return rows;
}

TEST(SweepReport, TabulatesEveryCaseAndPlotsEachResultAgainstEachSweptKey) {
  // Two masses x three velocities on a rigid target: the report's table holds the six cases, each peak
  // force that of the Hertz closed form F = k^(2/5) (5 m v0²/4)^(3/5) to the 5 digits shown; peak force
  // and absorbed energy are plotted against both keys, one line per value of the other key.
  const Sweep s = Sweep::from_text(rigid_deck(""), "deck.toml",
                                   {"impactor.mass=0.314,1.2", "impactor.velocity=1,2,2.92"});
  const fs::path dir = scratch("report");
  int factorizations = 0;
  (void)run_in_process(s, dir, 2, true, &factorizations);
  const std::string html = read_text_file(dir / "report.html");
  ASSERT_FALSE(html.empty());
  EXPECT_EQ(test::occurrences(html, "class=\"plot\""), 4U)
      << "peak force and absorbed energy against mass and velocity";
  EXPECT_EQ(test::occurrences(html, "<polyline"), 2U * 3U + 2U * 2U)
      << "3 velocity lines against the mass, 2 mass lines";
  EXPECT_EQ(test::occurrences(html, "<circle"), 4U * 6U) << "every case a dot in every plot";
  EXPECT_EQ(test::occurrences(html, ">impactor.velocity = 2.92<"), 2U);
  EXPECT_EQ(test::occurrences(html, ">impactor.mass = 1.2<"), 2U);
  EXPECT_EQ(test::occurrences(html, "<script"), 0U);
  EXPECT_EQ(test::occurrences(html, "http"), test::occurrences(html, "xmlns=\"http://www.w3.org/2000/svg\""));
  EXPECT_EQ(html.find("did not complete"), std::string::npos);
  const auto rows = case_table(html);
  ASSERT_EQ(rows.size(), 7U);
  EXPECT_EQ(rows[0][1], "impactor.mass");
  EXPECT_EQ(rows[0][2], "impactor.velocity");
  EXPECT_EQ(rows[0][4], "peak force [N]");
  for (std::size_t r = 1; r < rows.size(); ++r) {
    const double m = std::stod(rows[r][1]), v0 = std::stod(rows[r][2]);
    const double F_max = std::pow(0.6e9, 0.4) * std::pow(1.25 * m * v0 * v0, 0.6);
    EXPECT_EQ(rows[r][3], "ok");
    EXPECT_NEAR(std::stod(rows[r][4]) / F_max, 1.0, 1e-4) << rows[r][4]; // 5 digits shown
  }
}

TEST(SweepReport, ACaseThatFailedIsListedWithItsError) {
  const Sweep s = Sweep::from_text(rigid_deck(""), "deck.toml", {"impactor.velocity=1.0,-1.0"});
  const fs::path dir = scratch("report-failed");
  int factorizations = 0;
  (void)run_in_process(s, dir, 1, true, &factorizations);
  const std::string html = read_text_file(dir / "report.html");
  EXPECT_NE(html.find("<li>case 1: failed: "), std::string::npos) << html;
  EXPECT_NE(html.find("impactor.velocity must be positive"), std::string::npos);
  EXPECT_EQ(test::occurrences(html, "<tr class=\"failed\">"), 1U);
  EXPECT_NE(html.find("2 (1 failed, 1 ok)"), std::string::npos);
}

TEST(SweepReport, MonteCarloSamplesAreDotsNotLines) {
  // A randomly drawn mass: the peak force against it is a scatter (no line through unordered draws).
  const Sweep s = Sweep::from_text(
      rigid_deck("[sweep.random]\nsamples = 5\nseed = 7\n\"impactor.mass\" = { uniform = [0.2, 1.2] }\n"),
      "deck.toml");
  const fs::path dir = scratch("report-random");
  int factorizations = 0;
  (void)run_in_process(s, dir, 1, true, &factorizations);
  const std::string html = read_text_file(dir / "report.html");
  EXPECT_EQ(test::occurrences(html, "class=\"plot\""), 2U);
  EXPECT_EQ(test::occurrences(html, "<polyline"), 0U);
  EXPECT_EQ(test::occurrences(html, "<circle"), 2U * 5U);
  EXPECT_NE(html.find("uniform on [0.2, 1.2]"), std::string::npos);
  EXPECT_NE(html.find("5 per grid point, seed 7"), std::string::npos);
}

} // namespace
} // namespace plyimpact::sweep_tests
