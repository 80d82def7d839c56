// Large-deflection impact against the linear solver on the same case (issue 8 speed target: a
// non-linear step under 10× a linear one for the §3.6 case). Run:
//   ./build/release/bench/bench_nonlinear_impact --benchmark_repetitions=3
//   --benchmark_report_aggregates_only=true
// Counters: steps, us_per_step, newton_per_step (iterations per time step), factorizations of K̄.
#include "plyimpact/analysis/impact/impact_case.hpp"
#include "plyimpact/io/deck/case_from_deck.hpp"
#include "plyimpact/io/deck/deck.hpp"

#include <benchmark/benchmark.h>

#include <string>

namespace {

using namespace plyimpact;

Deck section36() {
  return load_deck(std::string(PLYIMPACT_SOURCE_DIR) + "/examples/thesis-3.6-v268.toml");
}

/// §3.6 case, 15×11, 6.14 kg at 2.68 m/s, Δt = 1 µs, full event (end = auto): linear solver.
void BM_Section36_Linear(benchmark::State& state) {
  const ImpactCase impact(impact_case_description(section36()));
  ImpactResult r;
  for (auto _ : state) {
    r = impact.run();
    double peak = r.peak_force; // a copy: DoNotOptimize on the member itself zeroes it (bench_impact.cpp)
    benchmark::DoNotOptimize(peak);
  }
  state.counters["steps"] = static_cast<double>(r.steps);
  state.counters["us_per_step"] = r.wall_time / static_cast<double>(r.steps) * 1e6;
  state.counters["peak_deflection_mm"] = r.peak_contact_deflection * 1e3;
}
BENCHMARK(BM_Section36_Linear)->Unit(benchmark::kMillisecond)->Iterations(1);

/// The same case, geometrically non-linear (von Kármán or Green–Lagrange).
void BM_Section36_Nonlinear(benchmark::State& state) {
  ImpactCaseDescription description = impact_case_description(section36());
  description.nonlinear = NonlinearImpactSettings{.measure = static_cast<StrainMeasure>(state.range(0))};
  const ImpactCase impact(description);
  ImpactResult r;
  for (auto _ : state) {
    r = impact.run();
    double peak = r.peak_force; // a copy: DoNotOptimize on the member itself zeroes it (bench_impact.cpp)
    benchmark::DoNotOptimize(peak);
  }
  const auto steps = static_cast<double>(r.steps);
  state.counters["steps"] = steps;
  state.counters["us_per_step"] = r.wall_time / steps * 1e6;
  state.counters["newton_per_step"] = static_cast<double>(r.newton->iterations) / steps;
  state.counters["max_newton"] = r.newton->max_iterations_per_step;
  state.counters["factorizations"] = r.newton->factorizations;
  state.counters["peak_deflection_mm"] = r.peak_contact_deflection * 1e3;
}
BENCHMARK(BM_Section36_Nonlinear)
    ->Arg(static_cast<int>(StrainMeasure::von_karman))
    ->Arg(static_cast<int>(StrainMeasure::green_lagrange))
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1);

} // namespace

BENCHMARK_MAIN();
