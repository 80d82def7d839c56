#pragma once
// Assembly equation by equation: f = Σₑ Lₑᵀ fₑ with each global equation summed by the thread that owns it,
// from the element entries that add into it, in element order. A one-thread loop of scatter_add over the
// elements adds the same terms to each equation in the same order, starting from zero, so the bits are the
// same for any number of threads (element_loop.hpp); the elements' own vectors are computed on threads
// beforehand, each into its slot.
#include "plyimpact/fem/dof_map.hpp"

#include <Eigen/Core>
#include <functional>
#include <vector>

namespace plyimpact {

class EquationGather {
public:
  /// For elements 0 … count − 1 whose 45 entries go to the equations `equations_of(e)` (−1: restrained) of
  /// a vector of `size` equations.
  EquationGather(int size, int count, const std::function<const ElementEquations&(int)>& equations_of);

  /// f = Σₑ Lₑᵀ element_vectors[e], f resized to the equations: the numbers of f.setZero() followed by
  /// scatter_add(f, equations_of(e), element_vectors[e]) for e = 0, 1, …, on the calling thread's threads.
  void assemble(const std::vector<ElementVector>& element_vectors, Eigen::VectorXd& f) const;

private:
  std::vector<int> first_; ///< equation i's entries: entry_[first_[i]] … entry_[first_[i + 1] − 1]
  std::vector<int> entry_; ///< e · 45 + (the element's DOF), in element order within each equation
};

} // namespace plyimpact
