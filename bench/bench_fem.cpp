// Benchmarks of the FE core on the thesis §3.6 plate (bench/README.md has the commands and results):
//
//   assemble_K/<nx>x<ny>               DiscretePlate::stiffness()
//   assemble_M/<nx>x<ny>               DiscretePlate::mass() (lumped, 3-point Lobatto)
//   factor_K/<backend>/<nx>x<ny>       SpdSolver::factorize(K): ordering + symbolic + numeric
//   factor_Keff/<backend>/<nx>x<ny>    SpdSolver::factorize(K + M/(β Δt²)), β = 1/4, Δt = 1 µs,
//                                      the matrix the impact solver factors once per run
//   solve/<backend>/<nx>x<ny>          one forward + back substitution with the factor of K
//                                      (unit point load at the plate centre)
//   ordering/<ordering>/<nx>x<ny>      one solve with CHOLMOD's simplicial LDLᵀ of K̄ in the AMD, METIS
//                                      or NESDIS ordering; nnz_L of that factor
//   mixed_precision/<nx>x<ny>          K̄ x = f to double accuracy with a single-precision factor (Eigen's
//                                      SimplicialLDLT<float>, AMD) and iterative refinement: residual in
//                                      double, correction by the float factor, until the residual is that of
//                                      the double solve; counters: refinements, error against the double
//                                      solve
//   float_solve/<nx>x<ny>              one solve with that float factor alone (the floor of the above)
//
// for meshes 15×11 (the thesis's), 30×22, 60×44, 120×88 and both SpdSolver backends (CHOLMOD
// supernodal LLᵀ, Eigen SimplicialLDLT). Counters: dofs = model.size(), nnz_K = stored non-zeros of
// the (full, symmetric) global matrix, nnz_L = non-zeros of the Cholesky factor L including its
// diagonal (CHOLMOD: Common->lnz of the ordering it selected; SimplicialLDLT: strictly lower nnz + n),
// flops_L = CHOLMOD's floating-point operation count of the numeric factorization (Common->fl).
// The label of the CHOLMOD runs names the fill-reducing ordering CHOLMOD chose.
#include "plyimpact/fem/boundary.hpp"
#include "plyimpact/fem/discrete_plate.hpp"
#include "plyimpact/fem/loads.hpp"
#include "plyimpact/fem/spd_solver.hpp"
#include "plyimpact/laminate/laminate.hpp"
#include "plyimpact/laminate/layup.hpp"

#include <Eigen/CholmodSupport>
#include <Eigen/SparseCholesky>
#include <benchmark/benchmark.h>

#include <map>
#include <memory>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace {

using namespace plyimpact;

constexpr double plate_a = 0.127, plate_b = 0.0762;
constexpr double newmark_beta = 0.25, time_step = 1e-6;

Laminate thesis_3_6_laminate() {
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
  return Laminate({m}, plies);
}

BoundaryConditions all_edges_ss() {
  return BoundaryConditions::on_edges("ss", "ss", "ss", "ss");
}

/// One mesh: the model and its matrices, built once and shared by every benchmark of that mesh.
struct Case {
  DiscretePlate model;
  SparseMatrix K, M, Keff;
  Eigen::VectorXd f;

  Case(int nx, int ny)
      : model(thesis_3_6_laminate(), {plate_a, plate_b}, {nx, ny, MassMatrix::lumped, ElementFormulation::q9},
              all_edges_ss()),
        K(model.stiffness()), M(model.mass()), Keff(K + M / (newmark_beta * time_step * time_step)),
        f(point_load(model, plate_a / 2, plate_b / 2, 1.0)) {}
};

Case& get_case(int nx, int ny) {
  static std::map<std::pair<int, int>, std::unique_ptr<Case>> cases;
  auto& c = cases[{nx, ny}];
  if (!c) c = std::make_unique<Case>(nx, ny);
  return *c;
}

