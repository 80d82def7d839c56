#pragma once
// Sparse symmetric positive-definite direct solver: factor once, solve many times.
#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <memory>
#include <stdexcept>

namespace plyimpact {

enum class SparseSolverKind {
  cholmod,         ///< CHOLMOD supernodal LLᵀ with its fill-reducing ordering (AMD/METIS)
  simplicial_ldlt, ///< Eigen's SimplicialLDLT with AMD ordering
  /// CHOLMOD simplicial LDLᵀ (AMD): the same kind of factor as simplicial_ldlt, with triangular solves
  /// that treat columns of equal pattern together: about 2× faster solves (bench/README.md). Where the
  /// factor is dense (flops per entry ≥ supernodal_flops_per_entry: a stack of sub-laminates on a
  /// coupon's mesh) CHOLMOD makes a supernodal LLᵀ instead, factored by BLAS blocks.
  cholmod_simplicial,
};

/// The flops per factor entry (CHOLMOD's flop count over nnz(L), from its analysis) from which the
/// cholmod_simplicial kind factors by supernodes (CHOLMOD's supernodal_switch; its own default is 40).
/// Measured (bench/README.md, "Supernodal where the factor is dense"): single plates lie at 64–134 and
/// the 6 615-equation stacked example at 427, where the simplicial LDLᵀ ran 10–25 % faster over whole
/// runs (many solves, few factorizations); the 107 611-equation stack of the ASTM coupon lies at 3 220,
/// where a run spent about 6 minutes simplicial before its first step, and a 3-step run took 18.4 s in all
/// by supernodes.
inline constexpr double supernodal_flops_per_entry = 1000.0;

/// The fill-reducing ordering of a CHOLMOD factor (bench/README.md, "Orderings", compares them).
enum class FillOrdering {
  amd,               ///< approximate minimum degree (the default; Eigen's SimplicialLDLT uses it too)
  metis,             ///< METIS nested dissection of the whole graph (CHOLMOD_METIS)
  nested_dissection, ///< CHOLMOD's own nested dissection (NESDIS: METIS partitions, CAMD on the parts)
};

/// The matrix is not positive definite (insufficient restraint, zero thickness, ...).
class NotPositiveDefinite : public std::runtime_error {
public:
  using std::runtime_error::runtime_error;
};

class SpdSolver {
public:
  /// `ordering` other than AMD needs a CHOLMOD backend (std::invalid_argument otherwise).
  explicit SpdSolver(SparseSolverKind kind = SparseSolverKind::simplicial_ldlt,
                     FillOrdering ordering = FillOrdering::amd);
  ~SpdSolver();
  SpdSolver(SpdSolver&&) noexcept;
  SpdSolver& operator=(SpdSolver&&) noexcept;
  SpdSolver(const SpdSolver&) = delete;
  SpdSolver& operator=(const SpdSolver&) = delete;

  /// Analyses the pattern (fill-reducing ordering, symbolic factor) and factors A. A matrix with the
  /// pattern of the one analysed last (a refreshed K̄: same mesh, new numbers) is factored with that
  /// analysis, numbers only; the factor is the same, bit for bit. Throws NotPositiveDefinite.
  void factorize(const Eigen::SparseMatrix<double>& A);
  /// The analysis alone (unless A has the pattern analysed last): returns the entries the factor of A
  /// will hold below its diagonal, so that its memory is known before it is made
  /// (analysis/impact/guards.hpp); factorize(A) then reuses the analysis.
  [[nodiscard]] long analyse(const Eigen::SparseMatrix<double>& A);
  /// Takes the analysis `other` made last (same kind and ordering), so that a matrix of its pattern is
  /// factored here without being ordered again: the factors of K̄ at each time-step level, all of one
  /// pattern. Eigen's LDLᵀ cannot share its analysis and makes its own.
  void adopt_analysis_of(const SpdSolver& other);
  /// Buffers that solve(b, x, workspace) keeps from one call to the next, so that a time loop solves
  /// without allocating (CHOLMOD's solution and work arrays, and the CHOLMOD common they live in).
  /// Belongs to one thread; may serve several solvers.
  class Workspace {
  public:
    Workspace();
    ~Workspace();
    Workspace(const Workspace&) = delete;
    Workspace& operator=(const Workspace&) = delete;
    Workspace(Workspace&&) noexcept;
    Workspace& operator=(Workspace&&) noexcept;

  private:
    friend class SpdSolver;
    struct Buffers;
    std::unique_ptr<Buffers> buffers_;
  };

  /// x = A⁻¹ b with the current factor. The solves may be called from several threads at once (runs
  /// that share a case, io/sweeps/sweep_runner.hpp): each solve(b, x, w) works in its workspace's CHOLMOD
  /// common, the others take turns in the factor's own.
  [[nodiscard]] Eigen::VectorXd solve(const Eigen::VectorXd& b) const;
  /// x = A⁻¹ b into x (sized once), with the buffers of `w`: the same numbers as solve(b). With
  /// cholmod_simplicial (the time loop's default) nothing is allocated after the first call but
  /// CHOLMOD 3.0's own work array (bench/README.md); the other backends solve as solve(b) does.
  void solve(const Eigen::VectorXd& b, Eigen::VectorXd& x, Workspace& w) const;
  [[nodiscard]] Eigen::MatrixXd solve(const Eigen::MatrixXd& B) const;
  /// Seconds for one solve(b, x, w) of `size` equations into kept buffers, as a time loop solves: the
  /// median of `repeats` (benchmarks).
  [[nodiscard]] double median_solve_seconds(int size, int repeats) const;
  /// Modifies the factor of A into the factor of A + C Cᵀ (`update`) or A − C Cᵀ, C of A's rows
  /// (CHOLMOD's multiple-rank update and downdate of a simplicial LDLᵀ, Davis & Hager): the cost of
  /// the factor's columns that C reaches, not of a factorization. Returns false, and leaves the solver
  /// to be factored anew, where the backend has no such update (cholmod_simplicial only) or the
  /// modified matrix is not positive definite.
  [[nodiscard]] bool modify(const Eigen::SparseMatrix<double>& C, bool update);
  [[nodiscard]] SparseSolverKind kind() const { return kind_; }
  [[nodiscard]] FillOrdering ordering() const { return ordering_; }
  /// Non-zeros of the factor (memory estimate), after factorize().
  [[nodiscard]] long factor_nonzeros() const;
  /// The factor made last is supernodal (LLᵀ by BLAS blocks): the cholmod kind, or cholmod_simplicial on
  /// a dense factor. Such a factor has no update (modify returns false).
  [[nodiscard]] bool supernodal_factor() const;

private:
  struct Impl;
  SparseSolverKind kind_;
  FillOrdering ordering_;
  std::unique_ptr<Impl> impl_;
};

} // namespace plyimpact
