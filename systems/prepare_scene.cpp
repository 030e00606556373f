#include "systems/prepare_scene.hpp"

#include <cstring>

#include <tbb/parallel_for.h>

#include "components/camera.hpp"
#include "components/phase.hpp"
#include "components/chunk.hpp"
#include "components/world_source.hpp"
#include "core/rng.hpp"
#include "world/chunk_cache.hpp"
#include "world/collision_proxy.hpp"
#include "world/plan_captures.hpp"
#include "world/terrain_lod.hpp"

namespace silva::systems {

SceneBuilder::SceneBuilder(const assets::AssetLibrary& library)
    : library_(&library), asset_meshes_(std::make_shared<std::vector<render::MeshLods>>(library.assets.size())) {
  for (const assets::Asset& a : library.assets)
    ground_cover_.push_back(a.kind == AssetKind::Grass || a.kind == AssetKind::Fern || a.kind == AssetKind::GroundCover);
}

void SceneBuilder::make_drawable(const std::vector<render::Instance>& instances, size_t first) const {
  std::vector<uint32_t> missing;
  std::vector<bool> seen(asset_meshes_->size(), false);
  for (size_t i = first; i < instances.size(); ++i) {
    const uint32_t asset = instances[i].mesh;
    if (asset < seen.size() && !seen[asset] && (*asset_meshes_)[asset].lods.empty()) {
      seen[asset] = true;
      missing.push_back(asset);
    }
  }
  // Each variant's meshes are a pure function of its source, so making them in parallel is safe.
  tbb::parallel_for(size_t(0), missing.size(), [&](size_t k) {
    const assets::Asset& a = library_->assets[missing[k]];
    render::MeshLods lods;
    for (const Mesh& m : a.lods()) lods.lods.push_back(&m);
    if (const Mesh& caster = a.geometry->shadow_caster(); &caster != &a.lods()[0]) lods.shadow_caster = &caster;
    lods.lod_screen_sizes = a.lod_screen_sizes;
    lods.lod_screen_sizes.resize(lods.lods.size() - 1);
    lods.compute_bounds();
    (*asset_meshes_)[missing[k]] = std::move(lods);
  });
}

uint32_t variation_seed(const Vec3f& position) {
  uint32_t bits[3];
  std::memcpy(bits, position.data(), sizeof bits);
  return uint32_t(hash_combine(hash_combine(bits[0], bits[1]), bits[2]));
}

double ground_cover_cutoff(uint32_t variation, double ground_cover_distance) {
  return ground_cover_distance * (0.75 + 0.25 * double(variation) / 4294967296.0);
}

FrameScene SceneBuilder::build(std::vector<std::shared_ptr<const ChunkContent>> chunks, const Vec3d& eye,
                               double ground_cover_distance) const {
  FrameScene out;
  render::Scene& scene = out.scene;
  scene.meshes.resize(asset_meshes_->size());  // filled below, once the drawn assets are known
  size_t objects = 0;
  for (const auto& c : chunks) objects += c->objects.size();
  scene.instances.reserve(objects + 2 * chunks.size());
  // `bounds`: cached with the chunk, or empty for the renderer to compute each pass.
  auto add_world_mesh = [&](const Mesh& mesh, const Mesh* coarse, const AABB& bounds) {
    if (mesh.indices.empty()) return;
    render::MeshLods lods;
    lods.lods.push_back(&mesh);
    if (coarse && !coarse->indices.empty()) {
      lods.lods.push_back(coarse);
      lods.lod_screen_sizes.push_back(world::kTerrainLodScreenSize);
    }
    lods.bounds = bounds;
    scene.meshes.push_back(std::move(lods));
    render::Instance inst;
    inst.mesh = uint32_t(scene.meshes.size() - 1);
    scene.instances.push_back(inst);
  };
  std::vector<render::Instance> objects_drawn;
  objects_drawn.reserve(objects);
  for (const auto& c : chunks) {
    add_world_mesh(c->terrain, &c->terrain_lod, c->terrain_bounds);
    for (const Vegetation& v : c->objects) {
      const render::Instance inst = object_instance(v);
      if (ground_cover_[v.asset] != 0 &&
          (v.position.cast<double>() - eye).norm() > ground_cover_cutoff(inst.variation, ground_cover_distance))
        continue;
      objects_drawn.push_back(inst);
    }
  }
  make_drawable(objects_drawn, 0);
  std::copy(asset_meshes_->begin(), asset_meshes_->end(), scene.meshes.begin());
  scene.instances.insert(scene.instances.end(), objects_drawn.begin(), objects_drawn.end());
  out.chunks = std::move(chunks);
  return out;
}

render::Instance SceneBuilder::object_instance(const Vegetation& v) {
  render::Instance inst;
  inst.variation = variation_seed(v.position);
  inst.object_to_world = world::object_to_world(v.position, v.yaw, v.scale);
  inst.mesh = v.asset;
  inst.instance_id = v.instance_id;
  return inst;
}

ChunkRays SceneBuilder::ray_instances(const ChunkContent& chunk, double ground_cover_distance) const {
  std::vector<render::Instance> objects;
  objects.reserve(chunk.objects.size());
  for (const Vegetation& v : chunk.objects) objects.push_back(object_instance(v));
  make_drawable(objects, 0);
  ChunkRays out;
  out.solid.push_back({&chunk.terrain, Affine3f::Identity(), 0});
  for (size_t k = 0; k < objects.size(); ++k) {
    const render::Instance& inst = objects[k];
    raycast::RayInstance r{(*asset_meshes_)[inst.mesh].lods[0], inst.object_to_world, inst.instance_id};
    if (ground_cover_[inst.mesh] == 0) {
      out.solid.push_back(r);
      continue;
    }
    r.cutoff = ground_cover_cutoff(inst.variation, ground_cover_distance);
    r.anchor = chunk.objects[k].position;
    out.ground_cover.push_back(r);
  }
  return out;
}

namespace {
/// The contents of view.coords among `streamed` (the contents of view.streamed(), in its order; both sorted).
std::vector<std::shared_ptr<const ChunkContent>> view_contents(const ViewChunks& view,
                                                               const std::vector<std::shared_ptr<const ChunkContent>>& streamed) {
  if (view.fan.empty()) return streamed;
  std::vector<std::shared_ptr<const ChunkContent>> out;
  out.reserve(view.coords.size());
  size_t k = 0;
  for (size_t i = 0; i < view.fan.size() && k < view.coords.size(); ++i)
    if (view.fan[i] == view.coords[k]) out.push_back(streamed[i]), ++k;
  return out;
}
}  // namespace

void install_prepare_scene(ecs::World& world, const assets::AssetLibrary& library) {
  world.set_resource(PreparedScene{});
  world.system("prepare_scene")
      .phase(Phase::Prepare)
      .reads_resource<WorldSource, CaptureQueue, ViewChunks>()
      .writes_resource<world::ChunkCache, PreparedScene>()
      .reads<world::PlannedFrame>()
      .run([builder = SceneBuilder(library)](ecs::SystemContext& sys) {
        const ecs::Entity camera = sys.resource<const CaptureQueue>().active;
        if (camera.is_null()) return;
        const ViewChunks& view = sys.resource<const ViewChunks>();
        const Vec3d eye = sys.get<const world::PlannedFrame>(camera).camera.position();
        const double distance = sys.resource<const WorldSource>().ctx->config.render.ground_cover_distance;
        PreparedScene& prepared = sys.resource<PreparedScene>();
        const auto streamed = sys.resource<world::ChunkCache>().take(view.streamed());
        prepared.frame = builder.build(view_contents(view, streamed), eye, distance);
        if (view.fan.empty()) {
          prepared.fan = nullptr;
          prepared.fan_coords.clear();
        } else if (!prepared.fan || prepared.fan_coords != view.fan || prepared.fan_eye != eye) {
          prepared.fan = std::make_shared<const FrameScene>(builder.build(streamed, eye, distance));
          prepared.fan_coords = view.fan;
          prepared.fan_eye = eye;
        }
      });
}

}  // namespace silva::systems
