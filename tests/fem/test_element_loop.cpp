// The element loops on threads (fem/element_loop.hpp): every index once, the first error rethrown, the
// caller's thread setting restored, and K u by blocks of rows equal to Eigen's one-thread product to the
// bit for any number of threads.
#include "plyimpact/fem/element_loop.hpp"

#include <gtest/gtest.h>

#include <Eigen/SparseCore>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

namespace plyimpact::element_loop_tests {
namespace {

TEST(ElementLoop, EveryElementOnceOnTwoThreads) {
  // The loop runs in a team of two threads. Which thread takes which element is the scheduler's choice:
  // on a loaded machine the first thread may take all 1000 before the second starts, so the test asks for
  // the team, not for work on thread 1 (that version failed once under a sanitizer build beside other jobs).
  const ElementThreads two(2);
  EXPECT_EQ(element_threads(), 2);
  std::vector<int> visits(1000, 0);
  std::atomic<int> team{0};
  for_each_element(1000, [&](int e) {
    ++visits[static_cast<std::size_t>(e)];
    team = omp_get_num_threads();
  });
  for (const int v : visits)
    EXPECT_EQ(v, 1);
  EXPECT_EQ(team.load(), 2);
}

TEST(ElementLoop, TheErrorOfTheFirstFailingElementIsRethrown) {
  // Elements 700 and 300 fail; a loop on one thread would have met 300 first, whichever thread runs it.
  const ElementThreads two(2);
  try {
    for_each_element(1000, [](int e) {
      if (e == 700 || e == 300) throw std::runtime_error("element " + std::to_string(e));
    });
    FAIL() << "no exception";
  } catch (const std::runtime_error& e) {
    EXPECT_STREQ(e.what(), "element 300");
  }
}

TEST(ElementLoop, ThreadsAreRestoredAfterTheRun) {
  const int before = element_threads();
  {
    const ElementThreads three(3);
    EXPECT_EQ(element_threads(), std::min(3, hardware_threads())); // never more than the machine has
  }
  {
    const ElementThreads absurd(100000); // OMP_NUM_THREADS=100000 crashed libgomp (issue 77)
    EXPECT_EQ(element_threads(), hardware_threads());
  }
  EXPECT_EQ(element_threads(), before);
  const ElementThreads unchanged(0); // 0: as they are
  EXPECT_EQ(element_threads(), before);
}

TEST(ElementLoop, RowBlockProductIsTheOneThreadProductToTheBit) {
  // A sparse matrix with rows of many terms of mixed magnitude, where a different order of summation
  // would change the last bits.
  const int n = 5000;
  std::vector<Eigen::Triplet<double>> t;
  for (int i = 0; i < n; ++i)
    for (int k = -40; k <= 40; k += 3) {
      const int j = (i + k + n) % n;
      t.emplace_back(i, j, std::sin(1.0 + i * 0.37 + j * 0.11) * std::pow(10.0, (i + j) % 7 - 3));
    }
  Eigen::SparseMatrix<double, Eigen::RowMajor> K(n, n);
  K.setFromTriplets(t.begin(), t.end());
  Eigen::VectorXd u(n);
  for (int i = 0; i < n; ++i)
    u(i) = std::cos(0.3 * i) * std::pow(10.0, i % 5 - 2);
  const Eigen::VectorXd serial = K * u;
  for (const int threads : {1, 2, 4}) {
    const ElementThreads setting(threads);
    Eigen::VectorXd out;
    parallel_rows_product(K, u, out);
    ASSERT_EQ(out.size(), n);
    for (int i = 0; i < n; ++i)
      ASSERT_EQ(out(i), serial(i)) << "row " << i << " with " << threads << " threads";
  }
}

} // namespace
} // namespace plyimpact::element_loop_tests
