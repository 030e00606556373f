#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "highway_targets.hpp"
#include "render/post.hpp"

namespace silva::render {
namespace {

TEST(ShadingPost, AcesFitKnownAnswersAndMonotone) {
  EXPECT_EQ(tonemap_aces(0.0f), 0.0f);
  EXPECT_EQ(tonemap_aces(-1.0f), 0.0f);
  // Narkowicz fit at 0.5, (0.5 (1.255 + 0.03)) / (0.5 (1.215 + 0.59) + 0.14), over its value at 1, 2.54 / 3.16.
  EXPECT_NEAR(tonemap_aces(0.5f), (0.6425 / 1.0425) / (2.54 / 3.16), 1e-6);
  // The sensor's full scale is white, and so is everything above it.
  EXPECT_NEAR(tonemap_aces(1.0f), 1.0f, 1e-6f);
  EXPECT_EQ(tonemap_aces(1.01f), 1.0f);
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

namespace silva::render {
namespace {

TEST(ShadingPost, NoisySignalKnownAnswers) {
  const NoiseScale sensor{10000.0f, 1e-4f, 9.0f};  // full well 10 000 e-, read noise 3 e-
  // 0.25 of full scale: 2 500 e-, sigma sqrt(2 509) e- = 0.0050090 of full scale.
  EXPECT_NEAR(noisy_signal(0.25f, 1.0f, sensor), 0.25 + 0.0050090, 1e-6);
  EXPECT_NEAR(noisy_signal(0.25f, -2.0f, sensor), 0.25 - 2 * 0.0050090, 1e-6);
  EXPECT_NEAR(noisy_signal(0.0f, 1.0f, sensor), 3e-4, 1e-8);      // read noise only
  EXPECT_NEAR(noisy_signal(-0.5f, 1.0f, sensor), -0.5 + 3e-4, 1e-7);
  EXPECT_NEAR(noisy_signal(4.0f, 1.0f, sensor), 4.0 + 0.0100045, 1e-6);  // a full well above full scale
  EXPECT_EQ(noisy_signal(0.3f, 0.0f, sensor), 0.3f);
}

TEST(ShadingPost, RowEncoderGivesTheScalarBytesOnEveryHighwayTarget) {
  std::vector<float> radiance, normals, scales;
  for (int i = 0; i < 3 * 53; ++i) {  // 53 pixels: full vectors plus a tail on every target
    radiance.push_back(i % 7 == 0 ? -0.5f : float(i * i % 997) * 0.004f);
    normals.push_back(float(i % 11 - 5) * 0.6f);
    scales.push_back(1.7f * (1.0f - float(i % 13) * 0.03f));
  }
  const float exposure = 1.7f;
  const NoiseScale sensor{1250.0f, 1.0f / 1250.0f, 25.0f};
  std::vector<uint8_t> plain, noisy, vignetted;
  for (size_t k = 0; k < radiance.size(); ++k) {
    plain.push_back(linear_to_srgb8(tonemap_aces(radiance[k] * exposure)));
    noisy.push_back(linear_to_srgb8(tonemap_aces(noisy_signal(radiance[k] * exposure, normals[k], sensor))));
    vignetted.push_back(linear_to_srgb8(tonemap_aces(noisy_signal(radiance[k] * scales[k], normals[k], sensor))));
  }
  EXPECT_NE(plain, noisy);
  EXPECT_NE(noisy, vignetted);
  const std::vector<int64_t> targets = test::highway_targets();
  ASSERT_GE(targets.size(), 2u);
  for (int64_t target : targets) {
    const test::PinnedTarget pinned(target);
    ASSERT_EQ(encode_simd_target(), target);
    SCOPED_TRACE(hwy::TargetName(target));
    std::vector<uint8_t> out(radiance.size());
    encode_srgb8_row(radiance.data(), 53, {exposure, nullptr, nullptr, sensor}, out.data());
    EXPECT_EQ(out, plain);
    encode_srgb8_row(radiance.data(), 53, {exposure, nullptr, normals.data(), sensor}, out.data());
    EXPECT_EQ(out, noisy);
    encode_srgb8_row(radiance.data(), 53, {exposure, scales.data(), normals.data(), sensor}, out.data());
    EXPECT_EQ(out, vignetted);
  }
}

}  // namespace
}  // namespace silva::render
