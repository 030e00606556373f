#include "world/placement.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "world/chunk_regions.hpp"
#include "world/class_mix.hpp"
#include "tests/common/test_library.hpp"

namespace silva::world {

TEST(ClassMix, SumsToOneAndTreeShareIsTheDensity) {
  for (double d : {1.0, 5.0, 10.0, 20.0, 25.0}) {
    for (bool ground : {true, false}) {
      const ClassMix m = class_mix(d, ground);
      double sum = 0;
      for (double p : m) {
        EXPECT_GE(p, 0.0);
        sum += p;
      }
      EXPECT_NEAR(sum, 1.0, 1e-12);
      EXPECT_NEAR(m[size_t(PointClass::Conifer)] + m[size_t(PointClass::Broadleaf)], d / 100, 1e-12);
      EXPECT_EQ(m[size_t(PointClass::Ground)] > 0, ground);
    }
  }
  // More trees, fewer ground-vegetation points (thesis Table 5.1).
  EXPECT_LT(class_mix(25, true)[size_t(PointClass::Ground)], class_mix(1, true)[size_t(PointClass::Ground)]);
  EXPECT_EQ(pick_class(class_mix(5, true), 0.0), PointClass::Conifer);
  EXPECT_EQ(pick_class(class_mix(5, false), 0.999999), PointClass::Nothing);
}

TEST(Placement, CandidatesStayInTheirAdmissibleCircleAndChunk) {
  const Config cfg = test::small_world_config(8);
  const WorldContext ctx = make_world_context(cfg, test::small_library());
  const ChunkCoord cc{-2, 1};
  const ChunkCandidates c = place_candidates(ctx, cc, true);
  EXPECT_GT(c.solids.size(), 5u);
  EXPECT_GT(c.ground.size(), 100u);
  const int n = int(cfg.terrain.chunk_size / cfg.vegetation.grid_spacing);
  for (const auto* list : {&c.solids, &c.ground}) {
    for (const Candidate& k : *list) {
      const double gx = cc.i * 32 + (k.point % n + 0.5) * 2, gy = cc.j * 32 + (k.point / n + 0.5) * 2;
      EXPECT_LT(std::hypot(k.position.x() - gx, k.position.y() - gy), 1.0);
      EXPECT_NEAR(k.position.z(), terrain_height(ctx.terrain, k.position.x(), k.position.y()), 1e-5);  // float storage
      EXPECT_EQ(k.chunk_key, cc.key());
    }
  }
  // Without ground vegetation the solids are unchanged.
  const ChunkCandidates solids_only = place_candidates(ctx, cc, false);
  ASSERT_EQ(solids_only.solids.size(), c.solids.size());
  EXPECT_TRUE(solids_only.ground.empty());
  for (size_t k = 0; k < c.solids.size(); ++k) EXPECT_EQ(solids_only.solids[k].position, c.solids[k].position);
}

TEST(Placement, NothingOnTheTrailCorridor) {
  for (int64_t seed : {1, 2, 3, 4}) {
    Config cfg = test::small_world_config(seed, 25);
    const WorldContext ctx = make_world_context(cfg, test::small_library());
    const BuiltWorld w = test::build_world(ctx, default_world_chunks(ctx.config), 2);
    // Dense samples of the nav spline (10 cm apart), checked in the horizontal plane.
    std::vector<Eigen::Vector2d> samples;
    for (double s = 0; s <= ctx.trail.nav.length(); s += 0.1) samples.push_back(ctx.trail.nav.position(s).head<2>());
    uint64_t near_trail = 0;
    for (const ChunkContent& c : w.chunks) {
      for (const Vegetation& v : c.objects) {
        const double reach = ctx.trail.corridor_half_width() + ctx.footprint[v.asset] * v.scale;
        double best = 1e9;
        for (const auto& p : samples) best = std::min(best, (p - v.position.head<2>().cast<double>()).norm());
        EXPECT_GE(best, reach - 0.01) << "seed " << seed;
        near_trail += best < reach + 1.0;
      }
    }
    EXPECT_GT(near_trail, 0u) << "objects grow right up to the corridor";
    EXPECT_GT(w.totals.trail_rejected, 0u);
  }
}

TEST(Placement, TreeCountGrowsWithDensity) {
  uint64_t last = 0;
  for (double d : {1.0, 5.0, 10.0, 20.0, 25.0}) {
    const WorldContext ctx = make_world_context(test::small_world_config(31, d), test::small_library());
    const BuiltWorld w = test::build_world(ctx, chunks_in_disc(0, 0, 40, 32), 2);
    const uint64_t trees = w.totals.objects_by_role[size_t(Role::TreeTrunk)];
    EXPECT_GT(trees, last) << d;
    last = trees;
  }
}

TEST(Placement, NoGroundVegetationWhenDisabled) {
  Config cfg = test::small_world_config(4);
  cfg.vegetation.ground = false;
  const WorldContext ctx = make_world_context(cfg, test::small_library());
  const BuiltWorld w = test::build_world(ctx, {ChunkCoord{0, 0}, ChunkCoord{1, 1}}, 1);
  EXPECT_EQ(w.totals.objects_by_role[size_t(Role::GroundVegetation)], 0u);
  EXPECT_GT(w.totals.objects, 0u);
}

}  // namespace silva::world
