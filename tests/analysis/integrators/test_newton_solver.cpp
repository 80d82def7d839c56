// Newton's method written once (analysis/integrators/newton_solver.hpp), on problems whose roots and
// convergence are known by hand: x³ = 2 (root 2^(1/3)), full Newton converging quadratically and a frozen
// matrix converging linearly at the rate |1 − f'(x*)/f'(x₀)|; the modified-Newton refresh where that rate is
// above refresh_ratio; a branch change, a deferred refresh, a correction that is not finite, and the
// limit on corrections.
#include "plyimpact/analysis/integrators/newton_solver.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>
#include <utility>
#include <vector>

namespace plyimpact::newton_solver_tests {
namespace {

/// f(x) = x³ − 2 = 0. The matrix is f'(x) at the last refactor (full: before every correction).
class CubeRoot final : public NewtonProblem {
public:
  CubeRoot(double x0, bool full) : x_(x0), slope_(3.0 * x0 * x0), full_(full) {}

  Trial trial(int corrections) override {
    events_ += 't';
    residual_ = x_ * x_ * x_ - 2.0;
    if (corrections > 0 && std::abs(residual_) < 1e-13) return Trial::converged;
    return std::exchange(branch_changed_, false) ? Trial::branch_changed : Trial::iterate;
  }
  void refactor() override {
    events_ += 'r';
    slope_ = 3.0 * x_ * x_;
    ++refactors_;
  }
  double correct() override {
    if (full_) refactor();
    events_ += 'c';
    const double dx = -residual_ / slope_;
    x_ += dx;
    corrections_.push_back(std::abs(dx));
    return std::abs(dx);
  }

  double x_, slope_, residual_ = 0.0;
  bool full_;
  int refactors_ = 0;
  bool branch_changed_ = false;
  std::vector<double> corrections_;
  std::string events_; ///< t: trial, r: refactor, c: correction
};

const double root = std::cbrt(2.0);
constexpr NewtonControl frozen{100, INFINITY, std::numeric_limits<int>::max()};

TEST(NewtonSolver, FullNewtonConvergesQuadratically) {
  CubeRoot p(2.0, true);
  const NewtonOutcome o = solve_newton(p, frozen);
  ASSERT_TRUE(o.converged) << o.why;
  EXPECT_NEAR(p.x_, root, 1e-14);
  // e_{k+1} ≈ (f''/2f') e_k² = e_k² / x*: the last corrections are the errors of the iterates before.
  const std::size_t n = p.corrections_.size();
  ASSERT_GE(n, 4U);
  const double e1 = p.corrections_[n - 3], e2 = p.corrections_[n - 2];
  EXPECT_NEAR(e2 / (e1 * e1), 1.0 / root, 0.05 / root);
  EXPECT_LE(o.corrections, 7);
}

TEST(NewtonSolver, AFrozenMatrixConvergesLinearlyAtTheSlopesRatio) {
  CubeRoot p(1.5, false); // f'(x₀) = 6.75, f'(x*) = 3·2^(2/3): rate 1 − f'(x*)/f'(x₀) ≈ 0.2946
  const NewtonOutcome o = solve_newton(p, frozen);
  ASSERT_TRUE(o.converged) << o.why;
  EXPECT_NEAR(p.x_, root, 1e-13);
  EXPECT_EQ(p.refactors_, 0);
  const double rate = 1.0 - 3.0 * root * root / 6.75;
  const std::size_t n = p.corrections_.size();
  EXPECT_NEAR(p.corrections_[n - 3] / p.corrections_[n - 4], rate, 1e-3);
}

TEST(NewtonSolver, RefreshesTheMatrixWhereTheCorrectionsContractLessThanTheRatio) {
  CubeRoot slow(1.5, false); // contraction ≈ 0.29 > 0.25: refreshed after the second correction
  const NewtonOutcome o = solve_newton(slow, NewtonControl{100, 0.25, std::numeric_limits<int>::max()});
  ASSERT_TRUE(o.converged);
  EXPECT_GE(slow.refactors_, 1);
  CubeRoot fast(1.5, false); // a looser ratio keeps the first matrix
  ASSERT_TRUE(solve_newton(fast, NewtonControl{100, 0.5, std::numeric_limits<int>::max()}).converged);
  EXPECT_EQ(fast.refactors_, 0);
  EXPECT_LT(o.corrections, static_cast<int>(fast.corrections_.size()));
}

TEST(NewtonSolver, RefreshesEveryNCorrectionsAndADeferredRefreshFollowsTheNextTrial) {
  const NewtonControl every_two{100, INFINITY, std::numeric_limits<int>::max(), 2};
  CubeRoot now(1.5, false); // after corrections 2, 4, …: at once
  ASSERT_TRUE(solve_newton(now, every_two).converged);
  EXPECT_EQ(now.events_.substr(0, 12), "tctcrtctcrtc");
  CubeRoot deferred(1.5, false); // … after the trial at the next iterate
  NewtonControl every_two_deferred = every_two;
  every_two_deferred.defer_refresh = true;
  ASSERT_TRUE(solve_newton(deferred, every_two_deferred).converged);
  EXPECT_EQ(deferred.events_.substr(0, 12), "tctctrctctrc");
  EXPECT_NEAR(deferred.x_, root, 1e-13);
}

TEST(NewtonSolver, ABranchChangeRefactorsBeforeTheNextCorrection) {
  CubeRoot p(1.5, false);
  p.branch_changed_ = true; // said by the first trial
  const NewtonOutcome o = solve_newton(p, frozen);
  ASSERT_TRUE(o.converged);
  EXPECT_EQ(p.refactors_, 1);
  EXPECT_EQ(p.events_.substr(0, 3), "trc");
}

TEST(NewtonSolver, GivesUpAfterTheLimitOrOnANonFiniteCorrection) {
  CubeRoot p(1.5, false);
  const NewtonOutcome o = solve_newton(p, NewtonControl{3, INFINITY, std::numeric_limits<int>::max()});
  EXPECT_FALSE(o.converged);
  EXPECT_EQ(o.corrections, 3);
  EXPECT_FALSE(o.failed);
  EXPECT_EQ(o.why, "the Newton iterations did not converge after 3 solves");

  CubeRoot flat(0.0, false); // f'(0) = 0: the correction divides by zero
  const NewtonOutcome f = solve_newton(flat, frozen);
  EXPECT_FALSE(f.converged);
  EXPECT_EQ(f.corrections, 0);
  EXPECT_TRUE(f.failed);
  EXPECT_EQ(f.why, "non-finite state");
}

} // namespace
} // namespace plyimpact::newton_solver_tests
