#include "pipeline/schedule/world_schedule.hpp"

#include <gtest/gtest.h>

#include <algorithm>

#include "core/rng.hpp"
#include "world/chunk_regions.hpp"
#include "world/world_generator.hpp"
#include "tests/common/test_library.hpp"

namespace silva::world {

using pipeline::build_default_world;
using pipeline::build_world;

TEST(WorldBuild, SameSeedSameHashForOneAndTwoThreads) {
  const WorldContext ctx = make_world_context(test::small_world_config(77, 10), test::small_library());
  const BuiltWorld one = build_default_world(ctx, 1);
  const BuiltWorld two = build_default_world(ctx, 2);
  EXPECT_EQ(one.hash, two.hash);
  EXPECT_EQ(one.totals.objects, two.totals.objects);
  EXPECT_EQ(one.chunks.size(), default_world_chunks(ctx.config).size());
  EXPECT_GT(one.totals.objects, 1000u);
}

TEST(WorldBuild, StreamingOrderEqualsAllAtOnce) {
  const WorldContext ctx = make_world_context(test::small_world_config(12, 5), test::small_library());
  std::vector<ChunkCoord> coords = chunks_in_disc(10, -5, 40, 32);
  const BuiltWorld all = build_world(ctx, coords, 2);
  // One chunk at a time, in a shuffled order, each generated on its own.
  std::vector<ChunkCoord> shuffled = coords;
  for (size_t k = shuffled.size(); k > 1; --k) {
    Rng r(1, k, Purpose::Test);
    std::swap(shuffled[k - 1], shuffled[r.below(uint32_t(k))]);
  }
  ASSERT_NE(shuffled, coords);
  std::vector<ChunkContent> streamed;
  for (ChunkCoord c : shuffled) streamed.push_back(generate_chunk(ctx, c));
  std::sort(streamed.begin(), streamed.end(), [](const auto& a, const auto& b) { return a.coord < b.coord; });
  EXPECT_EQ(world_hash(streamed), all.hash);
  for (size_t k = 0; k < streamed.size(); ++k) EXPECT_EQ(chunk_hash(streamed[k]), chunk_hash(all.chunks[k]));
}

TEST(WorldBuild, DifferentSeedsDiffer) {
  const auto& lib = test::small_library();
  const std::vector<ChunkCoord> coords = {{0, 0}, {1, 0}};
  const BuiltWorld a = build_world(make_world_context(test::small_world_config(1), lib), coords, 1);
  const BuiltWorld b = build_world(make_world_context(test::small_world_config(2), lib), coords, 1);
  const BuiltWorld a2 = build_world(make_world_context(test::small_world_config(1), lib), coords, 1);
  EXPECT_NE(a.hash, b.hash);
  EXPECT_EQ(a.hash, a2.hash);
}

TEST(WorldBuild, TotalsAddUp) {
  const WorldContext ctx = make_world_context(test::small_world_config(3, 25), test::small_library());
  const BuiltWorld w = build_world(ctx, chunks_in_disc(0, 0, 30, 32), 2);
  uint64_t objects = 0, triangles = 0;
  for (const ChunkContent& c : w.chunks) {
    objects += c.objects.size();
    triangles += c.terrain.triangle_count();
  }
  EXPECT_EQ(w.totals.objects, objects);
  EXPECT_EQ(w.totals.triangles, triangles);
  EXPECT_EQ(w.totals.chunks, w.chunks.size());
  EXPECT_LE(w.totals.objects + w.totals.dropped + w.totals.ground_dropped, w.totals.candidates);
  EXPECT_GT(w.totals.broad_queries, w.totals.narrow_queries / 10);
}

}  // namespace silva::world
