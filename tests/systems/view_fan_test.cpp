// The frames of an autopilot point form a view fan: they stream the same chunks and share one set of sun maps,
// drawn once, planned over every view of the point and equal bit for bit to the maps a fresh schedule draws.
#include <gtest/gtest.h>

#include <algorithm>
#include <bit>

#include "components/camera.hpp"
#include "components/phase.hpp"
#include "core/error.hpp"
#include "pipeline/schedule/world_schedule.hpp"
#include "render/shadow_plan.hpp"
#include "systems/aim_camera.hpp"
#include "systems/prefetch_chunks.hpp"
#include "world/chunk_cache.hpp"
#include "tests/common/test_library.hpp"
#include "world/view_fan.hpp"

namespace silva::systems {
namespace {

/// A small world with 160x90 cameras and autopilot points of three yaws.
struct FanWorld {
  Config cfg = [] {
    Config c = test::small_world_config(31, 3);
    c.output.width = 160;
    c.output.height = 90;
    c.captures.autopilot_points = 4;
    return c;
  }();
  world::WorldContext ctx = world::make_world_context(cfg, test::small_library());
  std::vector<world::PlannedFrame> frames = world::plan_autopilot(ctx);

  /// Settings that select rgb (so the sun maps are drawn).
  static CaptureSettings rgb() {
    CaptureSettings s;
    s.outputs = io::OutputSelection::from_names({"rgb"});
    return s;
  }
};

TEST(ViewFan, EveryFrameOfAnAutopilotPointGetsTheSameViewsWithItsOwnAmongThem) {
  const FanWorld w;
  ASSERT_EQ(w.frames.size(), 12u);
  for (size_t point = 0; point < 4; ++point) {
    const std::vector<Camera> fan = world::view_fan(w.frames[point * 3]);
    ASSERT_EQ(fan.size(), 3u);
    for (size_t k = 0; k < 3; ++k) {
      const world::PlannedFrame& f = w.frames[point * 3 + k];
      const std::vector<Camera> views = world::view_fan(f);
      ASSERT_EQ(views.size(), 3u);
      for (size_t j = 0; j < 3; ++j) EXPECT_EQ(views[j].camera_to_world, fan[j].camera_to_world) << point << k << j;
      EXPECT_TRUE(views[k].camera_to_world.isApprox(f.camera.camera_to_world, 1e-12)) << point << k;
    }
  }
  world::PlannedFrame alone = w.frames[0];
  alone.fan_yaws_deg.clear();
  ASSERT_EQ(world::view_fan(alone).size(), 1u);
  EXPECT_EQ(world::view_fan(alone)[0].camera_to_world, alone.camera.camera_to_world);
}

TEST(ViewFan, AFansFramesStreamTheSameChunksAndDrawTheirOwnView) {
  const FanWorld w;
  const ViewChunks first = frame_chunks(w.frames[3], w.ctx.chunk_size(), 0.0);
  for (size_t k = 0; k < 3; ++k) {
    const world::PlannedFrame& f = w.frames[3 + k];
    const ViewChunks view = frame_chunks(f, w.ctx.chunk_size(), 0.0);
    EXPECT_EQ(view.fan, first.fan) << k;
    EXPECT_EQ(view.coords, capture_chunks(f.camera, w.ctx.chunk_size(), 0.0)) << k;
    EXPECT_TRUE(std::includes(view.fan.begin(), view.fan.end(), view.coords.begin(), view.coords.end())) << k;
  }
  EXPECT_GT(first.fan.size(), first.coords.size());  // the other yaws see chunks this one does not
}

TEST(ViewFan, TheShadowPlanOfAFanCoversEachViewsOwn) {
  const FanWorld w;
  const world::PlannedFrame& f = w.frames[6];
  const std::vector<Camera> fan = world::view_fan(f);
  const Vec3d to_sun = Vec3d(0.3, -0.5, 0.8).normalized();
  const render::ShadowPlan shared = render::plan_shadow(fan, 0.0f, 6.0, to_sun);
  for (const Camera& c : fan) {
    const render::ShadowPlan own = render::plan_shadow({&c, 1}, 0.0f, 6.0, to_sun);
    EXPECT_TRUE((shared.region.min.array() <= own.region.min.array()).all());
    EXPECT_TRUE((shared.region.max.array() >= own.region.max.array()).all());
    EXPECT_GE(shared.resolution, own.resolution);
  }
  EXPECT_THROW(render::plan_shadow({}, 0.0f, 6.0, to_sun), InputError);
}

TEST(ViewFan, TheNextPointsChunksAreMadeWhileTheWholeFanRendersAndHandedOverAtItsFirstFrame) {
  const FanWorld w;
  pipeline::WorldSchedule schedule(w.ctx, 256);
  CaptureQueue& queue = schedule.ecs().resource<CaptureQueue>();
  for (size_t k = 0; k < 6; ++k) queue.cameras.push_back(schedule.ecs().spawn(world::PlannedFrame(w.frames[k])));
  const auto& prefetched = schedule.ecs().resource<PrefetchedChunks>();
  const auto& cache = schedule.ecs().resource<world::ChunkCache>();
  schedule.ecs().run_phases(Phase::Stream, Phase::Prepare);  // point 0, first yaw: its fan streamed
  const std::vector<ChunkCoord> next = cache.missing(frame_chunks(w.frames[3], w.ctx.chunk_size(), 0.0).streamed());
  ASSERT_FALSE(next.empty());
  EXPECT_EQ(prefetched.started(), next);  // point 1's, not the next yaw's (which lacks nothing)
  const size_t generated = cache.generated();
  for (int yaw = 1; yaw < 3; ++yaw) {  // the rest of the fan streams nothing and keeps the batch
    schedule.ecs().run_phases(Phase::Stream, Phase::Prepare);
    EXPECT_EQ(prefetched.started(), next) << yaw;
    EXPECT_EQ(cache.generated(), generated) << yaw;
  }
  schedule.ecs().run_phases(Phase::Stream, Phase::Prepare);  // point 1: the batch goes into the cache
  EXPECT_TRUE(cache.missing(next).empty());
  EXPECT_EQ(cache.generated(), generated + next.size());
}

TEST(ViewFan, AFansFramesShareSunMapsDrawnOnceThatEqualFreshlyDrawnOnes) {
  const FanWorld w;
  pipeline::WorldSchedule schedule(w.ctx, 256);
  std::vector<std::shared_ptr<FrameWork>> works;
  for (size_t k = 3; k < 6; ++k) works.push_back(schedule.render_view(w.frames[k], FanWorld::rgb()));
  ASSERT_NE(works[0]->sun, nullptr);
  EXPECT_EQ(works[1]->sun, works[0]->sun);
  EXPECT_EQ(works[2]->sun, works[0]->sun);
  const std::shared_ptr<FrameWork> next = schedule.render_view(w.frames[6], FanWorld::rgb());  // the next point
  EXPECT_NE(next->sun, works[0]->sun);

  for (size_t k = 3; k < 6; ++k) {  // each frame of the fan alone, on a schedule of its own
    pipeline::WorldSchedule fresh(w.ctx, 256);
    const std::shared_ptr<FrameWork> alone = fresh.render_view(w.frames[k], FanWorld::rgb());
    const SunMaps& a = *alone->sun;
    const SunMaps& b = *works[0]->sun;
    EXPECT_EQ(a.shadow.width, b.shadow.width) << k;
    EXPECT_EQ(a.shadow.height, b.shadow.height) << k;
    EXPECT_EQ(a.shadow.world_to_light, b.shadow.world_to_light) << k;
    EXPECT_TRUE(std::equal(a.shadow.depth.begin(), a.shadow.depth.end(), b.shadow.depth.begin(), b.shadow.depth.end(),
                           [](float x, float y) { return std::bit_cast<uint32_t>(x) == std::bit_cast<uint32_t>(y); }))
        << k;
    EXPECT_EQ(a.canopy.cover, b.canopy.cover) << k;
    EXPECT_EQ(a.canopy.depth, b.canopy.depth) << k;
    EXPECT_EQ(alone->gbuffer.depth, works[k - 3]->gbuffer.depth) << k;  // the camera's own scene, as alone
  }
}

TEST(SunCache, KeptMapsAreFoundByTheirKeyAndLetGoForAnotherSoTheirSetIsDrawnIntoAgain) {
  SunCache cache;
  const auto scene = std::make_shared<const FrameScene>();
  SunKey first{scene, AABB{}, 256, Vec3d::UnitZ()};
  SunKey second = first;
  second.resolution = 512;
  std::shared_ptr<SunMaps> maps = cache.take();
  const SunMaps* drawn = maps.get();
  cache.keep(first, maps);
  maps = nullptr;  // the frame that drew them is done
  EXPECT_EQ(cache.find(first).get(), drawn);
  EXPECT_EQ(cache.find(second), nullptr);
  EXPECT_EQ(cache.find(first), nullptr);     // let go by the other key's lookup
  EXPECT_EQ(cache.take().get(), drawn);      // so the next fan draws into the same set
}

TEST(SunCache, ASetAFrameStillHoldsIsNotDrawnInto) {
  SunCache cache;
  const std::shared_ptr<SunMaps> held = cache.take();
  EXPECT_NE(cache.take().get(), held.get());
}

}  // namespace
}  // namespace silva::systems