/// CHOLMOD's own statistics (fill and chosen ordering), which SpdSolver does not expose.
class CholmodProbe : public Eigen::CholmodSupernodalLLT<SparseMatrix> {
public:
  explicit CholmodProbe(const SparseMatrix& A) { analyzePattern(A); }
  [[nodiscard]] double factor_nonzeros() { return cholmod().lnz; }
  [[nodiscard]] double factor_flops() { return cholmod().fl; }
  [[nodiscard]] std::string ordering() {
    switch (cholmod().method[cholmod().selected].ordering) {
    case CHOLMOD_NATURAL:
      return "natural";
    case CHOLMOD_AMD:
      return "AMD";
    case CHOLMOD_METIS:
      return "METIS";
    case CHOLMOD_NESDIS:
      return "NESDIS";
    case CHOLMOD_COLAMD:
      return "COLAMD";
    default:
      return "other";
    }
  }
};

const char* backend_name(SparseSolverKind kind) {
  return kind == SparseSolverKind::cholmod ? "cholmod" : "simplicial_ldlt";
}

void set_size_counters(benchmark::State& state, const Case& c) {
  state.counters["dofs"] = static_cast<double>(c.model.size());
  state.counters["nnz_K"] = static_cast<double>(c.K.nonZeros());
}

void set_factor_counters(benchmark::State& state, const Case& c, const SparseMatrix& A, SparseSolverKind kind,
                         const SpdSolver& solver) {
  set_size_counters(state, c);
  if (kind == SparseSolverKind::cholmod) {
    CholmodProbe probe(A);
    state.counters["nnz_L"] = probe.factor_nonzeros();
    state.counters["flops_L"] = probe.factor_flops();
    state.SetLabel(probe.ordering());
  } else {
    state.counters["nnz_L"] = static_cast<double>(solver.factor_nonzeros() + A.rows());
  }
}

void assemble_K(benchmark::State& state, int nx, int ny) {
  Case& c = get_case(nx, ny);
  for (auto _ : state) {
    SparseMatrix K = c.model.stiffness();
    benchmark::DoNotOptimize(K.valuePtr());
    benchmark::ClobberMemory();
  }
  set_size_counters(state, c);
}

void assemble_M(benchmark::State& state, int nx, int ny) {
  Case& c = get_case(nx, ny);
  for (auto _ : state) {
    SparseMatrix M = c.model.mass();
    benchmark::DoNotOptimize(M.valuePtr());
    benchmark::ClobberMemory();
  }
  set_size_counters(state, c);
}

void factor(benchmark::State& state, int nx, int ny, SparseSolverKind kind, bool effective) {
  Case& c = get_case(nx, ny);
  const SparseMatrix& A = effective ? c.Keff : c.K;
  SpdSolver solver(kind);
  for (auto _ : state) {
    solver.factorize(A);
    benchmark::ClobberMemory();
  }
  set_factor_counters(state, c, A, kind, solver);
}

void solve(benchmark::State& state, int nx, int ny, SparseSolverKind kind) {
  Case& c = get_case(nx, ny);
  SpdSolver solver(kind);
  solver.factorize(c.K);
  for (auto _ : state) {
    Eigen::VectorXd u = solver.solve(c.f);
    benchmark::DoNotOptimize(u.data());
    benchmark::ClobberMemory();
  }
  // Sanity: the residual of the solve is round-off (a wrong factor would make the timing meaningless).
  const Eigen::VectorXd u = solver.solve(c.f);
  const double residual = (c.K * u - c.f).norm() / c.f.norm();
  if (!(residual < 1e-8)) state.SkipWithError(("solve residual " + std::to_string(residual)).c_str());
  set_factor_counters(state, c, c.K, kind, solver);
}

/// The factor of K̄ by CHOLMOD's simplicial LDLᵀ (the time loop's backend) in one fill-reducing ordering:
/// its non-zeros and the time of a solve, which is what a time step costs.
void ordering(benchmark::State& state, int nx, int ny, FillOrdering fill) {
  Case& c = get_case(nx, ny);
  SpdSolver solver(SparseSolverKind::cholmod_simplicial, fill);
  solver.factorize(c.Keff);
  SpdSolver::Workspace workspace;
  Eigen::VectorXd u(c.f.size());
  for (auto _ : state) {
    solver.solve(c.f, u, workspace);
    benchmark::DoNotOptimize(u.data());
    benchmark::ClobberMemory();
  }
  set_size_counters(state, c);
  state.counters["nnz_L"] = static_cast<double>(solver.factor_nonzeros() + c.Keff.rows());
}

/// The single-precision factor of K̄ and the double solve it must match.
struct MixedPrecision {
  Eigen::SparseMatrix<float> Kbar;
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<float>> factor;
  Eigen::VectorXd exact;        ///< CHOLMOD's double solve
  double target_residual = 0.0; ///< ‖f − K̄ x‖ of that solve

