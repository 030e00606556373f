#include "world/chunk_cache.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <map>

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

/// One chunk generated alone, with its own and each neighbour's candidates placed for it only.
ChunkContent generated_alone(const WorldContext& ctx, ChunkCoord coord) {
  std::map<ChunkCoord, ChunkCandidates> around;
  for (ChunkCoord n : ring_neighbours({coord}, ctx.neighbour_ring)) around.emplace(n, place_candidates(ctx, n, false));
  return generate_chunk(ctx, coord, place_candidates(ctx, coord, true),
                        [&](ChunkCoord c) -> const ChunkCandidates& { return around.at(c); });
}

TEST(ChunkCache, ABatchSharingNeighboursEqualsEachChunkAlone) {
  const WorldContext ctx = make_world_context(test::small_world_config(4, 1), test::small_library());
  // A block whose chunks are each other's neighbours, and one apart from it.
  const std::vector<ChunkCoord> coords{{1, 1}, {2, 1}, {1, 2}, {2, 2}, {-3, 0}};
  const std::vector<ChunkContent> batch = generate_chunks(ctx, coords);
  ASSERT_EQ(batch.size(), coords.size());
  size_t objects = 0;
  for (size_t k = 0; k < coords.size(); ++k) {
    EXPECT_EQ(batch[k].coord, coords[k]);
    EXPECT_EQ(chunk_hash(batch[k]), chunk_hash(generated_alone(ctx, coords[k]))) << coords[k].i << "," << coords[k].j;
    objects += batch[k].objects.size();
  }
  EXPECT_GT(objects, 0u);
  const auto drawable = drawable_chunks(ctx, coords);
  EXPECT_EQ(drawable[4]->terrain_lod.indices, drawable_chunk(ctx, coords[4]).terrain_lod.indices);
}

TEST(ChunkCache, RingNeighboursListTheRingAroundEachChunkOnce) {
  const std::vector<ChunkCoord> one = ring_neighbours({{0, 0}}, 1);
  EXPECT_EQ(one.size(), 8u);
  EXPECT_FALSE(std::binary_search(one.begin(), one.end(), ChunkCoord{0, 0}));
  // Two chunks side by side: each lies in the other's ring; 12 chunks in all.
  const std::vector<ChunkCoord> two = ring_neighbours({{0, 0}, {1, 0}}, 1);
  EXPECT_EQ(two.size(), 12u);
  EXPECT_TRUE(std::binary_search(two.begin(), two.end(), ChunkCoord{0, 0}));
  EXPECT_TRUE(std::binary_search(two.begin(), two.end(), ChunkCoord{1, 0}));
  EXPECT_TRUE(std::is_sorted(two.begin(), two.end()));
}

}  // namespace silva::world
