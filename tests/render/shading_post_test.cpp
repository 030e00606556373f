#include <gtest/gtest.h>

#include <cmath>

#include "render/post.hpp"

namespace silva::render {
namespace {

TEST(ShadingPost, AcesFitKnownAnswersAndMonotone) {
  EXPECT_EQ(tonemap_aces(0.0f), 0.0f);
  EXPECT_EQ(tonemap_aces(-1.0f), 0.0f);
  // Narkowicz fit at 1: (2.51 + 0.03) / (2.43 + 0.59 + 0.14).
  EXPECT_NEAR(tonemap_aces(1.0f), 2.54f / 3.16f, 1e-6f);
  EXPECT_EQ(tonemap_aces(1000.0f), 1.0f);
  float prev = 0;
  for (int i = 1; i < 400; ++i) {
    const float v = tonemap_aces(float(i) * 0.05f);
    EXPECT_GE(v, prev);
    prev = v;
  }
}

TEST(ShadingPost, SrgbEncodingKnownAnswers) {
  EXPECT_EQ(linear_to_srgb8(0.0f), 0);
  EXPECT_EQ(linear_to_srgb8(-0.5f), 0);
  EXPECT_EQ(linear_to_srgb8(1.0f), 255);
  EXPECT_EQ(linear_to_srgb8(2.0f), 255);
  EXPECT_EQ(linear_to_srgb8(0.5f), 188);   // 1.055 * 0.5^(1/2.4) - 0.055 = 0.7354 -> 187.5 -> 188
  EXPECT_EQ(linear_to_srgb8(0.18f), 118);  // 0.4614 -> 117.7
  EXPECT_EQ(linear_to_srgb8(0.002f), 7);   // linear segment: 12.92 * 0.002 * 255 = 6.6
  uint8_t prev = 0;
  for (int i = 0; i <= 1000; ++i) {
    const uint8_t v = linear_to_srgb8(float(i) / 1000.0f);
    EXPECT_GE(v, prev);
    prev = v;
  }
}

TEST(ShadingPost, ExposureIsPowerOfTwo) {
  EXPECT_EQ(exposure_scale(0.0f), 1.0f);
  EXPECT_EQ(exposure_scale(1.0f), 2.0f);
  EXPECT_EQ(exposure_scale(-2.0f), 0.25f);
  EXPECT_NEAR(exposure_scale(0.5f), std::sqrt(2.0f), 1e-6f);
}

}  // namespace
}  // namespace silva::render
