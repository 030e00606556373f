/// @file Construction of the default-world view of the peers bench (see default_view.hpp).
#include "bench/default_view.hpp"

#include <map>
#include <utility>

#include "assets/factory.hpp"
#include "render/instance_cull.hpp"
#include "render/renderer.hpp"
#include "world/chunk_cache.hpp"
#include "world/chunk_regions.hpp"
#include "world/plan_captures.hpp"

namespace silva::bench {

namespace {

/// Seed of the default view's world (the demo's seed).
constexpr int64_t kSeed = 1234567890;

/// The instances `lods` draws of `full`, each pointing at a single-LOD copy of its mesh entry (one
/// entry per distinct (mesh, LOD) pair).
FrozenView freeze_lods(const render::Scene& full, std::span<const uint32_t> lods) {
  FrozenView frozen;
  render::Scene& out = frozen.scene;
  std::map<std::pair<uint32_t, uint32_t>, uint32_t> mesh_of;
  for (uint32_t i = 0; i < full.instances.size(); ++i) {
    if (lods[i] == render::kCulled) continue;
    render::Instance inst = full.instances[i];
    const auto key = std::make_pair(inst.mesh, lods[i]);
    auto it = mesh_of.find(key);
    if (it == mesh_of.end()) {
      render::MeshLods single;
      single.lods = {full.meshes[inst.mesh].lods[lods[i]]};
      single.compute_bounds();
      out.meshes.push_back(std::move(single));
      it = mesh_of.emplace(key, uint32_t(out.meshes.size() - 1)).first;
    }
    inst.mesh = it->second;
    out.instances.push_back(inst);
    frozen.from.push_back(i);
  }
  return frozen;
}

}  // namespace

DefaultView::DefaultView() : library(std::make_unique<assets::AssetLibrary>(assets::generate_library())) {
  Config cfg;
  cfg.seed = kSeed;
  const world::WorldContext ctx = world::make_world_context(cfg, *library);
  const std::vector<world::PlannedFrame> poses = world::plan_autopilot(ctx);
  // The middle trail point, looking along the trail (yaw offset 0 is the middle of the default yaws).
  const size_t yaws = cfg.captures.autopilot_yaws.size();
  camera = poses[(poses.size() / yaws / 2) * yaws + yaws / 2].camera;
  world::ChunkCache cache(256);
  frame = systems::SceneBuilder(*library).build(cache.require(ctx, world::chunks_in_view(camera, ctx.chunk_size())),
                                                camera.position(), cfg.render.ground_cover_distance);
  render::Renderer renderer;
  renderer.render_visibility(frame.scene, camera, render::RenderOptions{});
  drawn = freeze_lods(frame.scene, renderer.instance_lods());
  render::RenderOptions no_lod;
  no_lod.lod = false;
  renderer.render_visibility(frame.scene, camera, no_lod);
  full_detail = freeze_lods(frame.scene, renderer.instance_lods());
}

size_t FrozenView::triangle_count() const {
  size_t n = 0;
  for (const render::Instance& inst : scene.instances) n += scene.meshes[inst.mesh].lods[0]->indices.size() / 3;
  return n;
}

const DefaultView& default_view() {
  static const DefaultView v;
  return v;
}

}  // namespace silva::bench
