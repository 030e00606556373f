// Known answers for `silva verify`'s per-pixel comparison and its error histogram.
#include "app/commands/verify/verify_compare.hpp"

#include <gtest/gtest.h>

namespace silva::app {
namespace {

TEST(ErrorHistogram, QuantilesAreBinEdgesAtOrAboveTheValue) {
  ErrorHistogram h;
  for (int i = 1; i <= 1000; ++i) h.add(1e-6 * i);  // 1e-6 ... 1e-3
  EXPECT_EQ(h.count, 1000u);
  EXPECT_DOUBLE_EQ(h.max, 1e-3);
  const double p50 = h.quantile(0.5), p99 = h.quantile(0.99);
  EXPECT_GE(p50, 500e-6);
  EXPECT_LE(p50, 500e-6 * 1.05);  // 50 bins per decade: edges 4.7 % apart
  EXPECT_GE(p99, 990e-6);
  EXPECT_LE(p99, 1e-3);
  EXPECT_DOUBLE_EQ(h.quantile(1.0), 1e-3);
  h.add(0.0);
  EXPECT_EQ(h.bins[0], 1u);
  EXPECT_EQ(ErrorHistogram().quantile(0.5), 0.0);
}

TEST(ErrorHistogram, MergeAddsCounts) {
  ErrorHistogram a, b;
  a.add(0.5);
  b.add(2.0);
  b.add(0.0);
  a.merge(b);
  EXPECT_EQ(a.count, 3u);
  EXPECT_DOUBLE_EQ(a.max, 2.0);
  EXPECT_EQ(a.at_most(1e-12), 1u);
}

TEST(InteriorPixel, OneClassInTheClippedNeighbourhood) {
  // 4 x 3, class 2 in column 3 only.
  const std::vector<uint8_t> s = {1, 1, 1, 2, 1, 1, 1, 2, 1, 1, 1, 2};
  EXPECT_TRUE(interior_pixel(s, 4, 3, 0));   // corner: its 2x2 neighbourhood is all 1
  EXPECT_TRUE(interior_pixel(s, 4, 3, 5));   // (1, 1)
  EXPECT_FALSE(interior_pixel(s, 4, 3, 6));  // (2, 1) touches column 3
  EXPECT_FALSE(interior_pixel(s, 4, 3, 3));  // (3, 0) touches column 2
}

/// A hit of `role` at depth z.
raycast::RayHit hit(Role role, float z, uint32_t instance = 0) {
  raycast::RayHit h;
  h.hit = true;
  h.t = z;
  h.role = role;
  h.instance_id = instance;
  h.normal = Vec3f::UnitZ();
  return h;
}

TEST(CompareFrame, CountsClassesDepthAndInstancesByKind) {
  // 5 x 3: ground (1) everywhere but a trunk (3, instance 42) at (4, 1); sky (0) at (0, 0).
  FrameTruth t;
  t.width = 5;
  t.height = 3;
  t.semantic.assign(15, 1);
  t.semantic[0] = 0;
  t.semantic[9] = 3;
  t.depth.assign(15, 10.0f);
  t.depth[0] = 0;
  t.instance.assign(15, 0);
  t.instance[9] = 42;
  t.normal.assign(15, Vec3f::UnitZ());
  t.normal[0] = Vec3f::Zero();
  std::vector<uint32_t> pixels;
  std::vector<raycast::RayHit> hits;
  for (uint32_t p = 0; p < 15; ++p) {
    pixels.push_back(p);
    hits.push_back(p == 0 ? raycast::RayHit{} : p == 9 ? hit(Role::TreeTrunk, 10.0f, 42) : hit(Role::Ground, 10.0f));
  }
  hits[6] = hit(Role::Ground, 10.05f);  // (1, 1): a silhouette pixel (it touches the sky), depth 0.5 % off
  hits[7] = hit(Role::Obstacle, 10.0f);  // (2, 1): interior, wrong class
  const VerifyTally v = compare_frame(t, pixels, hits, default_ontology(), {});
  // Interior: (2, 0), (2, 1), (0, 2), (1, 2), (2, 2); the rest touch the sky or the trunk.
  const auto [ip, ia] = v.interior.total();
  const auto [sp, sa] = v.silhouette.total();
  EXPECT_EQ(ip, 5u);
  EXPECT_EQ(sp, 10u);
  EXPECT_EQ(ip - ia, 1u);  // the obstacle hit
  EXPECT_EQ(sp, sa);       // every silhouette pixel agrees
  EXPECT_EQ(v.confusion.at({1, 9}), 1u);
  EXPECT_EQ(v.depth_hit, 14u);
  EXPECT_EQ(v.depth_within, 13u);
  EXPECT_EQ(v.depth_only_file + v.depth_only_ray, 0u);
  EXPECT_NEAR(v.depth_error.max, 0.005, 1e-6);
  EXPECT_EQ(v.depth_within_by_class[1], 12u);
  EXPECT_EQ(v.instance_pixels, ip);
  EXPECT_EQ(v.instance_agree, ip);  // the trunk is a silhouette pixel; ground has no instance
  EXPECT_EQ(v.normal_error_deg.count, 12u);  // same class, depth within tolerance
  ASSERT_FALSE(v.examples.empty());
  EXPECT_EQ(v.examples[0].x, 2);  // the interior class mismatch comes first
  EXPECT_EQ(v.examples[0].ray_class, 9);
  // A depth PNG's millimetres are allowed their rounding; a miss where the file has a depth is counted.
  t.depth_step = 0.001;
  t.depth[6] = 0.2f;
  hits[6] = hit(Role::Ground, 0.2004f);
  hits[8] = raycast::RayHit{};
  const VerifyTally w = compare_frame(t, pixels, hits, default_ontology(), {});
  EXPECT_EQ(w.depth_only_file, 1u);
  EXPECT_EQ(w.depth_within, 13u);
}

}  // namespace
}  // namespace silva::app
