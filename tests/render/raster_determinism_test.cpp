// Determinism: identical buffers for any thread count and for every Highway target.
#include <gtest/gtest.h>

#include <cstring>
#include <string>
#include <vector>

#include <hwy/targets.h>
#include <tbb/task_arena.h>

#include "raster_test_scenes.hpp"
#include "render/renderer.hpp"
#include "render/tile_raster.hpp"

namespace silva::render {
namespace {

/// True when two vectors hold the same bytes.
template <typename T>
bool same_bytes(const std::vector<T>& a, const std::vector<T>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0;
}

/// Asserts two G-buffers are bit-identical in every plane.
void expect_identical(const GBuffer& a, const GBuffer& b) {
  EXPECT_TRUE(same_bytes(a.depth, b.depth));
  EXPECT_TRUE(same_bytes(a.position, b.position));
  EXPECT_TRUE(same_bytes(a.normal, b.normal));
  EXPECT_TRUE(same_bytes(a.uv, b.uv));
  EXPECT_TRUE(same_bytes(a.role, b.role));
  EXPECT_TRUE(same_bytes(a.material, b.material));
  EXPECT_TRUE(same_bytes(a.instance_id, b.instance_id));
  EXPECT_TRUE(same_bytes(a.variation, b.variation));
}

/// The forest scene plus an alpha-tested, double-sided card wall and coplanar overlapping quads
/// (equal-depth ties) so every path of the tile rasteriser runs.
test::OwnedScene busy_scene(Camera& cam) {
  test::OwnedScene s = test::forest_scene(cam, 256, 192);
  auto mask = std::make_shared<AlphaMask>();
  mask->width = mask->height = 16;
  for (int i = 0; i < 256; ++i) mask->alpha.push_back(uint8_t((i * 37) % 256));
  Mesh card = test::make_quad({6, -2, 0}, {6, 2, 0}, {6, 2, 3}, {6, -2, 3}, Role::TreeCanopy, true, mask);
  s.add_instance(s.add_mesh(std::move(card)), test::place(Vec3f(0, 0, 0.3f)), 90);
  const uint32_t tie = s.add_mesh(test::make_quad({9, -1, 0}, {9, 1, 0}, {9, 1, 2}, {9, -1, 2}, Role::Stump, true));
  s.add_instance(tie, test::place(Vec3f(0, 0, 0.5f)), 91);
  s.add_instance(tie, test::place(Vec3f(0, 0.5f, 0.5f)), 92);  // same plane, overlapping
  return s;
}

/// Renders the busy scene's G-buffer inside an arena of `threads` threads; the second frame's
/// counters go to `stats` when given.
GBuffer render_with_threads(int threads, const test::OwnedScene& s, const Camera& cam, int tile_size = 64,
                            RenderStats* stats = nullptr) {
  GBuffer g;
  tbb::task_arena arena(threads);
  arena.execute([&] {
    Renderer renderer;
    RenderOptions opt;
    opt.tile_size = tile_size;
    renderer.render_gbuffer(s.scene, cam, opt, g);
    renderer.render_gbuffer(s.scene, cam, opt, g, stats);  // second frame reuses the scratch
  });
  return g;
}

TEST(RasterDeterminism, OneAndTwoThreadsGiveIdenticalBuffers) {
  Camera cam;
  const test::OwnedScene s = busy_scene(cam);
  const GBuffer one = render_with_threads(1, s, cam);
  const GBuffer two = render_with_threads(2, s, cam);
  expect_identical(one, two);
  expect_identical(one, render_with_threads(2, s, cam, 16));  // tile size does not change pixels
  size_t ties = 0;
  for (uint32_t id : one.instance_id) ties += id == 91 || id == 92;
  EXPECT_GT(ties, 100u);
}

// Each tile sees its triangles in draw order whatever thread set them up, so the early depth
// test rejects the same work: every counter, overdraw included, is the same for any thread count.
TEST(RasterDeterminism, WorkCountersDoNotDependOnTheThreadCount) {
  Camera cam;
  const test::OwnedScene s = busy_scene(cam);
  RenderStats one;
  render_with_threads(1, s, cam, 64, &one);
  ASSERT_GT(one.pixels_shaded_or_written, one.pixels_covered);  // overdraw happens
  for (int threads : {2, 3, 4}) {
    SCOPED_TRACE(threads);
    RenderStats many;
    render_with_threads(threads, s, cam, 64, &many);
    EXPECT_EQ(one.triangles_rasterised, many.triangles_rasterised);
    EXPECT_EQ(one.tile_bin_entries, many.tile_bin_entries);
    EXPECT_EQ(one.fragments_covered, many.fragments_covered);
    EXPECT_EQ(one.pixels_shaded_or_written, many.pixels_shaded_or_written);
  }
}

TEST(RasterDeterminism, EveryHighwayTargetGivesIdenticalBuffers) {
  Camera cam;
  const test::OwnedScene s = busy_scene(cam);
  hwy::SetSupportedTargetsForTest(0);
  const std::vector<int64_t> targets = hwy::SupportedAndGeneratedTargets();  // best first
  ASSERT_GE(targets.size(), 1u);
  const int64_t scalar = targets.back();
  EXPECT_TRUE(scalar == HWY_SCALAR || scalar == HWY_EMU128) << hwy::TargetName(scalar);
  hwy::SetSupportedTargetsForTest(scalar);
  ASSERT_EQ(raster_simd_target(), scalar);
  const GBuffer reference = render_with_threads(2, s, cam);
  for (int64_t target : targets) {
    hwy::SetSupportedTargetsForTest(target);
    ASSERT_EQ(raster_simd_target(), target);
    SCOPED_TRACE(hwy::TargetName(target));
    expect_identical(reference, render_with_threads(2, s, cam));
  }
  hwy::SetSupportedTargetsForTest(0);
  std::string names;
  for (int64_t t : targets) names += std::string(hwy::TargetName(t)) + " ";
  RecordProperty("targets", names);
  EXPECT_GE(targets.size(), 2u) << "only " << names << "- no SIMD target to compare with scalar";
}

}  // namespace
}  // namespace silva::render
