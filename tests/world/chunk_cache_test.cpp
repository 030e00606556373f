#include "world/chunk_cache.hpp"

#include <gtest/gtest.h>

#include "core/camera.hpp"
#include "world/chunk_regions.hpp"
#include "world/terrain_lod.hpp"
#include "world/world_summary.hpp"
#include "world/world_generator.hpp"
#include "tests/common/test_library.hpp"

namespace silva::world {

TEST(ChunkCache, LruEvictsLeastRecentlyUsed) {
  const WorldContext ctx = make_world_context(test::small_world_config(2, 1), test::small_library());
  ChunkCache cache(2);
  cache.require(ctx, {{0, 0}});
  cache.require(ctx, {{1, 0}});
  cache.require(ctx, {{0, 0}});  // (1,0) is now the least recently used
  cache.require(ctx, {{2, 0}});
  EXPECT_EQ(cache.size(), 2u);
  EXPECT_NE(cache.find({0, 0}), nullptr);
  EXPECT_EQ(cache.find({1, 0}), nullptr);
  EXPECT_EQ(cache.generated(), 3u);
  // A require larger than the capacity keeps everything it needs.
  const auto got = cache.require(ctx, {{5, 5}, {6, 5}, {7, 5}});
  EXPECT_EQ(got.size(), 3u);
  EXPECT_EQ(cache.size(), 3u);
  // Cached content equals a fresh generation, plus the terrain's coarse level for drawing.
  const ChunkContent fresh = generate_chunk(ctx, {6, 5});
  EXPECT_EQ(chunk_hash(*cache.find({6, 5})), chunk_hash(fresh));
  EXPECT_TRUE(fresh.terrain_lod.indices.empty());
  EXPECT_EQ(cache.find({6, 5})->terrain_lod.indices, build_terrain_lod(fresh.terrain).indices);
  EXPECT_GT(cache.find({6, 5})->terrain_lod.triangle_count(), 0u);
  EXPECT_EQ(cache.find({6, 5})->terrain_bounds.min, fresh.terrain.bounds().min);
  EXPECT_EQ(cache.find({6, 5})->terrain_bounds.max, fresh.terrain.bounds().max);
  EXPECT_TRUE(fresh.terrain_bounds.empty());
}

TEST(ChunkCache, WalkingTheTrailKeepsLiveChunksBounded) {
  Config cfg = test::small_world_config(9, 1);
  cfg.vegetation.ground = false;  // keep the test fast: streaming does not depend on content
  cfg.camera.far = 60;
  const WorldContext ctx = make_world_context(cfg, test::small_library());
  const size_t bound = 40;
  ChunkCache cache(bound);
  const auto& nav = ctx.trail.nav;
  size_t peak = 0;
  for (int k = 0; k <= 40; ++k) {
    const double s = k * nav.length() / 40;
    const Vec3d p = nav.position(s), t = nav.tangent(s);
    Camera cam = Camera::from_fov(320, 240, 90, cfg.camera.near, cfg.camera.far);
    cam.camera_to_world = pose_from_angles(p + Vec3d(0, 0, 1.5), std::atan2(t.y(), t.x()) * 180 / M_PI, 0, 0);
    const auto need = chunks_in_view(cam, cfg.terrain.chunk_size);
    const auto got = cache.require(ctx, need);
    for (const auto& c : got) ASSERT_NE(c, nullptr);
    peak = std::max(peak, cache.size());
  }
  EXPECT_LE(peak, bound);
  EXPECT_GT(cache.generated(), bound / 2);
}

}  // namespace silva::world
