// The asset files' own colours: texture sampling, colour factor and the packed sRGB8 G-buffer form.
#include "core/base_color.hpp"

#include <gtest/gtest.h>

namespace silva {
namespace {

/// A 4 x 1 texture: two red texels, then two blue ones.
BaseColor red_red_blue_blue() {
  BaseColor c;
  c.width = 4;
  c.height = 1;
  c.srgb = {255, 0, 0, 255, 0, 0, 0, 0, 255, 0, 0, 255};
  return c;
}

TEST(BaseColor, SrgbDecodingHitsTheCurve) {
  EXPECT_EQ(srgb8_to_linear(0), 0.0f);
  EXPECT_EQ(srgb8_to_linear(255), 1.0f);
  EXPECT_NEAR(srgb8_to_linear(188), 0.5029f, 1e-4f);  // (188/255 + 0.055)/1.055)^2.4
  EXPECT_NEAR(srgb8_to_linear(10), 10.0f / 255.0f / 12.92f, 1e-7f);  // linear toe
}

TEST(BaseColor, PackRoundTripsEveryCodeAndIsNeverZero) {
  for (int c = 0; c < 256; ++c) {
    const float x = srgb8_to_linear(uint8_t(c));
    const uint32_t packed = pack_srgb8(Vec3f(x, x, x));
    EXPECT_NE(packed, 0u);
    EXPECT_EQ(packed, uint32_t(c) | uint32_t(c) << 8 | uint32_t(c) << 16 | 0xffu << 24) << c;
    EXPECT_EQ(unpack_srgb8(packed), Vec3f(x, x, x));
  }
  EXPECT_EQ(pack_srgb8(Vec3f(-1, 0, 2)), 0xff000000u | 255u << 16);  // clamped
}

TEST(BaseColor, TexelCentresAndSpansBetweenEqualTexelsArePure) {
  const BaseColor c = red_red_blue_blue();
  for (float u : {0.125f, 0.2f, 0.375f, 1.25f, -0.75f}) EXPECT_EQ(c.albedo(u, 0.5f), Vec3f(1, 0, 0)) << u;
  for (float u : {0.625f, 0.8f, 0.875f}) EXPECT_EQ(c.albedo(u, 0.3f), Vec3f(0, 0, 1)) << u;
}

TEST(BaseColor, BilinearBlendsInLinearSpaceAndWraps) {
  const BaseColor c = red_red_blue_blue();
  const Vec3f mid = c.albedo(0.5f, 0.5f);  // halfway between texel 1 (red) and 2 (blue)
  EXPECT_NEAR(mid.x(), 0.5f, 1e-6f);
  EXPECT_NEAR(mid.z(), 0.5f, 1e-6f);
  const Vec3f seam = c.albedo(0.0f, 0.5f);  // halfway between texel 3 (blue) and, wrapped, texel 0 (red)
  EXPECT_NEAR(seam.x(), 0.5f, 1e-6f);
  EXPECT_NEAR(seam.z(), 0.5f, 1e-6f);
}

TEST(BaseColor, FactorScalesAndStandsAloneWithoutTexture) {
  BaseColor c = red_red_blue_blue();
  c.factor = Vec3f(0.5f, 1.0f, 0.25f);
  EXPECT_EQ(c.albedo(0.25f, 0.0f), Vec3f(0.5f, 0, 0));
  EXPECT_EQ(c.albedo(0.75f, 0.0f), Vec3f(0, 0, 0.25f));
  BaseColor plain;
  plain.factor = Vec3f(0.2f, 0.3f, 0.4f);
  EXPECT_EQ(plain.albedo(0.9f, 0.1f), Vec3f(0.2f, 0.3f, 0.4f));
}

}  // namespace
}  // namespace silva
