// Assembly equation by equation (fem/equation_gather.hpp): f = Σₑ Lₑᵀ fₑ gathered on threads is, to the bit,
// the vector that a one-thread loop of scatter_add over the elements in element order gives, for any number
// of threads, with restrained entries left out and equations that no element touches zero.
#include "plyimpact/fem/equation_gather.hpp"

#include "plyimpact/fem/element_loop.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace plyimpact::equation_gather_tests {
namespace {

/// Elements whose 45 entries go to overlapping windows of equations (as neighbours share nodes), every
/// seventh entry restrained (−1), and entries of mixed magnitude, so that another order of summation would
/// change the last bits; `size` has equations that no element touches at its end.
struct Elements {
  int size = 0;
  std::vector<ElementEquations> equations;
  std::vector<ElementVector> vectors;
};

Elements overlapping_elements(int count) {
  Elements m;
  m.size = 20 * count + 100;
  for (int e = 0; e < count; ++e) {
    ElementEquations eq{};
    ElementVector fe;
    for (int i = 0; i < q9_dofs; ++i) {
      eq[static_cast<std::size_t>(i)] = (e + i) % 7 == 0 ? -1 : 20 * e + (i * 13) % 45;
      fe(i) = std::sin(1.0 + 0.37 * e + 0.11 * i) * std::pow(10.0, (e + i) % 9 - 4);
    }
    m.equations.push_back(eq);
    m.vectors.push_back(fe);
  }
  return m;
}

/// The one-thread assembly: setZero, then scatter_add element after element.
Eigen::VectorXd scattered(const Elements& m) {
  Eigen::VectorXd f = Eigen::VectorXd::Zero(m.size);
  for (std::size_t e = 0; e < m.vectors.size(); ++e)
    scatter_add(f, m.equations[e], m.vectors[e]);
  return f;
}

EquationGather gather_of(const Elements& m) {
  return {m.size, static_cast<int>(m.equations.size()),
          [&m](int e) -> const ElementEquations& { return m.equations[static_cast<std::size_t>(e)]; }};
}

TEST(EquationGather, IsTheOneThreadScatterToTheBitOnAnyNumberOfThreads) {
  const Elements m = overlapping_elements(400); // 8 100 equations: above the size gathered in one call
  const Eigen::VectorXd serial = scattered(m);
  const EquationGather gather = gather_of(m);
  for (const int threads : {1, 2, 3, 4}) {
    const ElementThreads setting(threads);
    Eigen::VectorXd f = Eigen::VectorXd::Constant(3, 1.0); // resized and overwritten
    gather.assemble(m.vectors, f);
    ASSERT_EQ(f.size(), serial.size());
    int different = 0;
    for (Eigen::Index i = 0; i < f.size(); ++i)
      different += f(i) != serial(i) || std::signbit(f(i)) != std::signbit(serial(i)) ? 1 : 0;
    EXPECT_EQ(different, 0) << threads << " threads";
    EXPECT_EQ(f.tail(75).cwiseAbs().maxCoeff(), 0.0); // the equations past 20·count + 24: untouched
  }
}

TEST(EquationGather, SmallVectorsAreGatheredInOneCallWithTheSameNumbers) {
  const Elements m = overlapping_elements(10); // 300 equations
  const Eigen::VectorXd serial = scattered(m);
  const EquationGather gather = gather_of(m);
  const ElementThreads two(2);
  Eigen::VectorXd f;
  gather.assemble(m.vectors, f);
  EXPECT_TRUE(f == serial);
}

TEST(EquationGather, AnEquationBeyondTheVectorIsAProgrammingError) {
  const ElementEquations eq{};
  ElementEquations beyond = eq;
  beyond[3] = 10;
  EXPECT_THROW(EquationGather(10, 1, [&](int) -> const ElementEquations& { return beyond; }),
               std::logic_error);
}

} // namespace
} // namespace plyimpact::equation_gather_tests
