// Impact solver benchmarks (issue: impact speed targets). Run:
//   ./build/release/bench/bench_impact --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
// Counters: steps, us_per_step, solve_us (one triangular solve pair with the same factor, measured
// in the same process) and overhead = us_per_step / solve_us − 1.
#include "plyimpact/analysis/impact/impact_case.hpp"
#include "plyimpact/io/deck/case_from_deck.hpp"
#include "plyimpact/io/deck/deck.hpp"

#include <benchmark/benchmark.h>

#include <array>
#include <string>

namespace {

using namespace plyimpact;

Deck section36(int nx, int ny, std::optional<double> end) {
  Deck deck = load_deck(std::string(PLYIMPACT_SOURCE_DIR) + "/examples/thesis-3.6-v268.toml");
  deck.mesh->nx = nx;
  deck.mesh->ny = ny;
  deck.time.end = end;
  return deck;
}

void run_impact(benchmark::State& state, const Deck& deck, SparseSolverKind kind,
                FillOrdering ordering = FillOrdering::amd) {
  ImpactCaseDescription description = impact_case_description(deck);
  description.solver = kind;
  description.ordering = ordering;
  const ImpactCase impact(description);
  ImpactResult r;
  for (auto _ : state) {
    r = impact.run();
    // A copy: Google Benchmark 1.7's DoNotOptimize on a double member (asm "+m,r") zeroed r.peak_force.
    double peak = r.peak_force;
    benchmark::DoNotOptimize(peak);
  }
  const double solve = impact.time_one_solve(101);
  const double per_step = r.wall_time / static_cast<double>(r.steps);
  state.counters["steps"] = static_cast<double>(r.steps);
  state.counters["equations"] = impact.equations();
  state.counters["us_per_step"] = per_step * 1e6;
  state.counters["solve_us"] = solve * 1e6;
  state.counters["overhead"] = per_step / solve - 1.0;
  state.counters["peak_force_N"] = r.peak_force;
}

/// §3.6 case, 15×11, 6.14 kg at 2.68 m/s, Δt = 1 µs, full event (end = auto).
void BM_Impact_Section36_15x11_FullEvent(benchmark::State& state) {
  run_impact(state, section36(15, 11, std::nullopt), static_cast<SparseSolverKind>(state.range(0)));
}
BENCHMARK(BM_Impact_Section36_15x11_FullEvent)
    ->Arg(static_cast<int>(SparseSolverKind::cholmod_simplicial))
    ->Arg(static_cast<int>(SparseSolverKind::simplicial_ldlt))
    ->Arg(static_cast<int>(SparseSolverKind::cholmod))
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1);

/// A velocity study on the §3.6 plate (15×11, the deck's point load, Δt = 1 µs, whole events): the case
/// built once, 16 velocities from 1 to 4 m/s, then one more (2.5 m/s); arg 1: each run through the plate's
/// impulse response at the contact point (contact_point_response.hpp), arg 0: each run solved in full. The
/// time includes the case's set-up and, with arg 1, the impulse run. Counter `next_case_ms`: the wall time
/// of the last run alone, once the response is there (the marginal cost of a case in a long sweep).
void BM_Impact_Section36_VelocityStudy(benchmark::State& state) {
  const bool contact_point = state.range(0) != 0;
  RunRequest request;
  request.history_every = 0;
  request.contact_point_response = contact_point;
  Impactor imp;
  double peak = 0.0, next_case = 0.0;
  for (auto _ : state) {
    const ImpactCase impact(impact_case_description(section36(15, 11, std::nullopt)));
    imp = impact.settings().impactor;
    for (int i = 0; i < 16; ++i) {
      imp.velocity = 1.0 + 0.2 * i;
      request.impactor = imp;
      peak = impact.run(request).peak_force;
    }
    imp.velocity = 2.5;
    request.impactor = imp;
    next_case = impact.run(request).wall_time;
    benchmark::DoNotOptimize(peak);
  }
  state.counters["peak_force_4mps_N"] = peak;
  state.counters["next_case_ms"] = next_case * 1e3;
}
BENCHMARK(BM_Impact_Section36_VelocityStudy)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond)->Iterations(1);

/// Setup cost: assembly, factorization of K̄ and the fundamental period for the end rule.
void BM_Impact_Section36_15x11_Setup(benchmark::State& state) {
  const ImpactCaseDescription description = impact_case_description(section36(15, 11, std::nullopt));
  for (auto _ : state) {
    const ImpactCase impact(description);
    benchmark::DoNotOptimize(impact.equations());
  }
}
BENCHMARK(BM_Impact_Section36_15x11_Setup)->Unit(benchmark::kMillisecond);

/// Per-step cost on the finer meshes: the first 500 µs (500 steps) of the same event, with the factor of
/// K̄ in each fill-reducing ordering. Arguments: nx (ny = 11 nx / 15, the thesis's aspect) and the
/// FillOrdering (the label names it).
void BM_Impact_Section36_500Steps(benchmark::State& state) {
  const auto nx = static_cast<int>(state.range(0));
  const auto ordering = static_cast<FillOrdering>(state.range(1));
  run_impact(state, section36(nx, 11 * nx / 15, 500e-6), ImpactCaseDescription{}.solver, ordering);
  const std::array<const char*, 3> names{"AMD", "METIS", "NESDIS"};
  state.SetLabel(names.at(static_cast<std::size_t>(state.range(1))));
}
BENCHMARK(BM_Impact_Section36_500Steps)
    ->ArgsProduct({{15, 30, 45, 60, 90, 120}, {0, 1, 2}})
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1);

} // namespace

BENCHMARK_MAIN();
