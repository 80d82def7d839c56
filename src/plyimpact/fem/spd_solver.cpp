#include "plyimpact/fem/spd_solver.hpp"

#include <Eigen/CholmodSupport>
#include <Eigen/SparseCholesky>

#include <algorithm>
#include <chrono>
#include <memory>
#include <mutex>
#include <new>
#include <stdexcept>
#include <vector>

namespace plyimpact {

// Named rather than anonymous: SpdSolver::Impl (external linkage) holds these types as members, which
// GCC refuses (-Wsubobject-linkage) when this file is compiled inside a unity batch.
namespace spd_detail {

/// CHOLMOD's code of an ordering.
int cholmod_ordering(FillOrdering ordering) {
  switch (ordering) {
  case FillOrdering::metis:
    return CHOLMOD_METIS;
  case FillOrdering::nested_dissection:
    return CHOLMOD_NESDIS;
  case FillOrdering::amd:
    break;
  }
  return CHOLMOD_AMD;
}

/// Makes `common` try one ordering only (its default tries several and keeps the sparsest factor).
void use_one_ordering(cholmod_common& common, FillOrdering ordering) {
  common.nmethods = 1;
  common.method[0].ordering = cholmod_ordering(ordering);
  common.postorder = 1;
}

/// The sparsity pattern of a compressed matrix (column starts and row indices): a matrix of the same
/// pattern can be factored with the ordering and symbolic factor of the one analysed before.
class SparsityPattern {
public:
  SparsityPattern() = default;
  explicit SparsityPattern(const Eigen::SparseMatrix<double>& A) { remember(A); }
  [[nodiscard]] bool matches(const Eigen::SparseMatrix<double>& A) const {
    return A.isCompressed() && A.rows() == rows_ && A.cols() + 1 == std::ssize(starts_) &&
           std::equal(starts_.begin(), starts_.end(), A.outerIndexPtr()) &&
           A.nonZeros() == std::ssize(rows_of_entries_) &&
           std::equal(rows_of_entries_.begin(), rows_of_entries_.end(), A.innerIndexPtr());
  }
  /// Remembers A's pattern (none when A is not compressed: such a matrix is always analysed anew).
  void remember(const Eigen::SparseMatrix<double>& A) {
    rows_ = A.rows();
    starts_.clear();
    rows_of_entries_.clear();
    if (!A.isCompressed()) return;
    starts_.assign(A.outerIndexPtr(), A.outerIndexPtr() + A.cols() + 1);
    rows_of_entries_.assign(A.innerIndexPtr(), A.innerIndexPtr() + A.nonZeros());
  }

private:
  Eigen::Index rows_ = -1;
  std::vector<int> starts_, rows_of_entries_;
};

/// A CHOLMOD factorization (Eigen's wrapper `Factorization`) that analyses a pattern once: the
/// fill-reducing ordering and the symbolic factor are kept, and a matrix of the same pattern (a
/// refreshed K̄ of a damaged or non-linear plate) is factored from a copy of them, numbers only. The
/// analysis is deterministic, so the factor is the one a fresh analysis would give, bit for bit.
template <class Factorization>
class CholmodOnceAnalysed : public Factorization {
public:
  // CHOLMOD's own printing off: "CHOLMOD warning: not positive definite" reached the user's terminal beside
  // plyimpact's message, which names the deck values that cause it (issue 77); the status is still read
  CholmodOnceAnalysed() { this->cholmod().print = 0; }
  CholmodOnceAnalysed(const CholmodOnceAnalysed&) = delete;
  CholmodOnceAnalysed& operator=(const CholmodOnceAnalysed&) = delete;
  CholmodOnceAnalysed(CholmodOnceAnalysed&&) = delete;
  CholmodOnceAnalysed& operator=(CholmodOnceAnalysed&&) = delete;
  ~CholmodOnceAnalysed() {
    if (symbolic_ != nullptr) cholmod_free_factor(&symbolic_, &this->cholmod());
  }

