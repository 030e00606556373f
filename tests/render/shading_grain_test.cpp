#include <gtest/gtest.h>

#include <cmath>

#include "render/post.hpp"
#include "render/shade.hpp"
#include "shading_scene.hpp"

namespace silva::render {
namespace {

TEST(ShadingGrain, QuantileTableIsStandardNormal) {
  double sum = 0, sum_sq = 0;
  for (int i = 0; i < 65536; ++i) {
    const double q = grain_quantile(uint16_t(i));
    sum += q;
    sum_sq += q * q;
  }
  EXPECT_NEAR(sum / 65536, 0.0, 1e-6);
  EXPECT_NEAR(sum_sq / 65536, 1.0, 1e-5);
  EXPECT_NEAR(grain_quantile(32768), 0.0, 1e-3);
  EXPECT_NEAR(grain_quantile(uint16_t(65536 * 0.8413)), 1.0, 2e-3);  // Phi(1) = 0.8413
  EXPECT_LT(grain_quantile(0), -4.0f);
}

TEST(ShadingGrain, ZeroMeanWithTheConfiguredStdDev) {
  const float sigma = 0.015f;
  const uint64_t key = grain_key("random", 4);
  const int n = 200000;
  double sum = 0, sum_sq = 0;
  for (int i = 0; i < n; ++i) {
    const Vec3f g = film_grain(77, key, uint64_t(i), sigma);
    for (int c = 0; c < 3; ++c) {
      sum += g[c];
      sum_sq += double(g[c]) * g[c];
    }
  }
  const double mean = sum / (3.0 * n);
  const double sd = std::sqrt(sum_sq / (3.0 * n) - mean * mean);
  EXPECT_NEAR(mean, 0.0, 2e-4);  // 6 standard errors
  EXPECT_NEAR(sd, sigma, sigma * 0.01);
}

TEST(ShadingGrain, SameSeedAndFrameRepeatOtherFrameDiffers) {
  const uint64_t k4 = grain_key("random", 4), k5 = grain_key("random", 5);
  EXPECT_EQ(k4, grain_key("random", 4));
  EXPECT_NE(k4, k5);
  EXPECT_NE(k4, grain_key("autopilot", 4));
  int differ = 0;
  for (uint64_t i = 0; i < 1000; ++i) {
    EXPECT_EQ(film_grain(9, k4, i, 0.02f), film_grain(9, k4, i, 0.02f));
    differ += film_grain(9, k4, i, 0.02f) != film_grain(9, k5, i, 0.02f) ? 1 : 0;
  }
  EXPECT_GT(differ, 990);
}

TEST(ShadingGrain, ImagesRepeatPerFrameAndDifferAcrossFrames) {
  const Camera cam = test::test_camera(48, 32, 5);
  const GBuffer g = test::plane_gbuffer(cam, Material::Ground);
  const LightingPreset day = preset_day();
  std::vector<uint8_t> a, b, c, clean;
  shade_rgb({g, cam, day, nullptr, 5, "autopilot", 3, 0.015f}, a);
  shade_rgb({g, cam, day, nullptr, 5, "autopilot", 3, 0.015f}, b);
  shade_rgb({g, cam, day, nullptr, 5, "autopilot", 4, 0.015f}, c);
  shade_rgb({g, cam, day, nullptr, 5, "autopilot", 3, 0.0f}, clean);
  EXPECT_EQ(a, b);
  EXPECT_NE(a, c);
  // Grain is small and unbiased: the mean byte stays within half a code of the clean image.
  double diff = 0;
  for (size_t i = 0; i < a.size(); ++i) diff += double(a[i]) - double(clean[i]);
  EXPECT_LT(std::abs(diff / double(a.size())), 0.5);
  EXPECT_NE(a, clean);
}

}  // namespace
}  // namespace silva::render
