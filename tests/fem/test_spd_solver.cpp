// The sparse SPD solver backends (fem/spd_solver.*): each solves K̄ x = b to round-off against a dense
// Cholesky, and each refuses a singular matrix (an unrestrained plate) with NotPositiveDefinite.
#include "plyimpact/fem/spd_solver.hpp"
#include "support/decks.hpp"

#include <gtest/gtest.h>

#include <Eigen/Dense>

#include <cmath>
#include <stdexcept>
#include <vector>

namespace plyimpact::spd_solver_tests {
namespace {

class SpdSolverBackends : public ::testing::TestWithParam<SparseSolverKind> {};

DiscretePlate small_plate(const std::string& edges) {
  const Laminate lam = test::laminate_of(test::thesis_3_6(), "[45/90/-45/0]s", 0.5e-3);
  return {lam, {0.127, 0.0762}, {4, 3, MassMatrix::lumped, ElementFormulation::q9}, test::all_edges(edges)};
}

TEST_P(SpdSolverBackends, SolvesTheEffectiveStiffnessToRoundOff) {
  // K̄ = K + 4M/Δt² at Δt = 1 µs, as in the impact time loop; reference: dense LLᵀ of the same matrix.
  const DiscretePlate model = small_plate("ss");
  const SparseMatrix Kbar = model.stiffness() + (4.0 / 1e-12) * model.mass();
  const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(Kbar.rows(), -1.0, 2.0);
  const Eigen::VectorXd reference = Eigen::MatrixXd(Kbar).llt().solve(b);
  SpdSolver solver(GetParam());
  solver.factorize(Kbar);
  const Eigen::VectorXd x = solver.solve(b);
  EXPECT_LT((x - reference).norm(), 1e-11 * reference.norm());
  const Eigen::MatrixXd X = solver.solve(Eigen::MatrixXd(b.replicate(1, 2)));
  EXPECT_LT((X.col(1) - reference).norm(), 1e-11 * reference.norm());
}

TEST_P(SpdSolverBackends, WorkspaceSolveGivesTheNumbersOfThePlainSolve) {
  // The time loop's solve into a kept vector with kept buffers: bit for bit the plain solve's x, on
  // repeated calls and after the solver factors another matrix of another size with the same buffers.
  SpdSolver solver(GetParam());
  SpdSolver::Workspace workspace;
  Eigen::VectorXd x;
  for (const char* edges : {"ss", "clamped"}) {
    const DiscretePlate model = small_plate(edges);
    const SparseMatrix Kbar = model.stiffness() + (4.0 / 1e-12) * model.mass();
    solver.factorize(Kbar);
    for (int call = 0; call < 3; ++call) {
      const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(Kbar.rows(), -1.0 + call, 2.0);
      solver.solve(b, x, workspace);
      const Eigen::VectorXd plain = solver.solve(b);
      ASSERT_EQ(x.size(), plain.size());
      EXPECT_EQ(x, plain) << edges << ", call " << call;
    }
  }
}

TEST_P(SpdSolverBackends, AMatrixOfTheAnalysedPatternReusesTheAnalysisAndGetsTheFreshFactor) {
  // A refreshed K̄ (other numbers on the same mesh: here another Δt) is factored with the ordering and
  // symbolic factor of the last analysis: its solution is bit for bit that of a solver that analyses it
  // afresh, and it is K̄'s own (to round-off against a dense LLᵀ, far from the old matrix's solution).
  // A matrix of another pattern, of the same size (one coupling more, v (eᵢ + eⱼ)(eᵢ + eⱼ)ᵀ, positive
  // semi-definite) or of another size, is analysed anew: an entry outside the kept pattern would be
  // lost and miss the dense solution by the coupling's whole effect.
  const DiscretePlate model = small_plate("ss");
  const SparseMatrix first = model.stiffness() + (4.0 / 1e-12) * model.mass();
  const SparseMatrix refreshed = model.stiffness() + (4.0 / 4e-12) * model.mass();
  const auto n = static_cast<int>(first.rows());
  const double v = first.diagonal().maxCoeff();
  SparseMatrix pair(n, n);
  pair.insert(0, 0) = v;
  pair.insert(0, n - 1) = v;
  pair.insert(n - 1, 0) = v;
  pair.insert(n - 1, n - 1) = v;
  const SparseMatrix coupled = refreshed + pair;
  ASSERT_GT(coupled.nonZeros(), refreshed.nonZeros()); // another pattern, the same size
  const SparseMatrix other_size = [] {
    const DiscretePlate clamped = small_plate("clamped");
    return SparseMatrix(clamped.stiffness() + (4.0 / 1e-12) * clamped.mass());
  }();
  ASSERT_NE(other_size.rows(), first.rows());

  SpdSolver solver(GetParam());
  solver.factorize(first);
  for (const SparseMatrix* A : {&refreshed, &coupled, &other_size, &refreshed}) {
    const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(A->rows(), -1.0, 2.0);
    const Eigen::VectorXd dense = Eigen::MatrixXd(*A).llt().solve(b);
    solver.factorize(*A);
    SpdSolver fresh(GetParam());
    fresh.factorize(*A);
    const Eigen::VectorXd x = solver.solve(b);
    EXPECT_EQ(x, fresh.solve(b)) << "matrix of " << A->nonZeros() << " entries";
    EXPECT_LT((x - dense).norm(), 1e-11 * dense.norm()) << "matrix of " << A->nonZeros() << " entries";
  }
  // The couplings and the step matter: each matrix's solution is far from the others'.
  const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(n, -1.0, 2.0);
  const Eigen::VectorXd x_first = Eigen::MatrixXd(first).llt().solve(b);
  const Eigen::VectorXd x_refreshed = Eigen::MatrixXd(refreshed).llt().solve(b);
  const Eigen::VectorXd x_coupled = Eigen::MatrixXd(coupled).llt().solve(b);
  EXPECT_GT((x_refreshed - x_first).norm(), 1e-3 * x_refreshed.norm());
  EXPECT_GT((x_coupled - x_refreshed).norm(), 1e-3 * x_refreshed.norm());
}

TEST_P(SpdSolverBackends, TheAnalysisTellsTheSizeOfTheFactorBeforeItIsMade) {
  // The memory guard reads the factor's size from the analysis (analysis/impact/guards.hpp): for the
  // simplicial factors it is the count of the factor made after it, which reuses that analysis; a supernodal
  // factor stores its supernodes whole, at least the lower triangle of the matrix. Fill-in makes the factor
  // larger than the matrix's lower triangle.
  const DiscretePlate model = small_plate("ss");
  const SparseMatrix Kbar = model.stiffness() + (4.0 / 1e-12) * model.mass();
  const long lower = (Kbar.nonZeros() - Kbar.rows()) / 2;
  SpdSolver solver(GetParam());
  const long analysed = solver.analyse(Kbar);
  EXPECT_GT(analysed, lower);
  EXPECT_EQ(solver.analyse(Kbar), analysed);
  solver.factorize(Kbar);
  if (GetParam() != SparseSolverKind::cholmod) {
    EXPECT_EQ(solver.factor_nonzeros(), analysed);
  }
  const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(Kbar.rows(), -1.0, 2.0);
  SpdSolver fresh(GetParam());
  fresh.factorize(Kbar);
  EXPECT_EQ(solver.solve(b), fresh.solve(b));
}

TEST_P(SpdSolverBackends, ASolverThatAdoptsAnotherOnesAnalysisGetsTheFreshFactor) {
  // The factors of K̄ at two time-step levels (analysis/integrators/linear_step.cpp): the second solver takes
  // the first one's analysis and factors its own matrix of the same pattern, bit for bit as a solver that
  // analyses it afresh; a matrix of another pattern is still analysed anew. Only a solver of the same
  // kind and ordering can lend its analysis.
  const DiscretePlate model = small_plate("ss");
  const SparseMatrix level0 = model.stiffness() + (4.0 / 4e-12) * model.mass();
  const SparseMatrix level1 = model.stiffness() + (4.0 / 1e-12) * model.mass();
  const DiscretePlate clamped = small_plate("clamped");
  const SparseMatrix other = clamped.stiffness() + (4.0 / 1e-12) * clamped.mass();
  SpdSolver first(GetParam());
  first.factorize(level0);
  SpdSolver second(GetParam());
  second.adopt_analysis_of(first);
  for (const SparseMatrix* A : {&level1, &other}) {
    second.factorize(*A);
    SpdSolver fresh(GetParam());
    fresh.factorize(*A);
    const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(A->rows(), -1.0, 2.0);
    EXPECT_EQ(second.solve(b), fresh.solve(b));
  }
  const SparseSolverKind another = GetParam() == SparseSolverKind::cholmod
                                       ? SparseSolverKind::cholmod_simplicial
                                       : SparseSolverKind::cholmod;
  SpdSolver mismatched(another);
  EXPECT_THROW(mismatched.adopt_analysis_of(first), std::invalid_argument);
}

TEST_P(SpdSolverBackends, RefusesASingularStiffness) {
  // A plate with free edges has six rigid-body motions: K is singular.
  const DiscretePlate model = small_plate("00000");
  SpdSolver solver(GetParam());
  EXPECT_THROW(solver.factorize(model.stiffness()), NotPositiveDefinite);
}

TEST(SpdSolver, CholmodSimplicialHasAboutTheFillOfEigensLdlt) {
  // Both order by AMD (CHOLMOD's own AMD and Eigen's port of it differ in details: 5 175 against 5 550
  // here), so the memory estimate built on Eigen's symbolic analysis (analysis/impact/guards) holds for both.
  const DiscretePlate model = small_plate("clamped");
  const SparseMatrix Kbar = model.stiffness() + (4.0 / 1e-12) * model.mass();
  SpdSolver eigen(SparseSolverKind::simplicial_ldlt), cholmod(SparseSolverKind::cholmod_simplicial);
  eigen.factorize(Kbar);
  cholmod.factorize(Kbar);
  EXPECT_GT(eigen.factor_nonzeros(), Kbar.nonZeros() / 2);
  EXPECT_NEAR(static_cast<double>(cholmod.factor_nonzeros()) / static_cast<double>(eigen.factor_nonzeros()),
              1.0, 0.1);
}

/// Columns of an update C over the plate's equations: a penalty spring between two DOFs and one that
/// grounds a third (the shape of an interface point's jump), scaled by `k`.
SparseMatrix spring_columns(int n, double k) {
  SparseMatrix C(n, 2);
  C.insert(3, 0) = std::sqrt(k);
  C.insert(n - 5, 0) = -std::sqrt(k);
  C.insert(n / 2, 1) = std::sqrt(0.5 * k);
  return C;
}

TEST(SpdSolver, RankUpdatesGiveTheFactorOfTheModifiedMatrix) {
  // The factor of K̄ updated by C Cᵀ solves K̄ + C Cᵀ, and the downdate by the same C solves K̄ again: the
  // lagged delamination step's refresh, whose penalty springs are of the order of K̄'s diagonal. The
  // updates are not as exact as a factorization (relative residuals here: fresh 5.8e-15, updated
  // 4.5e-11, downdated 1.0e-9; springs 1000 times the diagonal: 1.1e-8 and 8.7e-7): enough for an
  // iteration matrix, whose Newton residual is evaluated exactly, while a wrong update misses by the
  // springs' whole effect (above 1e-3).
  const DiscretePlate model = small_plate("ss");
  const SparseMatrix Kbar = model.stiffness() + (4.0 / 1e-12) * model.mass();
  const auto n = static_cast<int>(Kbar.rows());
  const SparseMatrix C = spring_columns(n, Kbar.diagonal().maxCoeff());
  const SparseMatrix stiffened = Kbar + SparseMatrix(C * C.transpose());
  const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(n, -1.0, 2.0);
  const auto residual = [&b](const SparseMatrix& A, const Eigen::VectorXd& x) {
    return (A * x - b).norm() / b.norm();
  };
  const Eigen::VectorXd original = Eigen::MatrixXd(Kbar).llt().solve(b);
  ASSERT_GT(residual(stiffened, original), 1e-3); // the springs matter
  SpdSolver solver(SparseSolverKind::cholmod_simplicial);
  solver.factorize(Kbar);
  ASSERT_TRUE(solver.modify(C, true));
  EXPECT_LT(residual(stiffened, solver.solve(b)), 1e-8);
  ASSERT_TRUE(solver.modify(C, false));
  EXPECT_LT(residual(Kbar, solver.solve(b)), 1e-8);
}

TEST(SpdSolver, ADowndateThatLeavesNoPositiveMatrixOrABackendWithoutUpdatesAsksForAFactorization) {
  const DiscretePlate model = small_plate("ss");
  const SparseMatrix Kbar = model.stiffness() + (4.0 / 1e-12) * model.mass();
  const SparseMatrix C = spring_columns(static_cast<int>(Kbar.rows()), 1e3 * Kbar.diagonal().maxCoeff());
  SpdSolver simplicial(SparseSolverKind::cholmod_simplicial);
  simplicial.factorize(Kbar);
  EXPECT_FALSE(simplicial.modify(C, false)); // K̄ − C Cᵀ has a negative pivot
  for (const SparseSolverKind kind : {SparseSolverKind::simplicial_ldlt, SparseSolverKind::cholmod}) {
    SpdSolver solver(kind);
    solver.factorize(Kbar);
    EXPECT_FALSE(solver.modify(C, true));
  }
}

/// The Kac–Murdock–Szegő matrix ρ^|i−j| of order n, stored as a sparse matrix with every entry: dense,
/// symmetric positive definite for |ρ| < 1, its eigenvalues within [(1 − ρ)/(1 + ρ), (1 + ρ)/(1 − ρ)].
SparseMatrix kms_matrix(int n, double rho) {
  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(static_cast<std::size_t>(n) * static_cast<std::size_t>(n));
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i)
      entries.emplace_back(i, j, std::pow(rho, std::abs(i - j)));
  SparseMatrix A(n, n);
  A.setFromTriplets(entries.begin(), entries.end());
  return A;
}

TEST(SpdSolver, ADenseFactorIsMadeBySupernodesAndAPlatesBySimplicialColumns) {
  // CHOLMOD's switch at supernodal_flops_per_entry: a dense factor of order n costs n³/3 flops for n²/2
  // entries, 2n/3 per entry, above the switch for n = 1 800; a plate's factor is far below it. The
  // supernodal factor solves to round-off like the simplicial one, has no rank update, and refuses a
  // singular matrix (all ones: rank one) as the pivots' checks do.
  const int n = 1800;
  ASSERT_GT(2.0 * n / 3.0, supernodal_flops_per_entry);
  const SparseMatrix A = kms_matrix(n, 0.99);
  const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(n, -1.0, 2.0);
  const Eigen::VectorXd reference = Eigen::MatrixXd(A).llt().solve(b);
  SpdSolver dense(SparseSolverKind::cholmod_simplicial);
  dense.factorize(A);
  EXPECT_TRUE(dense.supernodal_factor());
  EXPECT_LT((dense.solve(b) - reference).norm(), 1e-11 * reference.norm());
  SpdSolver::Workspace workspace;
  Eigen::VectorXd x;
  dense.solve(b, x, workspace);
  EXPECT_EQ(x, dense.solve(b));
  EXPECT_FALSE(dense.modify(spring_columns(n, 1.0), true));
  EXPECT_GE(dense.factor_nonzeros(), static_cast<long>(n) * (n - 1) / 2);
  SpdSolver singular(SparseSolverKind::cholmod_simplicial);
  EXPECT_THROW(singular.factorize(kms_matrix(n, 1.0)), NotPositiveDefinite);

  const DiscretePlate model = small_plate("ss");
  SpdSolver plate(SparseSolverKind::cholmod_simplicial);
  plate.factorize(model.stiffness() + (4.0 / 1e-12) * model.mass());
  EXPECT_FALSE(plate.supernodal_factor());
}

TEST(SpdSolver, EveryFillOrderingSolvesToRoundOffAndChangesOnlyTheFill) {
  // A fill-reducing ordering permutes the unknowns: the solution is the same to round-off whichever
  // CHOLMOD uses, and the orderings differ (on 12 elements, METIS and NESDIS find other fills than AMD).
  const DiscretePlate model = small_plate("ss");
  const SparseMatrix Kbar = model.stiffness() + (4.0 / 1e-12) * model.mass();
  const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(Kbar.rows(), -1.0, 2.0);
  const Eigen::VectorXd reference = Eigen::MatrixXd(Kbar).llt().solve(b);
  std::vector<long> fill;
  for (const FillOrdering ordering :
       {FillOrdering::amd, FillOrdering::metis, FillOrdering::nested_dissection})
    for (const SparseSolverKind kind : {SparseSolverKind::cholmod_simplicial, SparseSolverKind::cholmod}) {
      SpdSolver solver(kind, ordering);
      solver.factorize(Kbar);
      EXPECT_LT((solver.solve(b) - reference).norm(), 1e-11 * reference.norm()) << static_cast<int>(ordering);
      if (kind == SparseSolverKind::cholmod_simplicial) fill.push_back(solver.factor_nonzeros());
    }
  EXPECT_NE(fill[0], fill[1]);
  EXPECT_NE(fill[0], fill[2]);
  // Eigen's SimplicialLDLT has AMD only: asking it for METIS is refused, not silently ignored.
  EXPECT_THROW(SpdSolver(SparseSolverKind::simplicial_ldlt, FillOrdering::metis), std::invalid_argument);
}

INSTANTIATE_TEST_SUITE_P(Backends, SpdSolverBackends,
                         ::testing::Values(SparseSolverKind::simplicial_ldlt,
                                           SparseSolverKind::cholmod_simplicial, SparseSolverKind::cholmod),
                         [](const auto& backend) {
                           switch (backend.param) {
                           case SparseSolverKind::simplicial_ldlt:
                             return std::string("eigen_simplicial_ldlt");
                           case SparseSolverKind::cholmod_simplicial:
                             return std::string("cholmod_simplicial");
                           case SparseSolverKind::cholmod:
                             return std::string("cholmod_supernodal");
                           }
                           return std::string("unknown");
                         });

} // namespace
} // namespace plyimpact::spd_solver_tests
