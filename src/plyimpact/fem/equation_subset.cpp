#include "plyimpact/fem/equation_subset.hpp"

#include "plyimpact/fem/discrete_plate.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace plyimpact {

EquationSubset::EquationSubset(int size) : keep_(static_cast<std::size_t>(size)), new_index_(keep_.size()) {
  std::iota(keep_.begin(), keep_.end(), 0);
  std::iota(new_index_.begin(), new_index_.end(), 0);
}

EquationSubset::EquationSubset(std::vector<int> keep, int size)
    : keep_(std::move(keep)), new_index_(static_cast<std::size_t>(size), -1) {
  std::sort(keep_.begin(), keep_.end());
  for (std::size_t i = 0; i < keep_.size(); ++i)
    new_index_[static_cast<std::size_t>(keep_[i])] = static_cast<int>(i);
}

Eigen::VectorXd EquationSubset::restrict(const Eigen::VectorXd& v) const {
  Eigen::VectorXd r(static_cast<Eigen::Index>(keep_.size()));
  for (std::size_t i = 0; i < keep_.size(); ++i)
    r(static_cast<Eigen::Index>(i)) = v(keep_[i]);
  return r;
}

void EquationSubset::expand(const Eigen::VectorXd& r, Eigen::VectorXd& out) const {
  out.setZero(model_size());
  for (std::size_t i = 0; i < keep_.size(); ++i)
    out(keep_[i]) = r(static_cast<Eigen::Index>(i));
}

Eigen::SparseMatrix<double> EquationSubset::restrict(const Eigen::SparseMatrix<double>& A) const {
  if (all()) return A;
  std::vector<Eigen::Triplet<double>> t;
  t.reserve(static_cast<std::size_t>(A.nonZeros()));
  for (const int col : keep_)
    for (Eigen::SparseMatrix<double>::InnerIterator it(A, col); it; ++it)
      if (const int r = new_index_[static_cast<std::size_t>(it.row())]; r >= 0)
        t.emplace_back(r, new_index_[static_cast<std::size_t>(col)], it.value());
  Eigen::SparseMatrix<double> R(static_cast<Eigen::Index>(keep_.size()),
                                static_cast<Eigen::Index>(keep_.size()));
  R.setFromTriplets(t.begin(), t.end());
  return R;
}

namespace {

/// Largest |A(i, j)| with i in-plane (u, v) and j bending (w, θx, θy), relative to max |A|.
double inplane_coupling(const DiscretePlate& model, const Eigen::SparseMatrix<double>& A) {
  std::vector<bool> inplane(static_cast<std::size_t>(model.size()));
  for (int n = 0; n < model.mesh().node_count(); ++n)
    for (int d = 0; d < 2; ++d)
      if (const int eq = model.dofs().equation(n, d); eq >= 0) inplane[static_cast<std::size_t>(eq)] = true;
  double coupling = 0.0, scale = 0.0;
  for (int col = 0; col < A.outerSize(); ++col)
    for (Eigen::SparseMatrix<double>::InnerIterator it(A, col); it; ++it) {
      scale = std::max(scale, std::abs(it.value()));
      if (inplane[static_cast<std::size_t>(it.row())] != inplane[static_cast<std::size_t>(col)])
        coupling = std::max(coupling, std::abs(it.value()));
    }
  return scale > 0.0 ? coupling / scale : 0.0;
}

} // namespace

EquationSubset bending_equations_if_decoupled(const DiscretePlate& model,
                                              const Eigen::SparseMatrix<double>& K,
                                              const Eigen::SparseMatrix<double>& M) {
  const bool decoupled = inplane_coupling(model, K) <= 1e-13 && inplane_coupling(model, M) <= 1e-13;
  if (!decoupled) return EquationSubset(model.size());
  std::vector<int> keep;
  for (int n = 0; n < model.mesh().node_count(); ++n)
    for (int d = 2; d < dofs_per_node; ++d)
      if (const int eq = model.dofs().equation(n, d); eq >= 0) keep.push_back(eq);
  return {std::move(keep), model.size()};
}

} // namespace plyimpact
