// Contact law (SPEC §4): Hertz loading, Tan–Sun unloading with permanent indentation, Yang–Sun
// reloading, reversibility, no tension; and the scalar contact-force solve.
#include "plyimpact/analysis/contact/hertz_contact.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace plyimpact::hertz_contact_tests {
namespace {

ContactLawParameters tan_sun() {
  ContactLawParameters p;
  p.q = 2.5;
  p.beta = 0.094;
  p.alpha_cr = 1.7e-4;
  return p;
}

TEST(HertzContact, LoadingFollowsTheHertzLaw) {
  const HertzContact law(0.6e9, tan_sun());
  EXPECT_DOUBLE_EQ(law.force(1e-4), 0.6e9 * std::pow(1e-4, 1.5));
  EXPECT_EQ(law.force(-1e-5), 0.0); // no tension
  EXPECT_NEAR(law.stiffness(1e-4), 1.5 * 0.6e9 * std::sqrt(1e-4), 1e-6);
}

TEST(HertzContact, UnloadingLeavesThePermanentIndentationOfTanAndSun) {
  HertzContact law(0.6e9, tan_sun());
  const double am = 5e-4;
  law.commit(am);
  const double a0 = 0.094 * (am - 1.7e-4); // α0 = β (αm − αcr)
  EXPECT_DOUBLE_EQ(law.permanent_indentation(), a0);
  const double Fm = 0.6e9 * std::pow(am, 1.5);
  const double alpha = 3e-4;
  EXPECT_NEAR(law.force(alpha), Fm * std::pow((alpha - a0) / (am - a0), 2.5), 1e-9 * Fm);
  EXPECT_EQ(law.force(a0), 0.0);
  EXPECT_NEAR(law.force(am), Fm, 1e-9 * Fm); // continuous at the turning point
}

/// ∫ law.force dα from a to b by Simpson's rule on 2000 intervals (the law's state held fixed).
double simpson(const HertzContact& law, double a, double b) {
  constexpr int n = 2000;
  const double h = (b - a) / n;
  double sum = law.force(a) + law.force(b);
  for (int i = 1; i < n; ++i)
    sum += (i % 2 == 1 ? 4.0 : 2.0) * law.force(a + i * h);
  return sum * h / 3.0;
}

TEST(HertzContact, WorkIsTheExactIntegralOfTheForceOnEveryBranch) {
  // The energy balance of a run (impact_loop.cpp) counts the contact's share with work(): loading
  // 0.4 k α^2.5, and on the Tan–Sun unloading curve Fm (αm − α0)/(q + 1) ((α − α0)/(αm − α0))^(q+1).
  HertzContact law(0.6e9, tan_sun());
  EXPECT_NEAR(law.work(0.0, 5e-4), 0.4 * 0.6e9 * std::pow(5e-4, 2.5), 1e-12);
  EXPECT_NEAR(law.work(-1e-5, 2e-4), simpson(law, -1e-5, 2e-4), 1e-9 * law.work(0.0, 2e-4));
  law.commit(5e-4);
  const double a0 = 0.094 * (5e-4 - 1.7e-4), Fm = 0.6e9 * std::pow(5e-4, 1.5);
  EXPECT_NEAR(law.work(a0, 5e-4), Fm * (5e-4 - a0) / 3.5, 1e-12); // whole unloading curve, q = 2.5
  EXPECT_NEAR(law.work(5e-4, 3e-4), simpson(law, 5e-4, 3e-4), 1e-9 * Fm * 5e-4); // unloading part-way
  EXPECT_NEAR(law.work(3e-4, 6e-4), simpson(law, 3e-4, 6e-4), 1e-9 * Fm * 5e-4); // back up past αm
  EXPECT_EQ(law.work(-1e-4, a0), 0.0);                                           // no force below α0
}

TEST(HertzContact, NoPermanentIndentationBelowTheCriticalIndentation) {
  HertzContact law(0.6e9, tan_sun());
  law.commit(1e-4); // below αcr = 1.7e-4
  EXPECT_EQ(law.permanent_indentation(), 0.0);
}

TEST(HertzContact, PartialUnloadIsReversibleAlongTheUnloadingCurve) {
  HertzContact law(0.6e9, tan_sun());
  law.commit(5e-4);
  law.commit(3e-4);                 // partial unload, still in contact (α > α0)
  const double f = law.force(4e-4); // reload before reaching α0: same unloading curve
  law.commit(4e-4);
  EXPECT_FALSE(law.reloading());
  EXPECT_DOUBLE_EQ(law.force(4e-4), f);
  law.commit(6e-4); // beyond αm: loading law, new αm
  EXPECT_DOUBLE_EQ(law.force(6e-4), 0.6e9 * std::pow(6e-4, 1.5));
  EXPECT_DOUBLE_EQ(law.max_indentation(), 6e-4);
}

TEST(HertzContact, ReloadingAfterSeparationFollowsYangAndSun) {
  HertzContact law(0.6e9, tan_sun());
  const double am = 5e-4;
  law.commit(am);
  const double a0 = law.permanent_indentation();
  law.commit(a0 - 1e-6); // full unload: separation
  EXPECT_TRUE(law.reloading());
  const double Fm = 0.6e9 * std::pow(am, 1.5);
  EXPECT_NEAR(law.force(4e-4), Fm * std::pow((4e-4 - a0) / (am - a0), 1.5), 1e-9 * Fm);
  EXPECT_NEAR(law.force(am), Fm, 1e-9 * Fm);
}

TEST(HertzContact, ElasticUnloadingRetracesTheLoadingCurve) {
  ContactLawParameters p = tan_sun();
  p.unloading = UnloadingLaw::elastic;
  HertzContact law(1e9, p);
  law.commit(5e-4);
  EXPECT_EQ(law.permanent_indentation(), 0.0);
  EXPECT_NEAR(law.force(2e-4), 1e9 * std::pow(2e-4, 1.5), 1e-6);
}

TEST(HertzContact, ContactForceSolvesTheScalarEquationToMachinePrecision) {
  for (const double compliance : {1e-9, 1e-7, 1e-5}) {
    HertzContact law(0.6e9, tan_sun());
    law.commit(5e-4); // on the unloading branch: exercises the kink at αm too
    for (const double alpha_free : {1e-5, 3e-4, 5e-4, 7e-4, 2e-3}) {
      const ContactSolution s = solve_contact_force(law, alpha_free, compliance);
      // Error in F estimated by one more Newton step: residual / g'(F), with g' = 1 + C dF/dα.
      const double alpha = alpha_free - compliance * s.force;
      const double residual = s.force - law.force(alpha);
      const double error = residual / (1.0 + compliance * law.stiffness(alpha));
      EXPECT_LE(std::abs(error), 1e-12 * std::max(s.force, 1.0)) << alpha_free << " " << compliance;
      EXPECT_NEAR(s.alpha, alpha_free - compliance * s.force, 1e-18);
      EXPECT_GE(s.force, 0.0);
    }
  }
  const HertzContact fresh(0.6e9, tan_sun());
  EXPECT_EQ(solve_contact_force(fresh, -1e-4, 1e-7).force, 0.0); // separated
}

} // namespace
} // namespace plyimpact::hertz_contact_tests
