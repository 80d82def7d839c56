// The element loops of a run on threads give the same bits for any number of threads (issue 50): the
// results folder of `plyimpact impact --threads 1` and `--threads 2` is the same bytes, wall time aside,
// for ply damage with central differences (the laws and K0 u on threads) and with large deflections and
// Newton–Newmark (the von Kármán element forces too), and for delamination with central differences and
// selective mass scaling (the interfaces, the block mass, the kinetic energies).
#include "support/cli.hpp"
#include "support/impact_decks.hpp"

#include <gtest/gtest.h>

#include <string>

namespace plyimpact::test::threads_tests {
namespace {

/// summary.json without its wall time.
nlohmann::json summary_without_time(const fs::path& dir) {
  nlohmann::json j = read_json(dir / "summary.json");
  j.erase("wall_time");
  return j;
}

/// The energy the run's damage dissipated: the plies' where they crack, else the interfaces'.
double dissipated(const nlohmann::json& summary) {
  if (summary.contains("damage")) return summary.at("damage").at("dissipated_energy").get<double>();
  return summary.at("delamination").at("dissipated_energy_J").get<double>();
}

void expect_same_results_for_one_and_two_threads(const std::string& name, const std::string& deck_text) {
  const fs::path dir = scratch("threads-" + name);
  const fs::path deck = write(dir, deck_text);
  for (const int threads : {1, 2}) {
    const CommandResult r = run("impact " + deck.string() + " -q --threads " + std::to_string(threads) +
                                " -o " + (dir / std::to_string(threads)).string());
    ASSERT_EQ(r.status, 0) << r.out;
  }
  const nlohmann::json one = summary_without_time(dir / "1");
  EXPECT_GT(dissipated(one), 0.0) << "nothing was damaged";
  EXPECT_EQ(one, summary_without_time(dir / "2"));
  EXPECT_EQ(read_text(dir / "1" / "history.csv"), read_text(dir / "2" / "history.csv"));
}

TEST(Threads, ExplicitPlyDamageIsTheSameBitsOnOneAndTwoThreads) {
  expect_same_results_for_one_and_two_threads(
      "explicit", with_key(example_text("damage-progressive-explicit.toml"), "end", "4.0e-4"));
}

TEST(Threads, NonlinearPlyDamageIsTheSameBitsOnOneAndTwoThreads) {
  expect_same_results_for_one_and_two_threads(
      "nonlinear", with_key(example_text("damage-progressive-nonlinear.toml"), "end", "4.0e-4"));
}

TEST(Threads, ExplicitDelaminationWithSelectiveMassIsTheSameBitsOnOneAndTwoThreads) {
  // The interfaces' laws and forces, the block mass's solve, M v and the added mass's energy on threads.
  expect_same_results_for_one_and_two_threads(
      "delamination", with_key(example_text("impact-delamination-explicit-selective.toml"), "end", "2.0e-4"));
}

} // namespace
} // namespace plyimpact::test::threads_tests
