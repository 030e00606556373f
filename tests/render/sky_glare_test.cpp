#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "render/lighting.hpp"
#include "render/sky.hpp"
#include "render/sky_glare.hpp"

namespace silva::render {
namespace {

constexpr int kSize = 512;  ///< Pixels per side of the test view.

/// A kSize x kSize view looking up into the sky: depth 0 (sky) where `sky_at(u, v)`, a surface 10 m away elsewhere.
template <class SkyAt>
GBuffer view_with_sky(SkyAt sky_at) {
  GBuffer g;
  g.resize(kSize, kSize);
  for (int v = 0; v < kSize; ++v)
    for (int u = 0; u < kSize; ++u) g.depth[size_t(v) * kSize + size_t(u)] = sky_at(u, v) ? 0.0f : 10.0f;
  return g;
}

/// A camera of the test view pitched up 60 degrees (sky in every direction).
Camera upward_camera() {
  Camera c = Camera::from_fov(kSize, kSize, 60.0, 0.1, 1000.0);
  c.camera_to_world = pose_from_angles(Vec3d(0, 0, 1.5), 0.0, 60.0, 0.0);
  return c;
}

/// Row v of a frame of `value` everywhere after the glare.
std::vector<Vec3f> glared_row(const SkyGlare& glare, int v, const Vec3f& value) {
  std::vector<Vec3f> row(kSize, value);
  glare.apply_row(v, row.data());
  return row;
}

TEST(SkyGlare, NoSkyOrNoStrengthChangesNothing) {
  const Sky sky(LightingPreset{});
  const Camera camera = upward_camera();
  const GBuffer closed = view_with_sky([](int, int) { return false; });
  EXPECT_FALSE(SkyGlare(closed, camera, sky, 0.03f).active());
  const GBuffer open = view_with_sky([](int u, int) { return u < kSize / 2; });
  EXPECT_FALSE(SkyGlare(open, camera, sky, 0.0f).active());
  EXPECT_TRUE(SkyGlare(open, camera, sky, 0.03f).active());
}

TEST(SkyGlare, SkyGlowsIntoTheEdgeAndFadesWithDistance) {
  // Sky on the left half: the surface pixels right of the edge gain light, most at the edge, falling with
  // distance, and the sky pixels give up about the share k of their own light.
  const Sky sky(LightingPreset{});
  const Camera camera = upward_camera();
  const GBuffer g = view_with_sky([](int u, int) { return u < kSize / 2; });
  const float k = 0.03f;
  const SkyGlare glare(g, camera, sky, k);
  const Vec3f surface(0.01f, 0.01f, 0.01f);
  const std::vector<Vec3f> row = glared_row(glare, kSize / 2, surface);
  const float at_edge = row[kSize / 2].y() - surface.y(), near = row[kSize / 2 + 8].y() - surface.y();
  const float far = row[kSize / 2 + 100].y() - surface.y();
  EXPECT_GT(at_edge, near);
  EXPECT_GT(near, far);
  EXPECT_GT(far, 0.0f);  // the widest blur still reaches 100 px
  EXPECT_EQ(row[kSize - 1], surface);  // and ends within its 3 sigma, 192 px
  const Vec3f sky_light = sky.radiance(Vec3f(0, 0, 1));
  EXPECT_GT(at_edge, 0.1f * k * sky_light.y());  // a visible share of the sky's light right at the edge
  EXPECT_LT(at_edge, k * sky_light.y() * kGlareSourceCap);
  // Deep inside the sky, a pixel with the sky's radiance keeps about its value: it gives up k L and gets k H, H ~ L.
  const Vec3f deep = sky.radiance(camera.ray_direction(8, kSize / 2).normalized().cast<float>());
  const Vec3f inside = glared_row(glare, kSize / 2, deep)[8];
  EXPECT_NEAR(inside.y(), deep.y(), 0.5f * k * deep.y());
}

TEST(SkyGlare, TheLightSpreadIsTheLightTheSkyGivesUp) {
  // A 32 x 32 px sky gap amid the view, each sky pixel lit with the sky's radiance, the forest black: the light
  // the surface pixels gain is the light the sky pixels lose (the widest blur's 3 sigma stays inside the view,
  // so only a sliver leaves it; the source samples each block's centre, so its light differs a little).
  const Sky sky(LightingPreset{});
  const Camera camera = upward_camera();
  const auto in_gap = [](int u, int v) { return std::abs(u - kSize / 2 + 0.5) < 16 && std::abs(v - kSize / 2 + 0.5) < 16; };
  const GBuffer g = view_with_sky(in_gap);
  const SkyGlare glare(g, camera, sky, 0.03f);
  double gained = 0.0, lost = 0.0;
  for (int v = 0; v < kSize; ++v) {
    std::vector<Vec3f> row(kSize, Vec3f::Zero());
    for (int u = 0; u < kSize; ++u)
      if (in_gap(u, v)) row[size_t(u)] = sky.radiance(camera.ray_direction(u, v).normalized().cast<float>());
    const std::vector<Vec3f> before = row;
    glare.apply_row(v, row.data());
    for (int u = 0; u < kSize; ++u) (in_gap(u, v) ? lost : gained) += double(std::abs(row[size_t(u)].y() - before[size_t(u)].y()));
  }
  EXPECT_GT(lost, 0.0);
  EXPECT_NEAR(gained, lost, 0.1 * lost);
}

}  // namespace
}  // namespace silva::render
