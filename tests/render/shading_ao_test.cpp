#include <gtest/gtest.h>

#include <vector>

#include "highway_targets.hpp"
#include "render/shade_ao.hpp"
#include "shading_scene.hpp"

namespace silva::render {
namespace {

TEST(ShadingAo, OpenPlaneIsUnoccludedAndTheFootOfAWallIsOccluded) {
  const Camera cam = test::test_camera(320, 200, 20);
  const GBuffer open = test::plane_gbuffer(cam, Material::Ground);
  const GBuffer walled = test::plane_gbuffer(cam, Material::Ground, 6.0);
  int occluded_feet = 0, feet = 0;
  for (int v = 0; v < cam.height; ++v) {
    for (int u = 0; u < cam.width; ++u) {
      const size_t i = size_t(v) * size_t(cam.width) + size_t(u);
      if (open.depth[i] > 0) {
        EXPECT_EQ(screen_space_ao(open, cam, u, v), 1.0f) << u << "," << v;
      }
      const Vec3f& p = walled.position[i];
      if (walled.depth[i] > 0 && walled.normal[i].z() > 0.5f && p.x() > 5.7f) {
        ++feet;
        occluded_feet += screen_space_ao(walled, cam, u, v) < 0.9f ? 1 : 0;
      }
    }
  }
  ASSERT_GT(feet, 0);
  EXPECT_GT(occluded_feet, feet / 2);
}

TEST(ShadingAo, RowsAreIdenticalOnEveryHighwayTargetAndMatchSinglePixels) {
  const Camera cam = test::test_camera(77, 40, 20);  // odd width: full vectors plus tails
  const GBuffer walled = test::plane_gbuffer(cam, Material::Ground, 6.0);
  const int half = (cam.width + 1) / 2;
  const size_t w = size_t(cam.width);
  const std::vector<int64_t> targets = test::highway_targets();
  ASSERT_GE(targets.size(), 2u);
  const std::vector<float> reference = [&] {
    const test::PinnedTarget portable(targets.back());
    std::vector<float> r(w * size_t(cam.height));
    for (int v = 0; v < cam.height; ++v) screen_space_ao_row(walled, cam, v, 0, 1, cam.width, &r[size_t(v) * w]);
    return r;
  }();
  int occluded = 0;
  for (size_t i = 0; i < reference.size(); ++i) occluded += walled.depth[i] > 0 && reference[i] < 1.0f;
  EXPECT_GT(occluded, 10);
  for (int64_t target : targets) {
    const test::PinnedTarget pinned(target);
    ASSERT_EQ(ao_simd_target(), target);
    SCOPED_TRACE(hwy::TargetName(target));
    std::vector<float> row(w);
    std::vector<float> even(static_cast<size_t>(half));
    std::vector<int32_t> columns;  // every third pixel, right to left
    for (int u = cam.width - 1; u >= 0; u -= 3) columns.push_back(u);
    std::vector<float> listed(columns.size());
    for (int v = 0; v < cam.height; ++v) {
      screen_space_ao_row(walled, cam, v, 0, 1, cam.width, row.data());
      screen_space_ao_row(walled, cam, v, 0, 2, half, even.data());
      screen_space_ao_columns(walled, cam, v, columns.data(), int(columns.size()), listed.data());
      for (size_t k = 0; k < columns.size(); ++k)
        EXPECT_EQ(listed[k], reference[size_t(v) * w + size_t(columns[k])]) << columns[k] << "," << v;
      for (int u = 0; u < cam.width; ++u) {
        const float expected = reference[size_t(v) * w + size_t(u)];
        EXPECT_EQ(row[size_t(u)], expected) << u << "," << v;
        EXPECT_EQ(screen_space_ao(walled, cam, u, v), expected) << u << "," << v;
        if (u % 2 == 0) {
          EXPECT_EQ(even[size_t(u / 2)], expected) << u << "," << v;
        }
      }
    }
  }
}

}  // namespace
}  // namespace silva::render
