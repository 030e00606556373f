#include <gtest/gtest.h>

#include <cmath>

#include "core/det_math.hpp"

namespace silva {
namespace {

TEST(DetMath, RoundHalfAwayEqualsLlround) {
  for (double x : {0.5, -0.5, 1.5, -1.5, 2.5, -2.5, 0.49999999999999994, -0.49999999999999994, 4503599627370495.5,
                   -4503599627370495.5, 0.0, -0.0, 1e-300, 123456.5, -7.4999999})
    EXPECT_EQ(round_half_away(x), std::llround(x)) << x;
  for (double x = -3000.0; x <= 3000.0; x += 0.0625) EXPECT_EQ(round_half_away(x), std::llround(x)) << x;
  for (double x = -1e9; x <= 1e9; x += 1234.56789) EXPECT_EQ(round_half_away(x), std::llround(x)) << x;
}

TEST(DetMath, ExpMatchesLibmClosely) {
  for (double x = -60.0; x <= 60.0; x += 0.37) EXPECT_NEAR(det_exp(x) / std::exp(x), 1.0, 4e-15) << x;
  EXPECT_EQ(det_exp(0.0), 1.0);
  EXPECT_EQ(det_exp(-800.0), 0.0);
}

TEST(DetMath, FloatExpMatchesLibmClosely) {
  for (float x = -80.0f; x <= 80.0f; x += 0.173f)
    EXPECT_NEAR(double(det_expf(x)) / std::exp(double(x)), 1.0, 4e-7) << x;
  EXPECT_EQ(det_expf(0.0f), 1.0f);
  EXPECT_EQ(det_expf(-100.0f), 0.0f);
  EXPECT_TRUE(std::isfinite(det_expf(500.0f)));
}

TEST(DetMath, LogMatchesLibmClosely) {
  for (double x = 1e-12; x < 1e6; x *= 1.7) EXPECT_NEAR(det_log(x), std::log(x), 4e-15 * std::max(1.0, std::abs(std::log(x)))) << x;
  EXPECT_EQ(det_log(1.0), 0.0);
  EXPECT_NEAR(det_exp(det_log(0.3)), 0.3, 1e-15);
}

}  // namespace
}  // namespace silva
