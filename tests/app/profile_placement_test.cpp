#include <gtest/gtest.h>

#include <cmath>

#include "pipeline/config/config_loader.hpp"
#include "pipeline/config/run_setup.hpp"
#include "pipeline/schedule/world_schedule.hpp"
#include "bench/harness/profile_output.hpp"
#include "bench/harness/pipeline_names.hpp"
#include "bench/harness/profile_world.hpp"
#include "silva_process.hpp"
#include "world/chunk_regions.hpp"

namespace silva::bench {
namespace {

/// A small world config (128 m region) at `density`.
LoadedConfig small_config(double density) {
  ConfigSources s;
  s.overrides = {"world.extent=128", "world.render_distance=32", "trail.control_points=6",
                 "vegetation.density=" + std::to_string(density)};
  s.seed = "42";
  return load_config(s);
}

/// The chunks within 48 m of the origin (16 chunks of 32 m).
std::vector<ChunkCoord> small_region() { return world::chunks_in_disc(0, 0, 48, 32); }

/// A profiled small world at `density` and, independently built, the same world.
struct Profiled {
  WorldProfile profile;
  world::BuiltWorld world;
};

Profiled profiled(double density) {
  const LoadedConfig loaded = small_config(density);
  const RunSetup setup = make_run_setup(loaded);
  return {profile_world(setup.world, small_region(), 2), build_world(setup.world, small_region(), 1)};
}

TEST(ProfilePlacement, CountsMatchAnIndependentBuildOfTheSameWorld) {
  const Profiled p = profiled(10);
  const world::WorldTotals& t = p.world.totals;
  EXPECT_EQ(p.profile.chunks, t.chunks);
  EXPECT_EQ(p.profile.objects, t.objects);
  EXPECT_EQ(p.profile.candidates, t.candidates) << "candidates per class sum to the build's";
  EXPECT_EQ(p.profile.broad_queries, t.broad_queries);
  EXPECT_EQ(p.profile.narrow_queries, t.narrow_queries);
  uint64_t dropped = 0, adjusted = 0;
  for (int r = 0; r < kRoleCount; ++r) {
    const ClassProfile& c = p.profile.classes[size_t(r)];
    EXPECT_EQ(c.placed, t.objects_by_role[size_t(r)]) << "role " << r;
    EXPECT_EQ(c.placed + c.dropped, c.candidates) << "role " << r;
    dropped += c.dropped;
    adjusted += c.adjusted;
  }
  EXPECT_EQ(dropped, t.dropped + t.ground_dropped);
  EXPECT_EQ(adjusted, t.adjusted);
}

TEST(ProfilePlacement, PerHectareTimesAreaIsTheCountAndCoverIsAPercentage) {
  const Profiled p = profiled(10);
  EXPECT_DOUBLE_EQ(p.profile.area_ha, 16 * 32.0 * 32.0 / 1e4);
  for (int r = 0; r < kRoleCount; ++r) {
    const ClassProfile& c = p.profile.classes[size_t(r)];
    EXPECT_NEAR(c.per_ha * p.profile.area_ha, double(c.placed), 1e-9 * double(c.placed + 1)) << "role " << r;
    EXPECT_GE(c.cover_pct, 0.0);
    EXPECT_LE(c.cover_pct, 100.0);
    if (c.nearest) {
      EXPECT_LE(c.nearest->min, c.nearest->p10);
      EXPECT_LE(c.nearest->p10, c.nearest->median);
      EXPECT_LE(c.nearest->median, c.nearest->p90);
      EXPECT_GT(c.nearest->min, 0.0) << "role " << r;
    }
  }
  EXPECT_GT(p.profile.canopy_cover_pct, 0.0);
  EXPECT_LE(p.profile.canopy_cover_pct, 100.0);
  uint64_t heat = 0;
  for (uint32_t h : p.profile.heat) heat += h;
  const auto& c = p.profile.classes;
  EXPECT_EQ(heat, p.profile.objects - c[size_t(Role::GroundVegetation)].placed - c[size_t(Role::Ground)].placed)
      << "every thing in one heatmap cell (ground vegetation and ground-cover debris are stuff)";
}

TEST(ProfilePlacement, TreesPerHectareAndCanopyGrowWithDensity) {
  double trees = -1, canopy = -1;
  for (double density : {1.0, 5.0, 25.0}) {
    const WorldProfile p = profiled(density).profile;
    const double t = p.classes[size_t(Role::TreeTrunk)].per_ha;
    EXPECT_GT(t, trees) << "density " << density;
    EXPECT_GT(p.canopy_cover_pct, canopy) << "density " << density;
    trees = t;
    canopy = p.canopy_cover_pct;
  }
}

TEST(ProfileMetrics, NearestNeighboursOfALatticeAreItsSpacing) {
  std::vector<Eigen::Vector2d> points;
  for (int y = 0; y < 30; ++y)
    for (int x = 0; x < 40; ++x) points.emplace_back(2.0 * x - 17.0, 2.0 * y + 3.0);
  points.emplace_back(1000.0, 1000.0);  // a far outlier: its nearest is the lattice corner
  const auto n = nearest_neighbours(points);
  ASSERT_TRUE(n);
  EXPECT_DOUBLE_EQ(n->min, 2.0);
  EXPECT_DOUBLE_EQ(n->median, 2.0);
  EXPECT_DOUBLE_EQ(n->p90, 2.0);
  EXPECT_FALSE(nearest_neighbours({Eigen::Vector2d(1, 1)}));
  const auto pair = nearest_neighbours({Eigen::Vector2d(0, 0), Eigen::Vector2d(3, 4)});
  EXPECT_DOUBLE_EQ(pair->min, 5.0);
  EXPECT_DOUBLE_EQ(pair->p90, 5.0);
}

TEST(ProfileMetrics, NearestRankPercentiles) {
  const std::vector<double> v = {1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11};
  EXPECT_EQ(nearest_rank(v, 0.0), 1);
  EXPECT_EQ(nearest_rank(v, 0.1), 2);
  EXPECT_EQ(nearest_rank(v, 0.5), 6);
  EXPECT_EQ(nearest_rank(v, 0.9), 10);
  EXPECT_EQ(nearest_rank(v, 1.0), 11);
}

TEST(ProfileMetrics, CoverOfADiscIsItsAreaShareAndOverlapsCountOnce) {
  // Chunks (0,0)..(1,0) of 32 m, only (0,0) counted: 1024 m^2.
  CoverGrid grid(0, 0, 1, 0, 32.0, 0.125, {true, false});
  grid.add({Eigen::Vector2d(16, 16), 8.0}, 0);
  grid.add({Eigen::Vector2d(16, 16), 4.0}, 0);     // inside the first: no new cover
  grid.add({Eigen::Vector2d(48, 16), 8.0}, 0);     // in the chunk not counted
  EXPECT_NEAR(grid.percent(0), 100.0 * M_PI * 64.0 / 1024.0, 0.2);
  EXPECT_EQ(grid.percent(1), 0.0);
  grid.add({Eigen::Vector2d(16, 16), 100.0}, 1);
  EXPECT_DOUBLE_EQ(grid.percent(1), 100.0);
}

TEST(ProfileOutput, HeatmapIsAPngOfTheWorldWithAColourBar) {
  const WorldProfile p = profiled(5).profile;
  const std::vector<uint8_t> png = heatmap_png(p, 1000.0, 2);
  ASSERT_GT(png.size(), 33u);
  EXPECT_EQ(std::string(png.begin() + 1, png.begin() + 4), "PNG");
  auto be32 = [&](size_t at) { return uint32_t(png[at]) << 24 | uint32_t(png[at + 1]) << 16 | uint32_t(png[at + 2]) << 8 | png[at + 3]; };
  EXPECT_EQ(be32(16), uint32_t(p.heat_width * 2 + 8 + 24));
  EXPECT_EQ(be32(20), uint32_t(p.heat_height * 2));
  EXPECT_EQ(heat_colour(0.0), (std::array<uint8_t, 3>{68, 1, 84}));
  EXPECT_EQ(heat_colour(1.0), (std::array<uint8_t, 3>{253, 231, 37}));
  EXPECT_EQ(heat_colour(7.0), heat_colour(1.0));
}

TEST(ProfileOutput, CsvHasOneRowPerSampleAndClass) {
  const LoadedConfig loaded = small_config(5);
  const RunSetup setup = make_run_setup(loaded);
  const std::vector<ProfileSample> samples = {{5, 1.5, true, 42, profiled(5).profile}, {5, 1.5, true, 43, profiled(5).profile}};
  size_t classes = 0;
  for (const ClassProfile& c : samples[0].world.classes) classes += c.candidates || c.placed ? 1 : 0;
  const auto lines = test::lines_of(samples_csv(samples, setup.ontology));
  EXPECT_EQ(lines.size(), 1 + 2 * classes);
  EXPECT_EQ(lines[0].rfind("density,max_elevation,trail,seed,class,", 0), 0u);
  const nlohmann::json means = sweep_means(samples, setup.ontology);
  ASSERT_EQ(means.size(), 1u);
  EXPECT_EQ(means[0]["seeds"], nlohmann::json({42, 43}));
  EXPECT_DOUBLE_EQ(means[0]["world"]["objects"].get<double>(), double(samples[0].world.objects));
}

TEST(ProfileCli, BadDensityIsBadInput) {
  const auto dir = test::fresh_test_dir();
  const auto r = test::run_silva({"profile", "placement", "--densities", "5,30", "--out", (dir / "p").string()}, dir);
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_NE(r.err.find("--densities"), std::string::npos) << r.err;
  const auto t = test::run_silva({"profile", "placement", "--trail", "maybe", "--out", (dir / "p").string()}, dir);
  EXPECT_EQ(t.code, 2) << t.err;
  EXPECT_FALSE(std::filesystem::exists(dir / "p"));
}

TEST(ProfileCli, WritesJsonCsvAndOneHeatmapPerDensity) {
  const auto dir = test::fresh_test_dir();
  const auto r = test::run_silva({"profile", "placement", "--seed", "7", "--radius", "40", "--densities", "2,20",
                                  "--seeds", "2", "--set", "world.extent=128", "--set", "world.render_distance=32",
                                  "--set", "trail.control_points=6", "--out", (dir / "p").string(), "--json"},
                                 dir);
  ASSERT_EQ(r.code, 0) << r.err;
  const auto summary = nlohmann::json::parse(r.out);
  EXPECT_EQ(summary["means"].size(), 2u);
  EXPECT_TRUE(std::filesystem::exists(dir / "p" / "placement.json"));
  EXPECT_TRUE(std::filesystem::exists(dir / "p" / "placement.csv"));
  EXPECT_TRUE(std::filesystem::exists(dir / "p" / "heatmap-density-2.png"));
  EXPECT_TRUE(std::filesystem::exists(dir / "p" / "heatmap-density-20.png"));
}

}  // namespace
}  // namespace silva::bench
