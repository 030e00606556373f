// LiDAR benchmarks: one os1_64 sweep (64 beams x 2048 columns = 131 k rays) through the ray-cast
// scene of the default forest around the middle autopilot pose, and the scene update per streamed
// chunk, on 1 and 2 threads. The scene (every chunk within the preset's range, full-detail meshes)
// is built once outside the timed region; its build time is reported as setup_ms. The environment
// variable SILVA_BENCH_EMBREE passes Embree a device configuration: SILVA_BENCH_EMBREE=isa=avx2 runs
// the sweep on Embree's AVX2 kernels (the sweep's own code has no ISA dispatch), as on an AVX2-only CPU.
#include <benchmark/benchmark.h>

#include <cstdlib>

#include <tbb/task_arena.h>

#include "pipeline/config/data_path.hpp"
#include "pipeline/config/lidar_config.hpp"
#include "assets/factory.hpp"
#include "core/stopwatch.hpp"
#include "systems/cast_lidar.hpp"
#include "world/chunk_cache.hpp"
#include "world/chunk_regions.hpp"
#include "world/plan_captures.hpp"

namespace {

using namespace silva;

/// The default forest around the middle autopilot pose, as the LiDAR system sees it.
struct LidarWorld {
  std::unique_ptr<assets::AssetLibrary> library = std::make_unique<assets::AssetLibrary>(assets::generate_library());
  Config cfg;
  raycast::LidarPreset preset;
  Camera camera;
  std::vector<std::shared_ptr<const ChunkContent>> chunks;
  systems::SceneBuilder builder{*library};
  systems::ChunkRayScene rays;
  double setup_ms = 0;
  std::string embree_config;  ///< SILVA_BENCH_EMBREE, if set.
  LidarWorld() {
    if (const char* c = std::getenv("SILVA_BENCH_EMBREE")) embree_config = c;
    rays.scene = std::make_unique<raycast::RayScene>(embree_config);
    cfg.seed = 1234567890;
    const toml::table file = toml::parse_file(pipeline::data_path("configs/lidar.toml").string());
    preset = pipeline::parse_lidar_presets(*file["lidar"]["presets"].as_table(), "lidar.toml").at("os1_64");
    const world::WorldContext ctx = world::make_world_context(cfg, *library);
    const std::vector<world::PlannedFrame> poses = world::plan_autopilot(ctx);
    const size_t yaws = cfg.captures.autopilot_yaws.size();
    camera = poses[(poses.size() / yaws / 2) * yaws + yaws / 2].camera;
    world::ChunkCache cache(1024);
    const Vec3d p = camera.position();
    chunks = cache.require(ctx, world::chunks_in_disc(p.x(), p.y(), preset.max_range, ctx.chunk_size()));
    const Stopwatch clock;
    rays.sync(chunks, builder, cfg.render.ground_cover_distance, camera.position());
    setup_ms = 1000 * clock.seconds();
  }
  /// The sweep pose of the camera with the default mount.
  raycast::SweepPose pose() const {
    const Mat4d sensor = camera.camera_to_world * systems::lidar_to_camera(cfg.lidar);
    raycast::SweepPose p;
    p.sensor_to_world = sensor.block<3, 3>(0, 0);
    p.position = sensor.block<3, 1>(0, 3);
    p.seed = uint64_t(cfg.seed);
    return p;
  }
};

LidarWorld& lidar_world() {
  static LidarWorld w;
  return w;
}

void BM_LidarSweep(benchmark::State& state) {
  LidarWorld& w = lidar_world();
  tbb::task_arena arena(int(state.range(0)));
  raycast::CastOptions options;
  options.eye = w.camera.position();
  size_t returns = 0;
  for (auto _ : state)
    arena.execute([&] { returns = raycast::cast_sweep(*w.rays.scene, w.preset, w.pose(), options).size(); });
  state.counters["rays"] = double(w.preset.elevations_deg.size() * size_t(w.preset.columns));
  state.counters["returns"] = double(returns);
  state.counters["instances"] = double(w.rays.scene->instance_count());
  state.counters["chunks"] = double(w.chunks.size());
  state.counters["setup_ms"] = w.setup_ms;
  state.counters["threads"] = double(state.range(0));
  if (!w.embree_config.empty()) state.SetLabel("embree " + w.embree_config);
}
BENCHMARK(BM_LidarSweep)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();

/// One chunk leaves the scene and streams back in (its mesh BVHs stay cached): the instance
/// records, the detach/attach and the top-level rebuild that every streamed chunk costs.
void BM_LidarChunkUpdate(benchmark::State& state) {
  LidarWorld& w = lidar_world();
  tbb::task_arena arena(int(state.range(0)));
  std::vector<std::shared_ptr<const ChunkContent>> without(w.chunks.begin() + 1, w.chunks.end());
  for (auto _ : state)
    arena.execute([&] {
      w.rays.sync(without, w.builder, w.cfg.render.ground_cover_distance, w.camera.position());
      w.rays.sync(w.chunks, w.builder, w.cfg.render.ground_cover_distance, w.camera.position());
    });
  state.counters["chunk_instances"] = double(w.chunks[0]->objects.size() + 1);
  state.counters["updates_per_iteration"] = 2;
  state.counters["threads"] = double(state.range(0));
}
BENCHMARK(BM_LidarChunkUpdate)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
