#include "plyimpact/analysis/plate_analyses/buckling_analysis.hpp"

#include "plyimpact/analysis/plate_analyses/static_analysis.hpp"

#include <Spectra/MatOp/SparseCholesky.h>
#include <Spectra/MatOp/SparseSymMatProd.h>
#include <Spectra/SymGEigsSolver.h>

#include <algorithm>
#include <stdexcept>

namespace plyimpact {

BucklingResult solve_buckling(const DiscretePlate& model, const BucklingSettings& settings) {
  require_bilateral(model.boundary(), "the buckling analysis");
  const SparseMatrix K = model.stiffness();
  (void)factor_stiffness(model, K); // clear message when the plate is not restrained enough
  Eigen::Matrix2d N;
  N << settings.Nx, settings.Nxy, settings.Nxy, settings.Ny;
  // K φ = λ G φ with G = −K_σ: solve G φ = μ K φ for the largest μ = 1/λ (K positive definite).
  const SparseMatrix G = -model.geometric_stiffness(N);
  const auto n = static_cast<int>(K.rows());
  const int nev = std::min(settings.count, n - 2);
  Spectra::SparseSymMatProd<double> op(G);
  Spectra::SparseCholesky<double> Bop(K);
  if (Bop.info() != Spectra::CompInfo::Successful)
    throw std::runtime_error("buckling: K could not be factored");
  const int ncv = std::min(n, std::max(2 * nev + 1, nev + 20));
  Spectra::SymGEigsSolver<Spectra::SparseSymMatProd<double>, Spectra::SparseCholesky<double>,
                          Spectra::GEigsMode::Cholesky>
      solver(op, Bop, nev, ncv);
  solver.init();
  solver.compute(Spectra::SortRule::LargestAlge, 2000, 1e-12);
  if (solver.info() != Spectra::CompInfo::Successful)
    throw std::runtime_error("buckling: the eigensolver did not converge");
  const Eigen::VectorXd mu = solver.eigenvalues();
  const Eigen::MatrixXd vec = solver.eigenvectors();
  BucklingResult r;
  std::vector<int> keep;
  for (int i = 0; i < mu.size(); ++i)
    if (mu(i) > 0.0) keep.push_back(i);
  if (keep.empty())
    throw std::runtime_error(
        "buckling: no positive load factor: the reference load (Nx, Ny, Nxy) puts the plate "
        "in tension; use compression (negative N)");
  std::sort(keep.begin(), keep.end(), [&](int a, int b) { return mu(a) > mu(b); });
  r.modes.resize(n, static_cast<Eigen::Index>(keep.size()));
  for (std::size_t i = 0; i < keep.size(); ++i) {
    r.load_factors.push_back(1.0 / mu(keep[i]));
    r.modes.col(static_cast<Eigen::Index>(i)) = vec.col(keep[i]);
  }
  return r;
}

} // namespace plyimpact
