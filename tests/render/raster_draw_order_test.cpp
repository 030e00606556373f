// Geometry front end bookkeeping: instance draw order (nearest first), the "inside the view"
// flag that lets triangles skip frustum and clip tests, and the per-item vertex cache.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <random>
#include <utility>
#include <vector>

#include "render/geometry_pass.hpp"
#include "render/instance_cull.hpp"
#include "raster_test_scenes.hpp"
#include "shading_scene.hpp"

namespace silva::render {
namespace {

using test::make_quad;
using test::OwnedScene;
using test::place;

/// A 1 m vertical quad facing -X (towards a camera on the X axis looking along +X).
Mesh small_card() {
  return make_quad(Vec3f(0, 0.5f, 0), Vec3f(0, -0.5f, 0), Vec3f(0, -0.5f, 1), Vec3f(0, 0.5f, 1), Role::Obstacle);
}

TEST(RasterDrawOrder, ItemsRunNearestFirstAndSkipCulledInstances) {
  OwnedScene s;
  const uint32_t card = s.add_mesh(small_card());
  s.add_instance(card, place(Vec3f(30, 0, 1)));   // 0: far
  s.add_instance(card, place(Vec3f(10, 0, 1)));   // 1: near
  s.add_instance(card, place(Vec3f(20, 0, 1)));   // 2: middle
  s.add_instance(card, place(Vec3f(-20, 0, 1)));  // 3: behind the camera
  s.add_instance(card, place(Vec3f(0.2f, 0, 1)));  // 4: its sphere holds the camera (negative nearness)
  s.add_instance(card, place(Vec3f(20, 0, 1)));   // 5: as near as 2 (a tie: after 2 by index)
  const Camera cam = test::test_camera(64, 48, 0);
  const ViewProjection view = ViewProjection::from_camera(cam);
  std::vector<BoundingSphere> spheres;
  mesh_spheres(s.scene, spheres);
  InstanceSelection sel;
  select_instances(s.scene, view, spheres, false, sel);
  EXPECT_EQ(sel.lod[3], kCulled);
  ASSERT_LT(sel.nearness[4], 0.0);
  EXPECT_EQ(sel.order, (std::vector<uint32_t>{4, 1, 2, 5, 0}));
  std::vector<DrawItem> items;
  EXPECT_EQ(build_draw_items(s.scene, sel, items), 10u);  // five drawn cards of 2 triangles
  ASSERT_EQ(items.size(), 5u);
  EXPECT_EQ(items[0].instance, 4u);
  EXPECT_EQ(items[1].instance, 1u);
  EXPECT_EQ(items[2].instance, 2u);
  EXPECT_EQ(items[3].instance, 5u);
  EXPECT_EQ(items[4].instance, 0u);
}

TEST(RasterDrawOrder, ManyInstancesSortByFloatNearnessThenIndex) {
  OwnedScene s;
  const uint32_t card = s.add_mesh(small_card());
  std::mt19937 gen(11);
  std::uniform_real_distribution<float> x(-5.0f, 300.0f), y(-40.0f, 40.0f);
  for (const float near : {0.3f, 0.1f, 0.2f}) s.add_instance(card, place(Vec3f(near, 0, 1)));  // negative nearness
  for (int i = 0; i < 3000; ++i) {
    const Vec3f p(x(gen), y(gen), 1);
    s.add_instance(card, place(p));
    if (i % 7 == 0) s.add_instance(card, place(p));  // ties
  }
  const ViewProjection view = ViewProjection::from_camera(test::test_camera(64, 48, 0));
  std::vector<BoundingSphere> spheres;
  mesh_spheres(s.scene, spheres);
  InstanceSelection sel;
  select_instances(s.scene, view, spheres, false, sel);
  std::vector<std::pair<float, uint32_t>> want;
  for (uint32_t i = 0; i < sel.lod.size(); ++i)
    if (sel.lod[i] != kCulled) want.emplace_back(float(sel.nearness[i]), i);
  std::sort(want.begin(), want.end());
  ASSERT_GT(want.size(), 500u);
  ASSERT_LT(want.front().first, 0.0f);  // negative nearness too
  ASSERT_EQ(sel.order.size(), want.size());
  for (size_t k = 0; k < want.size(); ++k) ASSERT_EQ(sel.order[k], want[k].second) << "position " << k;
}

TEST(RasterDrawOrder, InsideFlagOnlyForSpheresClearOfEveryPlane) {
  OwnedScene s;
  const uint32_t card = s.add_mesh(small_card());
  s.add_instance(card, place(Vec3f(20, 0, 1.5f)));   // 0: in the middle of the view
  s.add_instance(card, place(Vec3f(20, 20, 1.5f)));  // 1: straddles the left image side (90 deg fov)
  s.add_instance(card, place(Vec3f(0.3f, 0, 1.5f)));  // 2: crosses the near plane
  const Camera cam = test::test_camera(64, 48, 0);
  std::vector<BoundingSphere> spheres;
  mesh_spheres(s.scene, spheres);
  InstanceSelection sel;
  select_instances(s.scene, ViewProjection::from_camera(cam), spheres, false, sel);
  ASSERT_NE(sel.lod[1], kCulled);
  ASSERT_NE(sel.lod[2], kCulled);
  EXPECT_EQ(sel.inside[0], 1u);
  EXPECT_EQ(sel.inside[1], 0u);
  EXPECT_EQ(sel.inside[2], 0u);
  EXPECT_LT(sel.nearness[2], sel.nearness[0]);
}

TEST(RasterDrawOrder, VertexCacheTransformsOncePerItem) {
  VertexCache cache;
  int calls = 0;
  const auto position = [&] {
    ++calls;
    return Vec3d(1, 2, double(calls));
  };
  cache.begin_item(4);
  SetupVertex& a = cache.get(2, position);
  a.projected = true;
  EXPECT_EQ(&cache.get(2, position), &a);
  EXPECT_EQ(calls, 1);
  EXPECT_TRUE(cache.get(2, position).projected);
  cache.begin_item(4);  // a new item: the slot is stale and recomputed, its projection dropped
  EXPECT_EQ(cache.get(2, position).p.z(), 2.0);
  EXPECT_FALSE(cache.get(2, position).projected);
  EXPECT_EQ(calls, 2);
  cache.item = 0xffffffffu;  // the next item wraps the counter: every stamp must be forgotten
  cache.stamp[3] = 1;
  cache.begin_item(4);
  EXPECT_EQ(cache.item, 1u);
  cache.get(3, position);
  EXPECT_EQ(calls, 3);
}

}  // namespace
}  // namespace silva::render
