// Known answers for the ray-cast scene: planes, boxes, alpha cards, cut-offs, groups, thread counts.
#include "raycast/ray_scene.hpp"

#include <gtest/gtest.h>
#include <tbb/task_arena.h>

#include <cmath>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "core/rng.hpp"
#include "tests/raycast/test_meshes.hpp"

namespace silva::raycast {
namespace {

using test::alpha_card;
using test::box;
using test::placed;
using test::square;

/// A ray from `o` along `d`.
Ray ray(const Vec3d& o, const Vec3d& d) {
  Ray r;
  r.origin = o;
  r.direction = d;
  return r;
}

TEST(RayScene, EmptySceneMissesEverything) {
  RayScene scene;
  scene.commit();
  EXPECT_FALSE(scene.cast(ray({0, 0, 5}, {0, 0, -1})).hit);
}

TEST(RayScene, PlaneAndScaledBoxGiveAnalyticHits) {
  const Mesh plane = square(100.0f), cube = box(0.5f);
  RayScene scene;
  const RayInstance instances[] = {{&plane, placed({0, 0, -1}), 0}, {&cube, placed({10, 0, 1}, 2.0f), 42}};
  scene.add_group(7, instances);
  scene.commit();
  const RayHit down = scene.cast(ray({3, 4, 5}, {0, 0, -1}));
  ASSERT_TRUE(down.hit);
  EXPECT_FLOAT_EQ(down.t, 6.0f);
  EXPECT_EQ(down.role, Role::Ground);
  EXPECT_EQ(down.instance_id, 0u);
  EXPECT_NEAR(down.position.z(), -1.0f, 1e-5f);
  EXPECT_NEAR(down.normal.z(), 1.0f, 1e-6f);
  // The box is scaled 2x: its face x = 10 - 1 = 9 is hit at t = 9 from the origin.
  const RayHit side = scene.cast(ray({0, 0, 1}, {1, 0, 0}));
  ASSERT_TRUE(side.hit);
  EXPECT_NEAR(side.t, 9.0f, 1e-5f);
  EXPECT_EQ(side.role, Role::Obstacle);
  EXPECT_EQ(side.instance_id, 42u);
  EXPECT_NEAR(side.geometric_normal.x(), -1.0f, 1e-6f);
  // A direction of length 2 halves t.
  EXPECT_NEAR(scene.cast(ray({0, 0, 1}, {2, 0, 0})).t, 4.5f, 1e-5f);
  // t_far before the surface: a miss.
  Ray shortr = ray({0, 0, 1}, {1, 0, 0});
  shortr.t_far = 8.5;
  EXPECT_FALSE(scene.cast(shortr).hit);
}

TEST(RayScene, AlphaCardLetsRaysThroughTransparentTexels) {
  const Mesh plane = square(100.0f), card = alpha_card(2.0f);
  RayScene scene;
  const RayInstance instances[] = {{&plane, placed({0, 0, 0}), 0}, {&card, placed({0, 0, 1}), 5}};
  scene.add_group(1, instances);
  scene.commit();
  // u < 0.5 is y < 0 on the card: opaque. The ray goes down at 45 degrees through x = 0.
  const RayHit opaque = scene.cast(ray({-1, -0.5, 2}, {1, 0, -1}));
  ASSERT_TRUE(opaque.hit);
  EXPECT_EQ(opaque.role, Role::TreeCanopy);
  EXPECT_NEAR(opaque.t, 1.0f, 1e-5f);
  const RayHit through = scene.cast(ray({-1, 0.5, 2}, {1, 0, -1}));
  ASSERT_TRUE(through.hit);
  EXPECT_EQ(through.role, Role::Ground);
  EXPECT_NEAR(through.t, 2.0f, 1e-5f);
}

TEST(RayScene, ExactMasksPickTheTexelOnEitherSideOfATexelEdge) {
  // A card of 256 one-texel stripes, turned and placed far from the origin (where float rays are
  // coarsest); rays from 12 m away aim 1e-4 texel to either side of each texel edge.
  constexpr int kTexels = 256;
  constexpr float kSide = 0.4f;
  const Mesh card = test::striped_card(kSide, kTexels);
  const double yaw = 0.5;
  Affine3f pose = Affine3f::Zero();
  pose.block<3, 3>(0, 0) = Eigen::AngleAxisf(float(yaw), Vec3f::UnitZ()).toRotationMatrix();
  pose.col(3) = Vec3f(700.0f, -300.0f, 50.0f);
  RayScene scene;
  const RayInstance inst{&card, pose, 3};
  scene.add_group(1, std::span<const RayInstance>(&inst, 1));
  scene.commit();
  const Eigen::Matrix<double, 3, 4> m = pose.cast<double>();
  const double h = double(kSide / 2);
  CastOptions exact;
  exact.exact_masks = true;
  Rng rng(7, 1, Purpose::Test);
  int wrong = 0, cases = 0, float_wrong = 0;
  for (int edge = 1; edge < kTexels; ++edge)
    for (const double side : {-1e-4, 1e-4}) {
      const double u = (double(edge) + side) / kTexels;
      const Vec3d on_card = m.leftCols<3>() * Vec3d(0.0, -h + u * 2.0 * h, rng.range(-0.1f, 0.1f)) + m.col(3);
      const Vec3d from = Vec3d(std::cos(yaw), std::sin(yaw), 0.0) * 9.0 + Vec3d(0.0, 0.0, 8.0) +
                         Vec3d(rng.range(-3.0f, 3.0f), rng.range(-3.0f, 3.0f), 0.0);
      const bool opaque = (side < 0 ? edge - 1 : edge) % 2 == 0;
      wrong += scene.cast(ray(on_card + from, -from), exact).hit != opaque;
      float_wrong += scene.cast(ray(on_card + from, -from)).hit != opaque;
      ++cases;
    }
  EXPECT_EQ(wrong, 0) << "of " << cases << " rays";
  // The scene is one where Embree's float barycentrics do pick the wrong side (about half the rays).
  EXPECT_GT(float_wrong, cases / 10);
}

TEST(RayScene, CutoffHidesInstancesFromFarEyes) {
  const Mesh plane = square(100.0f), cube = box(0.5f);
  RayScene scene;
  RayInstance grass{&cube, placed({0, 0, 0.5f}), 0};
  grass.cutoff = 10.0f;
  grass.anchor = Vec3f(0, 0, 0.5f);
  const RayInstance instances[] = {{&plane, placed({0, 0, 0}), 0}, grass};
  scene.add_group(1, instances);
  scene.commit();
  CastOptions near_eye, far_eye;
  near_eye.eye = Vec3d(5, 0, 0);
  far_eye.eye = Vec3d(20, 0, 0);
  EXPECT_NEAR(scene.cast(ray({0, 0, 5}, {0, 0, -1}), near_eye).t, 4.0f, 1e-5f);
  EXPECT_NEAR(scene.cast(ray({0, 0, 5}, {0, 0, -1}), far_eye).t, 5.0f, 1e-5f);
}

TEST(RayScene, GroupsComeAndGoAndReleaseTheirMeshes) {
  const Mesh plane = square(10.0f), cube = box(0.5f);
  RayScene scene;
  const RayInstance a[] = {{&plane, placed({0, 0, 0}), 0}};
  const RayInstance b[] = {{&cube, placed({0, 0, 3}), 9}, {&plane, placed({20, 0, 0}), 0}};
  scene.add_group(1, a);
  scene.add_group(2, b);
  scene.commit();
  EXPECT_EQ(scene.instance_count(), 3u);
  EXPECT_EQ(scene.mesh_count(), 2u);
  EXPECT_EQ(scene.group_keys(), (std::vector<uint64_t>{1, 2}));
  EXPECT_EQ(scene.cast(ray({0, 0, 10}, {0, 0, -1})).instance_id, 9u);
  scene.remove_group(2);
  scene.commit();
  EXPECT_FALSE(scene.has_group(2));
  EXPECT_EQ(scene.mesh_count(), 1u);
  const RayHit h = scene.cast(ray({0, 0, 10}, {0, 0, -1}));
  ASSERT_TRUE(h.hit);
  EXPECT_EQ(h.instance_id, 0u);
  EXPECT_FALSE(scene.cast(ray({20, 0, 10}, {0, 0, -1})).hit);
  scene.add_group(2, b);
  scene.commit();
  EXPECT_TRUE(scene.cast(ray({20, 0, 10}, {0, 0, -1})).hit);
}

/// Hits of 5000 rays from above into 400 boxes and alpha cards (turned, scaled, on a plane), cast on
/// `threads` threads on an Embree device configured by `device_config`, with exact masks.
std::vector<RayHit> cast_random_scene(int threads, const std::string& device_config) {
  static const Mesh plane = square(200.0f), cube = box(0.5f), card = alpha_card(1.0f);
  std::vector<RayInstance> instances = {{&plane, placed({0, 0, 0}), 0}};
  Rng rng(1, 1, Purpose::Test);
  for (uint32_t i = 0; i < 400; ++i) {
    const Vec3f at(rng.range(-50, 50), rng.range(-50, 50), 0.5f);
    RayInstance r{i % 2 ? &cube : &card, placed(at, 1.0f + float(i % 3)), i + 1};
    r.object_to_world.leftCols<3>() *= Eigen::AngleAxisf(rng.range(0, 6.28f), Vec3f::UnitZ()).toRotationMatrix();
    instances.push_back(r);
  }
  std::vector<Ray> rays;
  for (uint32_t i = 0; i < 5000; ++i) {
    const double dx = rng.uniform_double() - 0.5, dy = rng.uniform_double() - 0.5;
    rays.push_back(ray({0.1, -0.2, 1.5}, {dx, dy, -0.05}));
  }
  std::vector<RayHit> hits(rays.size());
  CastOptions options;
  options.exact_masks = true;
  tbb::task_arena(threads).execute([&] {
    RayScene scene(device_config);
    scene.add_group(0, instances);
    scene.commit();
    scene.cast(rays, hits, options);
  });
  return hits;
}

/// Expects `a` and `b` to hit the same triangles at the same distances, bit for bit.
void expect_same_hits(const std::vector<RayHit>& a, const std::vector<RayHit>& b) {
  size_t hits = 0;
  for (size_t i = 0; i < a.size(); ++i) {
    ASSERT_EQ(a[i].hit, b[i].hit) << i;
    hits += a[i].hit;
    EXPECT_EQ(a[i].t, b[i].t) << i;
    EXPECT_EQ(a[i].position, b[i].position) << i;
    EXPECT_EQ(a[i].geometric_normal, b[i].geometric_normal) << i;
    EXPECT_EQ(a[i].instance_id, b[i].instance_id) << i;
    EXPECT_EQ(a[i].triangle, b[i].triangle) << i;
  }
  EXPECT_GT(hits, a.size() / 2);
}

TEST(RayScene, HitsAreTheSameForAnyThreadCount) { expect_same_hits(cast_random_scene(1, ""), cast_random_scene(2, "")); }

// Embree's kernels for each instruction set compute a hit's distance and barycentrics in float with
// different rounding; the scene recomputes them in double, so an AVX-512, an AVX2 and an SSE4.2
// machine write the same LiDAR points.
TEST(RayScene, HitsAreTheSameOnEveryEmbreeKernel) {
  const std::vector<RayHit> best = cast_random_scene(2, "");
  expect_same_hits(best, cast_random_scene(2, "isa=sse4.2"));
  if (__builtin_cpu_supports("avx2")) expect_same_hits(best, cast_random_scene(2, "isa=avx2"));
}

}  // namespace
}  // namespace silva::raycast
