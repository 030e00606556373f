// Rasteriser benchmark: visibility pass and visibility + resolve at 1920x1080, 1 and 2 threads, on
// the views of bench/bench_views.hpp (argument `view`): 0 = the synthetic stress forest of
// bench/forest_scene.hpp (128 m x 128 m terrain at 0.5 m, 300 instanced trees of ~2-4k triangles
// with alpha-tested leaf cards, LODs off), 1 = the default world's middle autopilot view (LODs on).
// Fixed seeds; work counts beside times. BM_OcclusionBound measures what occlusion culling could save at
// most: the share of drawn triangles in clusters hidden behind the view's own final depth.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include <tbb/task_arena.h>

#include "bench/bench_views.hpp"
#include "core/stopwatch.hpp"
#include "render/geometry_pass.hpp"
#include "render/instance_cull.hpp"
#include "render/raster_conventions.hpp"
#include "render/renderer.hpp"

namespace {

using namespace silva;
using namespace silva::render;

/// Adds the work counters of a frame and the rates derived from them.
void report(benchmark::State& state, const RenderStats& s, double pixels, double cold_ms) {
  state.counters["tri_submitted"] = double(s.triangles_submitted);
  state.counters["tri_after_cull"] = double(s.triangles_after_cull);
  state.counters["tri_rasterised"] = double(s.triangles_rasterised);
  state.counters["px_written"] = double(s.pixels_shaded_or_written);
  state.counters["px_covered"] = double(s.pixels_covered);
  state.counters["cold_ms"] = cold_ms;
  state.counters["ms_per_frame"] = benchmark::Counter(1e-3, benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
  state.counters["Mtri_per_s"] = benchmark::Counter(double(s.triangles_submitted) * 1e-6, benchmark::Counter::kIsIterationInvariantRate);
  state.counters["Mpix_per_s"] = benchmark::Counter(pixels * 1e-6, benchmark::Counter::kIsIterationInvariantRate);
}

/// Number of distinct (instance, triangle) pairs that own at least one pixel of `vis`: how much
/// of the rasterised geometry ends up visible.
double visible_triangles(const VisibilityBuffer& vis) {
  std::vector<uint64_t> keys;
  keys.reserve(vis.size());
  for (size_t i = 0; i < vis.size(); ++i)
    if (vis.instance[i] != kNoInstance) keys.push_back(uint64_t(vis.instance[i]) << 32 | vis.triangle[i]);
  std::sort(keys.begin(), keys.end());
  return double(std::unique(keys.begin(), keys.end()) - keys.begin());
}

/// One frame of view state.range(0) per iteration in an arena of state.range(1) threads; resolve
/// when `gbuffer`.
void run(benchmark::State& state, bool gbuffer) {
  const bench::BenchView v = bench::bench_view(state.range(0));
  const Scene& scene = *v.silva_scene;
  const Camera& camera = *v.peers.camera;
  tbb::task_arena arena(int(state.range(1)));
  Renderer renderer;
  GBuffer g;
  RenderStats stats;
  const RenderOptions opt = v.options();
  const auto frame = [&] {
    arena.execute([&] {
      if (gbuffer) {
        renderer.render_gbuffer(scene, camera, opt, g, &stats);
      } else {
        renderer.render_visibility(scene, camera, opt, &stats);
      }
    });
  };
  const Stopwatch clock;
  frame();  // cold: first frame grows every buffer
  const double cold_ms = 1000 * clock.seconds();
  for (auto _ : state) frame();
  report(state, stats, double(camera.width) * double(camera.height), cold_ms);
  if (!gbuffer) state.counters["tri_visible"] = visible_triangles(renderer.render_visibility(scene, camera, opt));
}

void BM_RasterVisibility(benchmark::State& state) { run(state, false); }
void BM_RasterVisibilityResolve(benchmark::State& state) { run(state, true); }

/// Runs of at most `size` consecutive triangles of every draw item: the clusters a culler would test.
std::vector<DrawItem> clusters(const std::vector<DrawItem>& items, uint32_t size) {
  std::vector<DrawItem> out;
  for (const DrawItem& item : items)
    for (uint32_t first = 0; first < item.triangle_count; first += size) {
      DrawItem c = item;
      c.first_triangle = item.first_triangle + first;
      c.triangle_count = std::min(size, item.triangle_count - first);
      out.push_back(c);
    }
  return out;
}

/// True when cluster `c`'s world bounds lie wholly in front of the near plane and strictly behind the
/// farthest stored depth over every pixel its projected bounds touch (so none of it can be visible).
bool hidden(const Scene& scene, const ViewProjection& view, const VisibilityBuffer& vis, const DrawItem& c) {
  const Mesh& mesh = scene.meshes[scene.instances[c.instance].mesh].level(c.lod);
  AABB box;
  for (size_t k = size_t(c.first_triangle) * 3; k < size_t(c.first_triangle + c.triangle_count) * 3; ++k)
    box.extend(mesh.positions[mesh.indices[k]]);
  const Affine3f& m = scene.instances[c.instance].object_to_world;
  double u0 = HUGE_VAL, v0 = HUGE_VAL, u1 = -HUGE_VAL, v1 = -HUGE_VAL, nearest = -HUGE_VAL;
  for (int k = 0; k < 8; ++k) {
    const Vec3f corner((k & 1) ? box.max.x() : box.min.x(), (k & 2) ? box.max.y() : box.min.y(),
                       (k & 4) ? box.max.z() : box.min.z());
    const Vec3f w = m.leftCols<3>() * corner + m.col(3);
    const Vec3d q = (view.world_to_view * Vec4d(w.x(), w.y(), w.z(), 1.0)).head<3>();
    if (q.z() < view.near) return false;
    const Vec2d s = view.project(q);
    u0 = std::min(u0, s.x()), u1 = std::max(u1, s.x()), v0 = std::min(v0, s.y()), v1 = std::max(v1, s.y());
    nearest = std::max(nearest, view.depth_value(q));
  }
  const int x0 = std::max(0, int(std::floor(u0))), x1 = std::min(vis.width - 1, int(std::ceil(u1)));
  const int y0 = std::max(0, int(std::floor(v0))), y1 = std::min(vis.height - 1, int(std::ceil(v1)));
  float farthest = HUGE_VALF;
  for (int y = y0; y <= y1; ++y)
    for (int x = x0; x <= x1; ++x) {
      const size_t i = size_t(y) * size_t(vis.width) + size_t(x);
      farthest = std::min(farthest, vis.instance[i] == kNoInstance ? 0.0f : vis.depth[i]);
    }
  return nearest < double(farthest) * (1.0 - 1e-6);  // float depths: a margin over their rounding
}

/// Upper bound of occlusion culling on view state.range(0) with clusters of state.range(1) triangles:
/// the share of the drawn triangles whose cluster lies behind the final depth buffer (a perfect
/// hierarchical depth; one built from solid occluders alone hides less).
void BM_OcclusionBound(benchmark::State& state) {
  const bench::BenchView v = bench::bench_view(state.range(0));
  const Scene& scene = *v.silva_scene;
  const RenderOptions opt = v.options();
  Renderer renderer;
  const VisibilityBuffer& vis = renderer.render_visibility(scene, *v.peers.camera, opt);
  const ViewProjection view = ViewProjection::from_camera(*v.peers.camera);
  std::vector<BoundingSphere> spheres;
  mesh_spheres(scene, spheres);
  InstanceSelection selection;
  select_instances(scene, view, spheres, opt.lod, selection);
  std::vector<DrawItem> items;
  build_draw_items(scene, selection, items);
  double drawn = 0, culled = 0;
  for (auto _ : state) {
    drawn = culled = 0;
    for (const DrawItem& c : clusters(items, uint32_t(state.range(1)))) {
      drawn += c.triangle_count;
      culled += hidden(scene, view, vis, c) ? c.triangle_count : 0;
    }
  }
  state.counters["tri_drawn"] = drawn;
  state.counters["hidden_share"] = culled / drawn;
}

}  // namespace

BENCHMARK(BM_OcclusionBound)->ArgsProduct({{0, 1, 2}, {32, 128, 1024}})->Iterations(1)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_RasterVisibility)->Apply(bench::views_and_threads);
BENCHMARK(BM_RasterVisibilityResolve)->Apply(bench::views_and_threads);
