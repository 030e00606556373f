#include "core/noise.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace silva {

TEST(Noise, ZeroAtLatticeOrigin) {
  // At a lattice vertex the first corner has zero offset and the others are out of reach.
  EXPECT_EQ(simplex2(0.0, 0.0), 0.0);
  EXPECT_EQ(simplex2(3.0, 5.0), 0.0);
}

TEST(Noise, RangeAndNonTrivial) {
  double lo = 0, hi = 0, sum2 = 0;
  const int n = 200;
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) {
      const double v = simplex2(x * 0.137 - 7.3, y * 0.119 + 2.1);
      ASSERT_LE(std::abs(v), 1.0);
      lo = std::min(lo, v);
      hi = std::max(hi, v);
      sum2 += v * v;
    }
  EXPECT_LT(lo, -0.6);
  EXPECT_GT(hi, 0.6);
  EXPECT_GT(sum2 / (n * n), 0.01);
}

TEST(Noise, ContinuousAndDeterministic) {
  for (int k = 0; k < 1000; ++k) {
    const double x = k * 0.0731, y = k * 0.0413 - 3.0;
    EXPECT_EQ(simplex2(x, y), simplex2(x, y));
    // The gradient is bounded, so a tiny step makes a tiny change.
    EXPECT_LT(std::abs(simplex2(x + 1e-4, y) - simplex2(x, y)), 1e-2);
  }
}

TEST(Noise, FbmOneOctaveIsScaledSimplex) {
  FbmParams p;
  p.octaves = 1;
  p.frequency = 0.25;
  p.offset_x = 10.5;
  p.offset_y = -3.25;
  for (int k = 0; k < 100; ++k) {
    const double x = k * 1.7, y = k * -0.9;
    EXPECT_EQ(fbm2(p, x, y), simplex2(x * 0.25 + 10.5, y * 0.25 - 3.25));
  }
}

TEST(Noise, FbmNormalisedAndSeededByOffset) {
  FbmParams a, b;
  b.offset_x = 123.0;
  int differ = 0;
  for (int k = 0; k < 500; ++k) {
    const double x = k * 3.1, y = k * 1.3;
    ASSERT_LE(std::abs(fbm2(a, x, y)), 1.0);
    differ += fbm2(a, x, y) != fbm2(b, x, y);
  }
  EXPECT_GT(differ, 490);
}

}  // namespace silva