  explicit MixedPrecision(const Case& c) : Kbar(c.Keff.cast<float>()) {
    factor.compute(Kbar);
    if (factor.info() != Eigen::Success) throw std::runtime_error("float factor of K̄ failed");
    SpdSolver solver(SparseSolverKind::cholmod_simplicial, FillOrdering::amd);
    solver.factorize(c.Keff);
    exact = solver.solve(c.f);
    target_residual = (c.f - c.Keff * exact).norm();
  }

  /// x with ‖f − K̄ x‖ ≤ 2 × the double solve's residual; returns the number of float solves.
  int solve(const Case& c, Eigen::VectorXd& x, Eigen::VectorXd& r) const {
    x.setZero();
    r = c.f;
    for (int k = 1; k <= 20; ++k) {
      x += factor.solve(r.cast<float>()).cast<double>();
      r = c.f - c.Keff * x;
      if (r.norm() <= 2.0 * target_residual) return k;
    }
    return -1; // did not reach double accuracy
  }
};

void mixed_precision(benchmark::State& state, int nx, int ny) {
  const Case& c = get_case(nx, ny);
  const MixedPrecision mp(c);
  Eigen::VectorXd x(c.f.size()), r(c.f.size());
  int solves = 0;
  for (auto _ : state) {
    solves = mp.solve(c, x, r);
    benchmark::DoNotOptimize(x.data());
    benchmark::ClobberMemory();
  }
  set_size_counters(state, c);
  state.counters["float_solves"] = solves;
  state.counters["error_vs_double"] = (x - mp.exact).norm() / mp.exact.norm();
  state.counters["nnz_L"] =
      static_cast<double>(mp.factor.matrixL().nestedExpression().nonZeros() + c.f.size());
}

void float_solve(benchmark::State& state, int nx, int ny) {
  const Case& c = get_case(nx, ny);
  const MixedPrecision mp(c);
  const Eigen::VectorXf f = c.f.cast<float>();
  Eigen::VectorXf x(f.size());
  for (auto _ : state) {
    x = mp.factor.solve(f);
    benchmark::DoNotOptimize(x.data());
    benchmark::ClobberMemory();
  }
  set_size_counters(state, c);
  state.counters["error_vs_double"] = (x.cast<double>() - mp.exact).norm() / mp.exact.norm();
}

} // namespace

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  const std::vector<std::pair<int, int>> meshes{{15, 11}, {30, 22}, {60, 44}, {120, 88}};
  const std::vector<SparseSolverKind> kinds{SparseSolverKind::cholmod, SparseSolverKind::simplicial_ldlt};
  // Every benchmark here reports milliseconds of wall time.
  const auto in_ms = [](const std::string& name, auto&&... args) {
    benchmark::RegisterBenchmark(name.c_str(), std::forward<decltype(args)>(args)...)
        ->Unit(benchmark::kMillisecond)
        ->UseRealTime();
  };
  for (const auto& [nx, ny] : meshes) {
    const std::string mesh = std::to_string(nx) + "x" + std::to_string(ny);
    in_ms("assemble_K/" + mesh, assemble_K, nx, ny);
    in_ms("assemble_M/" + mesh, assemble_M, nx, ny);
    in_ms("mixed_precision/" + mesh, mixed_precision, nx, ny);
    in_ms("float_solve/" + mesh, float_solve, nx, ny);
    for (const SparseSolverKind kind : kinds) {
      const std::string tag = std::string(backend_name(kind)) + "/" + mesh;
      in_ms("factor_K/" + tag, factor, nx, ny, kind, false);
      in_ms("factor_Keff/" + tag, factor, nx, ny, kind, true);
      in_ms("solve/" + tag, solve, nx, ny, kind);
    }
  }
  const std::vector<std::pair<FillOrdering, std::string>> orderings{
      {FillOrdering::amd, "AMD"},
      {FillOrdering::metis, "METIS"},
      {FillOrdering::nested_dissection, "NESDIS"}};
  for (const auto& [nx, ny] : meshes)
    for (const auto& [fill, name] : orderings)
      in_ms("ordering/" + name + "/" + std::to_string(nx) + "x" + std::to_string(ny), ordering, nx, ny, fill);
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