  /// Takes `other`'s analysis (a copy of its symbolic factor, its pattern shared), if it has one.
  void adopt_analysis_of(const CholmodOnceAnalysed& other) {
    if (other.symbolic_ == nullptr) return;
    cholmod_factor* copy = cholmod_copy_factor(other.symbolic_, &this->cholmod());
    if (copy == nullptr) throw std::bad_alloc();
    if (symbolic_ != nullptr) cholmod_free_factor(&symbolic_, &this->cholmod());
    symbolic_ = copy;
    pattern_ = other.pattern_;
  }

  /// Analyses A unless it has the pattern analysed last; returns the entries its factor will hold
  /// below the diagonal (simplicial: from the column counts; supernodal: the supernodes' whole size).
  long analyse(const Eigen::SparseMatrix<double>& A) {
    if (symbolic_ == nullptr || !pattern_->matches(A)) {
      this->analyzePattern(A);
      if (symbolic_ != nullptr) cholmod_free_factor(&symbolic_, &this->cholmod());
      symbolic_ = cholmod_copy_factor(this->m_cholmodFactor, &this->cholmod());
      if (symbolic_ == nullptr) throw std::bad_alloc();
      pattern_ = std::make_shared<const SparsityPattern>(A);
    }
    if (symbolic_->is_super != 0) return static_cast<long>(symbolic_->xsize);
    const auto* count = static_cast<const int*>(symbolic_->ColCount);
    long below = 0;
    for (std::size_t j = 0; j < symbolic_->n; ++j)
      below += count[j] - 1;
    return below;
  }

