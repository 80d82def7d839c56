#include "plyimpact/fem/equation_gather.hpp"

#include "plyimpact/fem/element_loop.hpp"

#include <stdexcept>

namespace plyimpact {

EquationGather::EquationGather(int size, int count,
                               const std::function<const ElementEquations&(int)>& equations_of)
    : first_(static_cast<std::size_t>(size) + 1, 0) {
  for (int e = 0; e < count; ++e) // count the entries of each equation …
    for (const int eq : equations_of(e)) {
      if (eq >= size) throw std::logic_error("equation gather: an element's equation beyond the vector");
      if (eq >= 0) ++first_[static_cast<std::size_t>(eq) + 1];
    }
  for (std::size_t i = 1; i < first_.size(); ++i)
    first_[i] += first_[i - 1];
  entry_.resize(static_cast<std::size_t>(first_.back()));
  std::vector<int> next(first_.begin(), first_.end() - 1);
  for (int e = 0; e < count; ++e) // … then list them, element by element: each equation's in element order
    for (int i = 0; i < q9_dofs; ++i)
      if (const int eq = equations_of(e)[static_cast<std::size_t>(i)]; eq >= 0)
        entry_[static_cast<std::size_t>(next[static_cast<std::size_t>(eq)]++)] = e * q9_dofs + i;
}

namespace {

/// Vectors shorter than this are gathered in one call: a parallel region costs a few microseconds, the
/// gather of 4 096 equations (about two elements' entries each on a mesh of nine-node elements) about as
/// much.
constexpr Eigen::Index gather_threshold = 4096;

} // namespace

void EquationGather::assemble(const std::vector<ElementVector>& element_vectors, Eigen::VectorXd& f) const {
  const auto size = static_cast<Eigen::Index>(first_.size()) - 1;
  f.resize(size);
  const auto sum_equations = [&](Eigen::Index first, Eigen::Index last) {
    for (Eigen::Index eq = first; eq < last; ++eq) {
      double sum = 0.0;
      const auto end = static_cast<std::size_t>(first_[static_cast<std::size_t>(eq) + 1]);
      for (auto k = static_cast<std::size_t>(first_[static_cast<std::size_t>(eq)]); k < end; ++k) {
        const int entry = entry_[k];
        sum += element_vectors[static_cast<std::size_t>(entry / q9_dofs)](entry % q9_dofs);
      }
      f(eq) = sum;
    }
  };
  // Each equation is written from its own entries alone: an elementwise update, in blocks on threads.
  elementwise_on_threads(size, sum_equations, gather_threshold);
}

} // namespace plyimpact
