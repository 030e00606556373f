#include "render/renderer.hpp"

#include <string>
#include <vector>

#include "core/error.hpp"
#include "render/geometry_pass.hpp"
#include "render/instance_cull.hpp"
#include "render/raster_conventions.hpp"
#include "render/resolve.hpp"
#include "render/shadow_pass.hpp"

namespace silva::render {

namespace {

/// Throws InputError unless the view size and tile size are ones the rasteriser supports.
void check_pass(const ViewProjection& view, const RenderOptions& options) {
  if (view.width < 1 || view.height < 1 || view.width > kMaxRasterSize || view.height > kMaxRasterSize)
    throw InputError("render: image size " + std::to_string(view.width) + "x" + std::to_string(view.height) +
                     " is outside 1.." + std::to_string(kMaxRasterSize) + " per side");
  if (options.tile_size < 8 || options.tile_size > 256 || options.tile_size % 8 != 0)
    throw InputError("render: tile_size " + std::to_string(options.tile_size) +
                     " must be a multiple of 8 in 8..256");
  if (view.perspective && !(view.near > 0.0 && view.far > view.near))
    throw InputError("render: camera near/far must satisfy 0 < near < far");
}

/// The per-view results of a pass kind (camera or shadow).
struct PassState {
  VisibilityBuffer vis;            ///< Winners per pixel.
  InstanceSelection instances;     ///< LOD per instance (kCulled when not drawn), draw order.
};

}  // namespace

struct Renderer::Impl {
  std::vector<BoundingSphere> spheres;         ///< Per mesh, this pass.
  std::vector<DrawItem> items;                 ///< Geometry tasks, this pass.
  MaskCache masks;                        ///< Opacity bits and leaf mips of the scene's alpha masks.
  GeometryStoreSet stores;                     ///< Set-up triangles and bins, per chunk of items.
  VertexCacheSet vertex_caches;                ///< Thread-local transformed vertices of an item.
  TileScratchSet tile_scratch;                 ///< Thread-local tile planes.
  std::vector<const GeometryStore*> store_list;  ///< Stores of this pass.
  PassState camera;                            ///< Camera pass results.
  PassState shadow;                            ///< Shadow pass results.

  /// Runs culling, LOD selection, geometry and tile passes of one view into `state`; `shadow`
  /// marks the sun's shadow map (back faces kept, shadow casters drawn).
  void run_pass(const Scene& scene, const ViewProjection& view, const RenderOptions& options, bool shadow,
                PassState& state, RenderStats* stats) {
    check_pass(view, options);
    const bool cull_back = !shadow && options.backface_cull;
    mesh_spheres(scene, spheres, shadow);
    select_instances(scene, view, spheres, options.lod, state.instances, shadow, options.min_radius);
    const uint64_t submitted = build_draw_items(scene, state.instances, items);
    const TileGrid grid = TileGrid::make(view.width, view.height, options.tile_size);
    const SetupView setup(view);
    masks.update(scene);
    run_geometry_pass(scene, setup, items, cull_back, masks, grid, stores, vertex_caches);
    store_list.clear();
    for (const GeometryStore& s : stores) store_list.push_back(&s);
    state.vis.resize(view.width, view.height);
    const TileCounters tc = rasterise_tiles(grid, view.depth_clear(), store_list, tile_scratch, state.vis);
    if (!stats) return;
    *stats = RenderStats{};
    stats->instances_submitted = scene.instances.size();
    for (uint32_t l : state.instances.lod) stats->instances_culled += l == kCulled ? 1 : 0;
    stats->triangles_submitted = submitted;
    for (const GeometryStore* s : store_list) {
      stats->triangles_after_cull += s->counters.after_cull;
      stats->triangles_clipped += s->counters.clipped;
      stats->triangles_rasterised += s->counters.emitted;
      stats->tile_bin_entries += s->bin_entries;
    }
    stats->fragments_covered = tc.fragments;
    stats->pixels_shaded_or_written = tc.writes;
    stats->pixels_covered = tc.covered;
  }
};

Renderer::Renderer() : impl_(std::make_unique<Impl>()) {}

Renderer::~Renderer() = default;

const VisibilityBuffer& Renderer::render_visibility(const Scene& scene, const Camera& camera,
                                                    const RenderOptions& options, RenderStats* stats) {
  impl_->run_pass(scene, ViewProjection::from_camera(camera), options, false, impl_->camera, stats);
  return impl_->camera.vis;
}

void Renderer::render_gbuffer(const Scene& scene, const Camera& camera, const RenderOptions& options, GBuffer& out,
                              RenderStats* stats) {
  const VisibilityBuffer& vis = render_visibility(scene, camera, options, stats);
  resolve_gbuffer(scene, camera, vis, impl_->camera.instances.lod, impl_->masks, out);
}

std::span<const uint32_t> Renderer::instance_lods() const { return impl_->camera.instances.lod; }

void Renderer::render_shadow_map(const Scene& scene, const Vec3d& direction_to_sun, const AABB& region, int resolution,
                                 const RenderOptions& options, ShadowMap& out, RenderStats* stats) {
  ShadowMap frame = shadow_map_frame(direction_to_sun, region, resolution);
  frame.depth.swap(out.depth);
  out = std::move(frame);
  impl_->run_pass(scene, shadow_view(out), options, true, impl_->shadow, stats);
  shadow_depth_from_visibility(impl_->shadow.vis, out);
}

ShadowMap Renderer::render_shadow_map(const Scene& scene, const Vec3d& direction_to_sun, const AABB& region,
                                      int resolution, const RenderOptions& options, RenderStats* stats) {
  ShadowMap out;
  render_shadow_map(scene, direction_to_sun, region, resolution, options, out, stats);
  return out;
}

ShadowMap render_shadow_map(const Scene& scene, const Vec3d& direction_to_sun, const AABB& region, int resolution,
                            const RenderOptions& options) {
  Renderer renderer;
  return renderer.render_shadow_map(scene, direction_to_sun, region, resolution, options);
}

}  // namespace silva::render
