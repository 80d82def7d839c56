// The stacked plate against the single laminate on the §3.6 case (issue 19 speed: "report the cost of the
// stacked model against the single-laminate run for the §3.6 plate with 3 interfaces"). Run:
//   ./build/release/bench/bench_delamination --benchmark_repetitions=3
//   --benchmark_report_aggregates_only=true
// The first 500 µs of the event (500 steps at Δt = 1 µs; the whole event is 8626 steps, whose cost is
// proportional): the single laminate's linear run, and the plate cut after plies 6, 12 and 18 with
// interfaces that hold, for each sparse solver, and with explicit central differences at the stack's
// stable step. Counters: DOFs, µs per step, solves per step (the explicit run: its Δt in ns).
#include "plyimpact/analysis/impact/impact_case.hpp"
#include "plyimpact/io/deck/case_from_deck.hpp"
#include "plyimpact/io/deck/deck.hpp"

#include <benchmark/benchmark.h>

#include <string>

namespace {

using namespace plyimpact;

ImpactCaseDescription section36() {
  ImpactCaseDescription d = impact_case_description(
      load_deck(std::string(PLYIMPACT_SOURCE_DIR) + "/examples/thesis-3.6-v268.toml"));
  d.time.end = 500e-6;
  return d;
}

void report(benchmark::State& state, const ImpactResult& r) {
  const auto steps = static_cast<double>(r.steps);
  state.counters["dofs"] = r.dofs;
  state.counters["us_per_step"] = r.wall_time / steps * 1e6;
  if (r.newton) state.counters["solves_per_step"] = static_cast<double>(r.newton->iterations) / steps;
}

/// Runs the case `d` once per iteration and reports the last run.
void run_case(benchmark::State& state, const ImpactCaseDescription& d) {
  const ImpactCase impact(d);
  ImpactResult r;
  for (auto _ : state) {
    r = impact.run();
    double peak = r.peak_force; // a copy: DoNotOptimize on the member itself zeroes it (bench_impact.cpp)
    benchmark::DoNotOptimize(peak);
  }
  report(state, r);
}

void BM_Section36_SingleLaminate(benchmark::State& state) {
  run_case(state, section36());
}
BENCHMARK(BM_Section36_SingleLaminate)->Unit(benchmark::kMillisecond)->Iterations(1);

/// Arg: SparseSolverKind (0 CHOLMOD supernodal, 1 Eigen SimplicialLDLT, 2 CHOLMOD simplicial).
DelaminationSettings three_interfaces_that_hold() {
  DelaminationSettings s;
  s.stack.cuts = {5, 11, 17};
  s.stack.interface.penalty_stiffness = turon_penalty_stiffness(7.5e9, 6 * 0.19375e-3);
  s.stack.interface.normal_strength = s.stack.interface.shear_strength = 1e10; // holds
  s.stack.interface.G_Ic = s.stack.interface.G_IIc = 1e9; // a gentle slope, never reached (DL5)
  s.stack.interface.bk_exponent = 1.45;
  return s;
}

void BM_Section36_ThreeInterfaces(benchmark::State& state) {
  ImpactCaseDescription d = section36();
  d.solver = static_cast<SparseSolverKind>(state.range(0));
  d.delamination = three_interfaces_that_hold();
  run_case(state, d);
}
BENCHMARK(BM_Section36_ThreeInterfaces)->DenseRange(0, 2)->Unit(benchmark::kMillisecond)->Iterations(1);

/// The same stack with explicit central differences (lumped mass, dt = "auto": the stack's stable step).
void BM_Section36_ThreeInterfacesExplicit(benchmark::State& state) {
  ImpactCaseDescription d = section36();
  d.mesh.mass = MassMatrix::lumped;
  d.time.dt.reset();
  d.delamination = three_interfaces_that_hold();
  d.time.laws = Integrator::central_difference;
  run_case(state, d);
  state.counters["dt_ns"] = ImpactCase(d).settings().dt * 1e9;
}
BENCHMARK(BM_Section36_ThreeInterfacesExplicit)->Unit(benchmark::kMillisecond)->Iterations(1);

} // namespace
BENCHMARK_MAIN();
