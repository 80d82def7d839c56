// The ply law at one point as the layered section sees it (laminate/ply_law.hpp): the law make_ply_law()
// gives, and the onset bound of PlyDamageLaw along a segment of stresses, checked against Hashin's
// index (hashin_plane_stress_index, the sign conditions applied here) sampled along the segment: the
// bound is never below it, and it is attained (the largest sampled value is within the sampling's
// resolution of it).
#include "plyimpact/laminate/ply_damage.hpp"
#include "plyimpact/laminate/ply_law.hpp"
#include "support/decks.hpp"
#include "support/hashin_index.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>

namespace plyimpact::ply_law_tests {
namespace {

TEST(PlyLaw, MakePlyLawGivesTheDamageLawOfTheMaterial) {
  const Material m = test::t300_976_with_damage_data();
  const std::unique_ptr<PlyLaw> law = make_ply_law(m, {});
  ASSERT_NE(dynamic_cast<const PlyDamageLaw*>(law.get()), nullptr);
  EXPECT_EQ(law->material().name, m.name);
  EXPECT_EQ(law->undamaged_stiffness(), PlyDamageLaw(m).undamaged_stiffness());
}

TEST(PlyLaw, HashinOnsetBoundIsTheLargestActiveIndexAlongTheSegment) {
  const Material m = test::t300_976_with_damage_data();
  const std::unique_ptr<PlyLaw> law = make_ply_law(m, {});
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> sigma(-1.5, 1.5);
  constexpr int samples = 20000;
  int sign_changes = 0;
  for (int trial = 0; trial < 200; ++trial) {
    // Stresses around the strengths: σ11 in units of Xt, σ22 of Yt (tension) to Yc, τ12 of S12.
    const auto draw = [&] {
      return Eigen::Vector3d(sigma(rng) * *m.strength.Xt, sigma(rng) * *m.strength.Yt * 3.0,
                             sigma(rng) * *m.strength.S12);
    };
    const Eigen::Vector3d s0 = draw(), s1 = draw();
    sign_changes += (s0(0) * s1(0) < 0.0 || s0(1) * s1(1) < 0.0) ? 1 : 0;
    double largest = 0.0;
    for (int i = 0; i <= samples; ++i) {
      const double f = static_cast<double>(i) / samples;
      largest = std::max(largest, test::active_hashin_index(s0 + f * (s1 - s0), m.strength));
    }
    const double bound = law->onset_bound(s0, s1);
    EXPECT_GE(bound, largest * (1.0 - 1e-12)) << s0.transpose() << " → " << s1.transpose();
    // The index changes by at most |d index/df| / samples between samples: a few 1e-4 of its size here.
    EXPECT_LE(bound, largest * (1.0 + 1e-3) + 1e-9) << s0.transpose() << " → " << s1.transpose();
  }
  EXPECT_GT(sign_changes, 50); // the segments cross the branches' boundaries often enough to check them
}

} // namespace
} // namespace plyimpact::ply_law_tests
