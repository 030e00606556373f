#include "systems/render_views.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <utility>
#include <vector>

#include <tbb/parallel_invoke.h>
#include <tbb/task_arena.h>

#include "components/camera.hpp"
#include "components/phase.hpp"
#include "components/sensor.hpp"
#include "components/world_source.hpp"
#include "core/stopwatch.hpp"
#include "render/canopy_map.hpp"
#include "render/shadow_plan.hpp"
#include "systems/prepare_scene.hpp"
#include "world/stereo_rig.hpp"
#include "world/terrain.hpp"
#include "world/view_fan.hpp"
#include "world/world_context.hpp"

namespace silva::systems {

bool SunKey::operator==(const SunKey& o) const {
  return scene == o.scene && region.min == o.region.min && region.max == o.region.max && resolution == o.resolution &&
         to_sun == o.to_sun;
}

std::shared_ptr<const SunMaps> SunCache::find(const SunKey& key) {
  if (key_ && *key_ == key) return last_;
  key_.reset();
  last_ = nullptr;
  return nullptr;
}

std::shared_ptr<SunMaps> SunCache::take() {
  for (const std::shared_ptr<SunMaps>& maps : pool_) {
    if (maps.use_count() != 1) continue;
    // The last holder dropped its reference with a release; this fence orders its reads before our writes.
    std::atomic_thread_fence(std::memory_order_acquire);
    return maps;
  }
  return pool_.emplace_back(std::make_shared<SunMaps>());
}

void SunCache::keep(SunKey key, std::shared_ptr<const SunMaps> maps) {
  key_ = std::move(key);
  last_ = std::move(maps);
}

std::shared_ptr<FrameWork> FrameSlots::take() {
  std::shared_ptr<FrameWork> w = slots_.take();
  w->shade_scratches = shade_scratches_;
  return w;
}

namespace {

/// Renders `camera`'s G-buffer into `work` and counts the pass.
void render_camera(const render::Scene& scene, const Camera& camera, const render::RenderOptions& options,
                   render::Renderer& renderer, FrameWork& work) {
  const Stopwatch clock;
  render::RenderStats stats;
  renderer.render_gbuffer(scene, camera, options, work.gbuffer, &stats);
  work.render_s = clock.seconds();
  work.triangles_submitted = stats.triangles_submitted;
  work.triangles_rasterised = stats.triangles_rasterised;
}

/// Renders the stereo pair's right camera of `work` into work.right (its lighting is work's).
void render_right(const render::Scene& scene, const render::RenderOptions& options, double baseline_m,
                  render::Renderer& renderer, FrameWork& work) {
  if (!work.right) work.right = std::make_unique<FrameWork>();
  FrameWork& right = *work.right;
  right.shade_scratches = work.shade_scratches;
  right.frame = world::stereo_right(work.frame, baseline_m);
  right.lighting = work.lighting;
  right.files.clear();
  render_camera(scene, right.frame.camera, options, renderer, right);
}

/// Draws `region` straight down (objects of canopy size only, kCanopyTexel texels) into `overhead` and
/// makes maps.canopy from it.
void map_canopy(const render::Scene& scene, const world::WorldContext& ctx, const AABB& region,
                render::RenderOptions options, render::Renderer& renderer, render::ShadowMap& overhead, SunMaps& maps) {
  const Vec3f extent = region.max - region.min;
  const int resolution =
      std::clamp(int(std::ceil(double(std::max(extent.x(), extent.y())) / render::kCanopyTexel)), 16, 1024);
  options.min_radius = render::kCanopyMinRadius;
  renderer.render_shadow_map(scene, Vec3d::UnitZ(), region, resolution, options, overhead);
  maps.canopy = render::build_canopy_map(
      overhead, [&](double x, double y) { return double(world::terrain_height(ctx.terrain, x, y)); });
}

/// Gives `work` the sun maps of its view fan (its left camera alone without one): the cached ones when the
/// fan's first frame drew them, else drawn now from scene.sun_scene().
void render_sun(const PreparedScene& scene, const world::WorldContext& ctx, const render::RenderOptions& options,
                render::Renderer& renderer, SunCache& cache, FrameWork& work) {
  const Stopwatch clock;
  const Vec3d sun = render::sun_direction(work.lighting.preset).cast<double>();
  const Vec3d p = work.frame.camera.position();
  const float ground_z = world::terrain_height(ctx.terrain, p.x(), p.y());
  const std::vector<Camera> views = world::view_fan(work.frame);
  const render::ShadowPlan plan = render::plan_shadow(views, ground_z, ctx.config.terrain.max_elevation, sun);
  const SunKey key{scene.fan, plan.region, plan.resolution, sun};
  work.sun = cache.find(key);  // null without a fan: keys are kept only with one
  if (!work.sun) {
    const std::shared_ptr<SunMaps> maps = cache.take();
    renderer.render_shadow_map(scene.sun_scene(), sun, plan.region, plan.resolution, options, maps->shadow);
    map_canopy(scene.sun_scene(), ctx, render::canopy_region(plan.region), options, renderer, cache.canopy_source(),
               *maps);
    if (scene.fan) cache.keep(key, maps);
    work.sun = maps;
  }
  work.shadow_s = clock.seconds();
}
}  // namespace

void render_frame(const PreparedScene& scene, const world::WorldContext& ctx, const CaptureSettings& settings,
                  std::span<const CameraSensor> cameras, FrameSlots& slots, FrameWork& work) {
  work.lighting = render::frame_lighting(settings.lighting, uint64_t(ctx.config.seed), work.frame.sequence,
                                         uint64_t(work.frame.frame));
  render::RenderOptions options;
  options.lod = ctx.config.render.lod;
  const auto draw_cameras = [&] {
    for (const CameraSensor& sensor : cameras) {
      if (sensor.right)
        render_right(scene.frame.scene, options, sensor.baseline_m, *slots.renderer, work);
      else
        render_camera(scene.frame.scene, work.frame.camera, options, *slots.renderer, work);
    }
  };
  if (!settings.outputs.has(io::OutputType::Rgb)) {
    draw_cameras();
    work.sun = nullptr;
    work.shadow_s = 0;
  } else if (tbb::this_task_arena::max_concurrency() < kThreadsForSunBeside) {
    draw_cameras();
    render_sun(scene, ctx, options, *slots.renderer, slots.sun_maps, work);
  } else {
    if (!slots.sun_renderer) slots.sun_renderer = std::make_unique<render::Renderer>();
    tbb::parallel_invoke(draw_cameras, [&] { render_sun(scene, ctx, options, *slots.sun_renderer, slots.sun_maps, work); });
  }
}

void install_render_views(ecs::World& world, CaptureSettings settings) {
  world.set_resource(std::move(settings));
  world.set_resource(FrameSlots{});
  world.system("render_views")
      .phase(Phase::Render)
      .reads_resource<WorldSource, CaptureQueue, CaptureSettings, PreparedScene>()
      .writes_resource<FrameSlots>()
      .reads<world::PlannedFrame, CameraSensor>()
      .run([](ecs::SystemContext& sys) {
        FrameSlots& slots = sys.resource<FrameSlots>();
        const ecs::Entity camera = sys.resource<const CaptureQueue>().active;
        slots.current = nullptr;
        if (camera.is_null()) return;
        std::vector<CameraSensor> cameras;  // the left camera first: the right one's shadow and exposure are its
        sys.each<const CameraSensor>([&](const CameraSensor& c) { cameras.push_back(c); });
        std::stable_sort(cameras.begin(), cameras.end(),
                         [](const CameraSensor& a, const CameraSensor& b) { return !a.right && b.right; });
        std::shared_ptr<FrameWork> work = slots.take();
        work->frame = sys.get<const world::PlannedFrame>(camera);
        work->files.clear();
        render_frame(sys.resource<const PreparedScene>(), *sys.resource<const WorldSource>().ctx,
                     sys.resource<const CaptureSettings>(), cameras, slots, *work);
        slots.current = std::move(work);
      });
}

}  // namespace silva::systems
