#pragma once
// A subset of the model's equations that a solve works on (the impact loop leaves out the in-plane
// DOFs when they are exactly decoupled from bending): the kept equations in order, and the moves
// between model numbering and subset numbering.
#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <vector>

namespace plyimpact {

class EquationSubset {
public:
  /// All `size` equations.
  explicit EquationSubset(int size);
  /// The equations `keep` (model numbering, any order) of a model with `size` equations.
  EquationSubset(std::vector<int> keep, int size);

  [[nodiscard]] int size() const { return static_cast<int>(keep_.size()); }
  [[nodiscard]] int model_size() const { return static_cast<int>(new_index_.size()); }
  [[nodiscard]] bool all() const { return size() == model_size(); }
  /// The model equation of subset equation i.
  [[nodiscard]] int model_equation(int i) const { return keep_.at(static_cast<std::size_t>(i)); }
  /// Model vector → subset vector.
  [[nodiscard]] Eigen::VectorXd restrict(const Eigen::VectorXd& v) const;
  /// Subset vector → model vector (zeros elsewhere), into `out` (sized by the call).
  void expand(const Eigen::VectorXd& r, Eigen::VectorXd& out) const;
  /// Rows and columns of a square model matrix.
  [[nodiscard]] Eigen::SparseMatrix<double> restrict(const Eigen::SparseMatrix<double>& A) const;

private:
  std::vector<int> keep_;      ///< model equations kept, ascending
  std::vector<int> new_index_; ///< model equation → subset equation (−1 if left out)
};

class DiscretePlate;

/// The bending equations (w, θx, θy) of `model` where its in-plane DOFs are exactly decoupled from them in
/// K and in M (B = 0 and I1 = 0: no coupling entry above 1e-13 of the largest), else all equations. A
/// transverse load then leaves the in-plane DOFs at zero, and the impact's time loop and its fundamental
/// period leave them out (about 2/5 of the equations).
[[nodiscard]] EquationSubset bending_equations_if_decoupled(const DiscretePlate& model,
                                                            const Eigen::SparseMatrix<double>& K,
                                                            const Eigen::SparseMatrix<double>& M);

} // namespace plyimpact