  /// Factors A, with the analysis of its pattern (analysed first if it is not the pattern analysed last).
  void analyse_and_factor(const Eigen::SparseMatrix<double>& A) {
    (void)analyse(A);
    cholmod_free_factor(&this->m_cholmodFactor, &this->cholmod());
    this->m_cholmodFactor = cholmod_copy_factor(symbolic_, &this->cholmod());
    if (this->m_cholmodFactor == nullptr) throw std::bad_alloc();
    // The state analyzePattern() leaves, which an adopted analysis never went through (Eigen checks it
    // in builds with assertions).
    this->m_isInitialized = true;
    this->m_analysisIsOk = 1;
    this->factorize(A);
  }

private:
  cholmod_factor* symbolic_ = nullptr;             ///< the analysis of pattern_, never factored
  std::shared_ptr<const SparsityPattern> pattern_; ///< shared by the solvers that adopted the analysis
};

/// CHOLMOD's simplicial LDLᵀ, with access to the pivots D (the first entry of each column of the
/// simplicial factor) for the same positive-definiteness checks as Eigen's LDLᵀ.
class CholmodLdlt : public CholmodOnceAnalysed<Eigen::CholmodSimplicialLDLT<Eigen::SparseMatrix<double>>> {
public:
  CholmodLdlt() {
    use_one_ordering(cholmod(), FillOrdering::amd); // as SimplicialLDLT, memory estimate
    // CHOLMOD's own rule, with its switch moved: a supernodal LLᵀ (dense blocks, BLAS) where the
    // factor's flops per entry reach supernodal_flops_per_entry, the simplicial LDLᵀ below.
    cholmod().supernodal = CHOLMOD_AUTO;
    cholmod().supernodal_switch = supernodal_flops_per_entry;
  }
  [[nodiscard]] bool supernodal() const { return m_cholmodFactor->is_super != 0; }
  /// The pivots of the factor: D of LDLᵀ (the first entry of each column of the simplicial factor), or
  /// the squared diagonal of a supernodal L (each supernode a dense column-major block).
  [[nodiscard]] Eigen::VectorXd pivots() const {
    const cholmod_factor* L = m_cholmodFactor;
    Eigen::VectorXd d(static_cast<Eigen::Index>(L->n));
    const auto* x = static_cast<const double*>(L->x);
    if (L->is_super != 0) {
      const auto* super = static_cast<const int*>(L->super);
      const auto* pi = static_cast<const int*>(L->pi);
      const auto* px = static_cast<const int*>(L->px);
      for (std::size_t s = 0; s < L->nsuper; ++s) {
        const int rows = pi[s + 1] - pi[s];
        for (int j = super[s]; j < super[s + 1]; ++j) {
          const int local = j - super[s];
          const double l = x[px[s] + local * rows + local];
          d(j) = l * l;
        }
      }
      return d;
    }
    const auto* p = static_cast<const int*>(L->p);
    for (std::size_t j = 0; j < L->n; ++j)
      d(static_cast<Eigen::Index>(j)) = x[p[j]];
    return d;
  }
  /// x = A⁻¹ b by cholmod_solve2, which reuses X, Y and E when they have the right size (what
  /// cholmod_solve, and so Eigen's solve(), allocates and frees on every call).
  /// `common` is the caller's: the factor is only read, so that threads with their own commons may
  /// solve with it at once (CHOLMOD keeps its status and memory counts in the common).
  void solve_into(const Eigen::VectorXd& b, Eigen::VectorXd& x, cholmod_dense*& X, cholmod_dense*& Y,
                  cholmod_dense*& E, cholmod_common& common) const {
    cholmod_dense B{};
    B.nrow = B.d = static_cast<std::size_t>(b.size());
    B.ncol = 1;
    B.nzmax = B.nrow;
    B.x = const_cast<double*>(b.data()); // read only: CHOLMOD's B is const in meaning, not in type
    B.xtype = CHOLMOD_REAL;
    B.dtype = CHOLMOD_DOUBLE;
    if (cholmod_solve2(CHOLMOD_A, m_cholmodFactor, &B, nullptr, &X, nullptr, &Y, &E, &common) == 0 ||
        X == nullptr)
      throw std::runtime_error("CHOLMOD could not solve with its factor (out of memory?)");
    x = Eigen::Map<const Eigen::VectorXd>(static_cast<const double*>(X->x), b.size());
  }
  /// LDLᵀ ± C Cᵀ (cholmod_updown), C in the rows of A: permuted here to the factor's order (P C), as
  /// cholmod_updown works on the rows of L. False where CHOLMOD failed.
  bool updown(const Eigen::SparseMatrix<double>& C, bool update) {
    const cholmod_factor* L = m_cholmodFactor;
    const auto* perm = static_cast<const int*>(L->Perm);
    std::vector<int> row_of(L->n); // row of L of each row of A
    for (std::size_t k = 0; k < L->n; ++k)
      row_of[static_cast<std::size_t>(perm[k])] = static_cast<int>(k);
    std::vector<Eigen::Triplet<double>> entries;
    for (int j = 0; j < C.outerSize(); ++j)
      for (Eigen::SparseMatrix<double>::InnerIterator it(C, j); it; ++it)
        entries.emplace_back(row_of[static_cast<std::size_t>(it.row())], j, it.value());
    Eigen::SparseMatrix<double> PC(C.rows(), C.cols()); // compressed, rows sorted: as CHOLMOD asks
    PC.setFromTriplets(entries.begin(), entries.end());
    cholmod_sparse view = Eigen::viewAsCholmod(PC);
    return cholmod_updown(update ? 1 : 0, &view, m_cholmodFactor, &cholmod()) != 0 &&
           cholmod().status == CHOLMOD_OK;
  }
  [[nodiscard]] long factor_nonzeros() const { // strictly lower, as SimplicialLDLT reports it
    if (supernodal())
      return static_cast<long>(m_cholmodFactor->xsize) - static_cast<long>(m_cholmodFactor->n);
    const auto* nz = static_cast<const int*>(m_cholmodFactor->nz);
    long total = 0;
    for (std::size_t j = 0; j < m_cholmodFactor->n; ++j)
      total += nz[j] - 1;
    return total;
  }
};

/// The checks on an LDLᵀ factorization: it completed, its pivots are positive and none is many orders
/// below the largest. `pivots` is called only when the factorization completed.
template <class Pivots>
void check_ldlt(Eigen::ComputationInfo info, const Pivots& pivots) {
  if (info != Eigen::Success)
    throw NotPositiveDefinite("the matrix is not positive definite (a pivot of LDLᵀ is zero or negative)");
  const Eigen::VectorXd d = pivots();
  if (!(d.minCoeff() > 0.0))
    throw NotPositiveDefinite("the matrix is not positive definite (a pivot of LDLᵀ is zero or negative)");
  // A pivot many orders below the largest is a near-mechanism: round-off, not stiffness.
  if (d.minCoeff() < 1e-13 * d.maxCoeff())
    throw NotPositiveDefinite("the matrix is singular to working precision (pivot ratio below 1e-13)");
}

} // namespace spd_detail

using spd_detail::check_ldlt;
using spd_detail::CholmodLdlt;
using spd_detail::CholmodOnceAnalysed;
using spd_detail::SparsityPattern;
using spd_detail::use_one_ordering;

/// Eigen's SimplicialLDLT, whose analysis (the column counts of L) can be read before the factorization.
class EigenLdlt : public Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> {
public:
  [[nodiscard]] long analysed_nonzeros() const { return m_matrix.outerIndexPtr()[m_matrix.outerSize()]; }
};

struct SpdSolver::Impl {
  CholmodOnceAnalysed<Eigen::CholmodSupernodalLLT<Eigen::SparseMatrix<double>>> cholmod;
  EigenLdlt ldlt;
  SparsityPattern ldlt_pattern; ///< what `ldlt` analysed
  CholmodLdlt cholmod_ldlt;
  /// Eigen's CHOLMOD solves work in the factor's own common: one at a time.
  std::mutex common_mutex;
};

SpdSolver::SpdSolver(SparseSolverKind kind, FillOrdering ordering)
    : kind_(kind), ordering_(ordering), impl_(std::make_unique<Impl>()) {
  if (ordering == FillOrdering::amd) return; // each backend's default
  if (kind == SparseSolverKind::simplicial_ldlt)
    throw std::invalid_argument("Eigen's SimplicialLDLT orders by AMD only; METIS orderings need CHOLMOD");
  use_one_ordering(impl_->cholmod.cholmod(), ordering);
  use_one_ordering(impl_->cholmod_ldlt.cholmod(), ordering);
}
SpdSolver::~SpdSolver() = default;
SpdSolver::SpdSolver(SpdSolver&&) noexcept = default;
SpdSolver& SpdSolver::operator=(SpdSolver&&) noexcept = default;

void SpdSolver::adopt_analysis_of(const SpdSolver& other) {
  if (other.kind_ != kind_ || other.ordering_ != ordering_)
    throw std::invalid_argument(
        "SpdSolver: an analysis is adopted from a solver of the same kind and ordering");
  if (kind_ == SparseSolverKind::cholmod) impl_->cholmod.adopt_analysis_of(other.impl_->cholmod);
  if (kind_ == SparseSolverKind::cholmod_simplicial)
    impl_->cholmod_ldlt.adopt_analysis_of(other.impl_->cholmod_ldlt);
}

long SpdSolver::analyse(const Eigen::SparseMatrix<double>& A) {
  if (A.rows() == 0) throw NotPositiveDefinite("the system has no free degrees of freedom");
  if (kind_ == SparseSolverKind::cholmod) return impl_->cholmod.analyse(A);
  if (kind_ == SparseSolverKind::cholmod_simplicial) return impl_->cholmod_ldlt.analyse(A);
  if (!impl_->ldlt_pattern.matches(A)) {
    impl_->ldlt.analyzePattern(A);
    impl_->ldlt_pattern.remember(A);
  }
  return impl_->ldlt.analysed_nonzeros();
}

void SpdSolver::factorize(const Eigen::SparseMatrix<double>& A) {
  if (A.rows() == 0) throw NotPositiveDefinite("the system has no free degrees of freedom");
  if (kind_ == SparseSolverKind::cholmod) {
    impl_->cholmod.analyse_and_factor(A);
    if (impl_->cholmod.info() != Eigen::Success)
      throw NotPositiveDefinite("the matrix is not positive definite (CHOLMOD found a non-positive pivot)");
    return;
  }
  if (kind_ == SparseSolverKind::cholmod_simplicial) {
    impl_->cholmod_ldlt.analyse_and_factor(A);
    check_ldlt(impl_->cholmod_ldlt.info(), [&] { return impl_->cholmod_ldlt.pivots(); });
    return;
  }
  (void)analyse(A);
  impl_->ldlt.factorize(A); // with the ordering and elimination tree of the analysis
  check_ldlt(impl_->ldlt.info(), [&] { return Eigen::VectorXd(impl_->ldlt.vectorD()); });
}

Eigen::VectorXd SpdSolver::solve(const Eigen::VectorXd& b) const {
  if (kind_ == SparseSolverKind::cholmod) {
    const std::lock_guard lock(impl_->common_mutex);
    return impl_->cholmod.solve(b);
  }
  if (kind_ == SparseSolverKind::cholmod_simplicial) {
    Workspace w;
    Eigen::VectorXd x(b.size());
    solve(b, x, w);
    return x;
  }
  return impl_->ldlt.solve(b);
}

bool SpdSolver::modify(const Eigen::SparseMatrix<double>& C, bool update) {
  if (kind_ != SparseSolverKind::cholmod_simplicial) return false;
  if (impl_->cholmod_ldlt.supernodal()) return false; // updown works on a simplicial LDLᵀ only
  if (!impl_->cholmod_ldlt.updown(C, update)) return false;
  try {
    check_ldlt(Eigen::Success, [&] { return impl_->cholmod_ldlt.pivots(); });
  } catch (const NotPositiveDefinite&) {
    return false;
  }
  return true;
}

Eigen::MatrixXd SpdSolver::solve(const Eigen::MatrixXd& B) const {
  const std::lock_guard lock(impl_->common_mutex);
  if (kind_ == SparseSolverKind::cholmod) return impl_->cholmod.solve(B);
  if (kind_ == SparseSolverKind::cholmod_simplicial) return impl_->cholmod_ldlt.solve(B);
  return impl_->ldlt.solve(B);
}

/// CHOLMOD's arrays for cholmod_solve2 and the common they are allocated in, the workspace's own: solves
/// on one factor with different workspaces may run on several threads at once.
struct SpdSolver::Workspace::Buffers {
  cholmod_common common{};
  cholmod_dense* X = nullptr; ///< the solution
  cholmod_dense* Y = nullptr; ///< work arrays
  cholmod_dense* E = nullptr;
  Buffers() {
    cholmod_start(&common);
    common.print = 0; // no library text on the terminal: the solver reports its failures itself
  }
  Buffers(const Buffers&) = delete;
  Buffers& operator=(const Buffers&) = delete;
  ~Buffers() {
    for (cholmod_dense** D : {&X, &Y, &E})
      if (*D != nullptr) cholmod_free_dense(D, &common);
    cholmod_finish(&common);
  }
};

SpdSolver::Workspace::Workspace() : buffers_(std::make_unique<Buffers>()) {}
SpdSolver::Workspace::~Workspace() = default;
SpdSolver::Workspace::Workspace(Workspace&&) noexcept = default;
SpdSolver::Workspace& SpdSolver::Workspace::operator=(Workspace&&) noexcept = default;

void SpdSolver::solve(const Eigen::VectorXd& b, Eigen::VectorXd& x, Workspace& w) const {
  if (kind_ != SparseSolverKind::cholmod_simplicial) {
    x = solve(b);
    return;
  }
  Workspace::Buffers& buf = *w.buffers_;
  impl_->cholmod_ldlt.solve_into(b, x, buf.X, buf.Y, buf.E, buf.common);
}

bool SpdSolver::supernodal_factor() const {
  if (kind_ == SparseSolverKind::cholmod) return true;
  return kind_ == SparseSolverKind::cholmod_simplicial && impl_->cholmod_ldlt.supernodal();
}

long SpdSolver::factor_nonzeros() const {
  if (kind_ == SparseSolverKind::cholmod) return -1;
  if (kind_ == SparseSolverKind::cholmod_simplicial) return impl_->cholmod_ldlt.factor_nonzeros();
  return static_cast<long>(impl_->ldlt.matrixL().nestedExpression().nonZeros());
}

double SpdSolver::median_solve_seconds(int size, int repeats) const {
  Eigen::VectorXd b = Eigen::VectorXd::Ones(size);
  Eigen::VectorXd x(size);
  Workspace workspace;
  std::vector<double> t;
  for (int i = 0; i < repeats; ++i) {
    const auto t0 = std::chrono::steady_clock::now();
    solve(b, x, workspace);
    t.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
    b(0) += 1e-30 * x(0);
  }
  std::nth_element(t.begin(), t.begin() + repeats / 2, t.end());
  return t[static_cast<std::size_t>(repeats / 2)];
}

} // namespace plyimpact
