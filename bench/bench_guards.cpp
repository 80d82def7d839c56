// Cost of the numerical guards of an impact run (docs/robustness.md, bench/README.md):
//
//   memory_estimate/<nx>x<ny>   estimate_factor_memory(K̄): AMD ordering + elimination tree of
//                               SimplicialLDLT, no numeric work (done once before factorizing K̄)
//   factor_Keff/<nx>x<ny>       SpdSolver::factorize(K̄) with SimplicialLDLT, for comparison
//   finite_check/<nx>x<ny>      check_finite_vector on u, v and a (done every 100 steps)
//
// on the thesis §3.6 plate (K̄ = K + M/(β Δt²), β = 1/4, Δt = 1 µs, all DOFs). Counters: dofs,
// nnz_L (strictly lower) and the estimate in MB.
#include "plyimpact/analysis/impact/guards.hpp"
#include "plyimpact/fem/boundary.hpp"
#include "plyimpact/fem/discrete_plate.hpp"
#include "plyimpact/fem/spd_solver.hpp"
#include "plyimpact/laminate/laminate.hpp"
#include "plyimpact/laminate/layup.hpp"

#include <benchmark/benchmark.h>

#include <vector>

namespace {

using namespace plyimpact;

DiscretePlate thesis_plate(int nx, int ny) {
  Material m;
  m.name = "thesis_3_6";
  m.E1 = 129e9;
  m.E2 = 7.5e9;
  m.G12 = m.G13 = m.G23 = 3.5e9;
  m.nu12 = 0.33;
  m.rho = 1540.0;
  std::vector<Ply> plies;
  for (const double angle : parse_layup("[45/90/-45/0]3s"))
    plies.push_back({angle, 0.19375e-3, 0});
  const BoundaryConditions bc = BoundaryConditions::on_edges("ss", "ss", "ss", "ss");
  return {Laminate({m}, plies), {0.127, 0.0762}, {nx, ny, MassMatrix::lumped, ElementFormulation::q9}, bc};
}

SparseMatrix effective_stiffness(const DiscretePlate& model) {
  constexpr double beta = 0.25, dt = 1e-6;
  return model.stiffness() + model.mass() / (beta * dt * dt);
}

void memory_estimate(benchmark::State& state) {
  const DiscretePlate model =
      thesis_plate(static_cast<int>(state.range(0)), static_cast<int>(state.range(1)));
  const SparseMatrix Keff = effective_stiffness(model);
  FactorMemoryEstimate e;
  for (auto _ : state) {
    e = estimate_factor_memory(Keff);
    benchmark::DoNotOptimize(e);
  }
  state.counters["dofs"] = static_cast<double>(e.equations);
  state.counters["nnz_L"] = static_cast<double>(e.factor_nonzeros);
  state.counters["MB"] = e.bytes / 1e6;
}

void factor_Keff(benchmark::State& state) {
  const DiscretePlate model =
      thesis_plate(static_cast<int>(state.range(0)), static_cast<int>(state.range(1)));
  const SparseMatrix Keff = effective_stiffness(model);
  for (auto _ : state) {
    SpdSolver solver(SparseSolverKind::simplicial_ldlt);
    solver.factorize(Keff);
    benchmark::DoNotOptimize(solver);
  }
  state.counters["dofs"] = static_cast<double>(Keff.rows());
}

void finite_check(benchmark::State& state) {
  const DiscretePlate model =
      thesis_plate(static_cast<int>(state.range(0)), static_cast<int>(state.range(1)));
  const Eigen::VectorXd u = Eigen::VectorXd::Constant(model.size(), 1e-3);
  for (auto _ : state) {
    check_finite_vector(100, 1e-4, "u", u);
    check_finite_vector(100, 1e-4, "v", u);
    check_finite_vector(100, 1e-4, "a", u);
    benchmark::ClobberMemory();
  }
  state.counters["dofs"] = static_cast<double>(model.size());
}

void meshes(benchmark::internal::Benchmark* b) {
  b->ArgNames({"nx", "ny"})->Args({15, 11})->Args({30, 22})->Args({60, 44})->Unit(benchmark::kMillisecond);
}

BENCHMARK(memory_estimate)->Apply(meshes);
BENCHMARK(factor_Keff)->Apply(meshes);
BENCHMARK(finite_check)->Apply(meshes)->Unit(benchmark::kMicrosecond);

} // namespace

BENCHMARK_MAIN();
