#include "plyimpact/analysis/plate_analyses/modal_analysis.hpp"

#include "plyimpact/fem/element_loop.hpp"
#include "plyimpact/fem/equation_subset.hpp"

#include <Eigen/SparseCholesky>
#include <Spectra/SymEigsSolver.h>
#include <Spectra/SymGEigsShiftSolver.h>
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <numbers>
#include <optional>
#include <stdexcept>

namespace plyimpact {

namespace {

/// y = A x with A = M^-½ K M^-½ (the symmetric form whose eigenvalues are the ω² of K φ = ω² M φ), not
/// formed: y = M^-½ (K (M^-½ x)). Formed, A took longer to build than the Lanczos iteration took to run
/// (7 of the 9 s of the coupon's 107 611 equations, where selective mass scaling widens its pattern to
/// 57.7 million entries). K is symmetric with both triangles stored, so its column-major arrays read as
/// rows are K (no copy); the rows go to the element-loop threads in fixed blocks (parallel_rows_product)
/// and M^-½ is a diagonal or BlockDiagonalMass::apply_inverse_sqrt: the same bits for any number of
/// threads.
class MassNormalisedStiffnessOp {
public:
  using Scalar = double;
  using InverseSqrt = std::function<void(const Eigen::VectorXd&, Eigen::VectorXd&)>;
  MassNormalisedStiffnessOp(const SparseMatrix& K, InverseSqrt inverse_sqrt)
      : K_rows_(K.rows(), K.cols(), K.nonZeros(), K.outerIndexPtr(), K.innerIndexPtr(), K.valuePtr()),
        inverse_sqrt_(std::move(inverse_sqrt)), x_(K.cols()), t_(K.cols()), y_(K.rows()) {
    if (!K.isCompressed()) throw std::invalid_argument("highest_mode: the stiffness must be compressed");
  }
  [[nodiscard]] Eigen::Index rows() const { return K_rows_.rows(); }
  [[nodiscard]] Eigen::Index cols() const { return K_rows_.cols(); }
  void perform_op(const double* x_in, double* y_out) const {
    x_ = Eigen::Map<const Eigen::VectorXd>(x_in, cols());
    inverse_sqrt_(x_, t_);
    parallel_rows_product(K_rows_, t_, y_);
    inverse_sqrt_(y_, t_);
    Eigen::Map<Eigen::VectorXd>(y_out, rows()) = t_;
  }

private:
  Eigen::Map<const Eigen::SparseMatrix<double, Eigen::RowMajor>> K_rows_;
  InverseSqrt inverse_sqrt_;
  mutable Eigen::VectorXd x_, t_, y_; ///< Spectra's vectors copied in and out, and M^-½ x (sized once)
};

/// y = (K − σM)⁻¹ x with one sparse LDLᵀ factorization per shift (Spectra's shift-invert operator).
class ShiftInvertOp {
public:
  using Scalar = double;
  ShiftInvertOp(const SparseMatrix& K, const SparseMatrix& M) : K_(K), M_(M) {}
  [[nodiscard]] Eigen::Index rows() const { return K_.rows(); }
  [[nodiscard]] Eigen::Index cols() const { return K_.cols(); }
  /// Factors K − σM, unless it is factored at this σ already (Spectra sets the shift it was given).
  void set_shift(double sigma) {
    if (shift_ == sigma) return;
    shift_.reset();
    const SparseMatrix A = K_ - sigma * M_;
    ldlt_.compute(A);
    if (ldlt_.info() != Eigen::Success)
      throw std::runtime_error("modal analysis: K - sigma M could not be factored");
    shift_ = sigma;
  }
  /// Whether K is positive definite (pivots above 1e-12 of the largest), from its factor at σ = 0.
  [[nodiscard]] bool stiffness_definite() {
    try {
      set_shift(0.0);
    } catch (const std::runtime_error&) {
      return false;
    }
    return ldlt_.vectorD().minCoeff() > 1e-12 * ldlt_.vectorD().maxCoeff();
  }
  void perform_op(const double* x_in, double* y_out) const {
    Eigen::Map<const Eigen::VectorXd> x(x_in, rows());
    Eigen::Map<Eigen::VectorXd> y(y_out, rows());
    y = ldlt_.solve(x);
  }

private:
  const SparseMatrix& K_;
  const SparseMatrix& M_;
  Eigen::SimplicialLDLT<SparseMatrix> ldlt_;
  std::optional<double> shift_; ///< the σ of ldlt_, if it holds a factor
};

/// The `count` lowest modes, or the `count_if_definite` lowest where K is positive definite (no rigid-body
/// or spurious zero-energy mode can then come first).
ModalResult lowest_modes(const SparseMatrix& K, const SparseMatrix& M, int count, int count_if_definite);

} // namespace

ModalResult solve_modal(const DiscretePlate& model, int count) {
  return solve_modal(model, count, model.mass_kind());
}

double fundamental_period(const DiscretePlate& model) {
  require_bilateral(model.boundary(), "the modal analysis");
  // The time loop's equations: the in-plane DOFs, exactly decoupled from bending for most laminates,
  // carry modes far above the bending ones and no share of a transverse impact.
  const SparseMatrix K_model = model.stiffness(), M_model = model.mass(model.mass_kind());
  const EquationSubset equations = bending_equations_if_decoupled(model, K_model, M_model);
  return fundamental_period(equations.restrict(K_model), equations.restrict(M_model));
}

double fundamental_period(const SparseMatrix& K, const SparseMatrix& M) {
  // A supported plate's lowest mode is elastic, and one mode costs a third of seven (the Lanczos basis
  // shrinks from 27 vectors to 21, with fewer restarts). A free plate has 6 rigid-body modes, and q9's
  // spurious zero-energy modes come on top (docs/elements.md): ask for more until one is elastic.
  const int most = static_cast<int>(K.rows()) - 2;
  for (int count = 7;; count = std::min(2 * count, most)) {
    const ModalResult r = lowest_modes(K, M, count, 1);
    for (const double f : r.frequencies_hz)
      if (f > 0.0) return 1.0 / f;
    if (count >= most)
      throw std::runtime_error(
          fmt::format("impact: the plate has no elastic mode among its lowest {}", count));
  }
}

ModalResult solve_modal(const DiscretePlate& model, int count, MassMatrix mass) {
  require_bilateral(model.boundary(), "the modal analysis");
  return solve_modal(model.stiffness(), model.mass(mass), count);
}

ModalResult solve_modal(const SparseMatrix& K, const SparseMatrix& M, int count) {
  return lowest_modes(K, M, count, count);
}

namespace {

ModalResult lowest_modes(const SparseMatrix& K, const SparseMatrix& M, int count, int count_if_definite) {
  const auto n = static_cast<int>(K.rows());
  if (std::min(count, n - 2) < 1)
    throw std::invalid_argument("modal analysis: the plate has too few free DOFs");
  // Shift: σ = 0 (plain inverse iteration on K) when K is positive definite. A free or partly free
  // plate has a singular K; then a small negative shift keeps K − σM positive definite so rigid-body
  // and spurious modes are found and reported, not hidden.
  // The test factors K as the operator's factor at σ = 0, which Spectra then reuses (one factorization).
  ShiftInvertOp op(K, M);
  double sigma = 0.0;
  const bool definite = op.stiffness_definite();
  const int nev = std::min(definite ? count_if_definite : count, n - 2);
  if (!definite) {
    double ratio = 0.0;
    int terms = 0;
    for (int i = 0; i < n; ++i)
      if (M.coeff(i, i) > 0.0) ratio += K.coeff(i, i) / M.coeff(i, i), ++terms;
    sigma = -1e-6 * ratio / std::max(terms, 1);
  }
  // The Lanczos iteration multiplies by M some hundred times. A lumped M is assembled on K's pattern
  // with zeros off the diagonal; dropped, its products cost n instead of nnz(K) (the same sums: the
  // dropped terms are exact zeros).
  SparseMatrix M_stored = M;
  M_stored.prune(0.0);
  Spectra::SparseSymMatProd<double> Bop(M_stored);
  const int ncv = std::min(n, std::max(2 * nev + 1, nev + 20));
  Spectra::SymGEigsShiftSolver<ShiftInvertOp, Spectra::SparseSymMatProd<double>,
                               Spectra::GEigsMode::ShiftInvert>
      solver(op, Bop, nev, ncv, sigma);
  solver.init();
  solver.compute(Spectra::SortRule::LargestMagn, 2000, 1e-12);
  if (solver.info() != Spectra::CompInfo::Successful)
    throw std::runtime_error("modal analysis: the eigensolver did not converge");

  const Eigen::VectorXd lambda = solver.eigenvalues(); // ω², nearest the shift first = ascending
  const Eigen::MatrixXd vectors = solver.eigenvectors();
  std::vector<int> order(static_cast<std::size_t>(lambda.size()));
  for (std::size_t i = 0; i < order.size(); ++i)
    order[i] = static_cast<int>(i);
  std::sort(order.begin(), order.end(), [&](int a, int b) { return lambda(a) < lambda(b); });

  ModalResult r;
  r.modes.resize(n, lambda.size());
  // Zero-energy test on the Rayleigh quotient: φᵀKφ relative to the largest stiffness entry times
  // φᵀφ is round-off (< 1e-12) for rigid and spurious modes, and above 1e-11 for the lowest elastic
  // mode of plates up to a/h ≈ 1e5.
  const double k_scale = K.diagonal().cwiseAbs().maxCoeff();
  for (std::size_t i = 0; i < order.size(); ++i) {
    const double l = lambda(order[i]);
    const Eigen::VectorXd phi = vectors.col(order[i]);
    const double energy = phi.dot(K * phi) / (k_scale * phi.squaredNorm());
    const bool zero = std::abs(energy) < 1e-12;
    if (zero) ++r.zero_energy_modes;
    r.frequencies_hz.push_back(zero ? 0.0 : std::sqrt(std::max(l, 0.0)) / (2.0 * std::numbers::pi));
    r.modes.col(static_cast<Eigen::Index>(i)) = phi;
  }
  return r;
}

} // namespace

double highest_angular_frequency(const SparseMatrix& K, const Eigen::VectorXd& mass) {
  return highest_mode(K, mass).omega;
}

namespace {

/// The largest eigenvalue of the symmetric form A = M^-½ K M^-½ by Lanczos, as highest_mode returns it.
HighestMode highest_of_symmetric_form(MassNormalisedStiffnessOp op) {
  const auto n = static_cast<int>(op.rows());
  Spectra::SymEigsSolver<MassNormalisedStiffnessOp> solver(op, 1, std::min(n, 20));
  // Spectra's own failures (its std::logic_error "TridiagEigen: eigen decomposition failed" reached the
  // user as an internal error, issue 77) and a result that is not a number say what the usual cause is
  constexpr const char* cause =
      "the stiffness or the mass holds values far out of scale: with [time] mass_scaling, a target_dt far "
      "beyond the mesh's own stable step (it adds masses beyond any plate's); else check the moduli, the "
      "densities and the element sizes";
  try {
    solver.init();
    solver.compute(Spectra::SortRule::LargestAlge, 1000, highest_frequency_tolerance);
  } catch (const std::exception& e) {
    throw std::runtime_error(
        fmt::format("the highest natural frequency of the plate, which sets the explicit "
                    "step, could not be computed (Lanczos: {}): {}",
                    e.what(), cause));
  }
  if (solver.info() != Spectra::CompInfo::Successful || !std::isfinite(solver.eigenvalues()(0)))
    throw std::runtime_error(
        fmt::format("the highest natural frequency of the plate, which sets the explicit "
                    "step, could not be computed (the Lanczos iterations did not "
                    "converge): {}",
                    cause));
  // The Ritz value θ lies below λ_max; Spectra stops where the residual ‖r‖ ≤ tol·θ, and an eigenvalue
  // lies within ‖r‖ of θ (symmetric A): θ(1 + tol) bounds the one it converged to from above.
  HighestMode mode;
  mode.omega = std::sqrt(solver.eigenvalues()(0) * (1.0 + highest_frequency_tolerance));
  Eigen::Index largest = 0;
  (void)solver.eigenvectors().col(0).cwiseAbs().maxCoeff(&largest); // the vector of M^½ φ
  mode.equation = static_cast<int>(largest);
  return mode;
}

} // namespace

HighestMode highest_mode(const SparseMatrix& K, const Eigen::VectorXd& mass) {
  const auto n = static_cast<int>(K.rows());
  if (n < 3) throw std::invalid_argument("highest_angular_frequency: too few DOFs");
  if (mass.size() != n || !(mass.minCoeff() > 0.0))
    throw std::invalid_argument("highest_angular_frequency: the mass must be diagonal and positive");
  const Eigen::VectorXd scale = mass.cwiseSqrt().cwiseInverse();
  return highest_of_symmetric_form(MassNormalisedStiffnessOp(
      K, [&scale](const Eigen::VectorXd& r, Eigen::VectorXd& x) { x = scale.cwiseProduct(r); }));
}

HighestMode highest_mode(const SparseMatrix& K, const BlockDiagonalMass& mass) {
  if (K.rows() < 3) throw std::invalid_argument("highest_angular_frequency: too few DOFs");
  if (mass.size() != K.rows())
    throw std::invalid_argument("highest_angular_frequency: the mass and the stiffness differ in size");
  return highest_of_symmetric_form(MassNormalisedStiffnessOp(
      K, [&mass](const Eigen::VectorXd& r, Eigen::VectorXd& x) { mass.apply_inverse_sqrt(r, x); }));
}

} // namespace plyimpact
