#include "systems/world_systems.hpp"

#include <chrono>
#include <map>
#include <utility>

#include "components/camera.hpp"
#include "components/chunk.hpp"
#include "systems/placement.hpp"
#include "systems/stream_plan.hpp"
#include "systems/world_generator.hpp"

namespace silva::world {

namespace {

/// Chunk systems do heavy work per entity: one chunk of iteration per entity.
constexpr size_t kPerChunk = 1;

/// Seconds elapsed since t0.
double since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

/// Stream: make every chunk the cameras (and the pinned list) need a full entity, keep halos
/// around them, and despawn what is out of range together with its vegetation entities.
void stream(ecs::SystemContext& sys) {
  const WorldContext& ctx = *sys.resource<const WorldSource>().ctx;
  const StreamSettings& settings = sys.resource<const StreamSettings>();
  std::vector<Camera> cameras;
  sys.each<const WorldCamera>([&](const WorldCamera& c) { cameras.push_back(c.camera); });
  const double s = ctx.chunk_size();
  const auto required = needed_chunks(cameras, settings.pinned, settings.render_distance, s);
  const auto keep = needed_chunks(cameras, settings.pinned, settings.render_distance + settings.hysteresis, s);
  std::map<ChunkCoord, bool> live;
  std::map<ChunkCoord, ecs::Entity> handle;
  sys.each<const Chunk>([&](ecs::Entity e, const Chunk& c) {
    live.emplace(c.coord, c.halo);
    handle.emplace(c.coord, e);
  });
  const StreamPlan plan = plan_stream(required, keep, live, ctx.neighbour_ring);
  ecs::CommandBuffer& cb = sys.commands();
  for (ChunkCoord c : plan.spawn_full) cb.spawn(Chunk{c, false}, ChunkTerrain{}, ChunkPlacement{}, ChunkObjects{});
  for (ChunkCoord c : plan.spawn_halo) cb.spawn(Chunk{c, true}, ChunkTerrain{}, ChunkPlacement{}, ChunkObjects{});
  for (ChunkCoord c : plan.promote) sys.get<Chunk>(handle.at(c)).halo = false;
  if (plan.despawn.empty()) return;
  std::vector<bool> dying;
  for (ChunkCoord c : plan.despawn) {
    const ecs::Entity e = handle.at(c);
    if (e.index >= dying.size()) dying.resize(size_t(e.index) + 1);
    dying[e.index] = true;
    cb.despawn(e);
  }
  sys.each<const VegetationOf>([&](ecs::Entity e, const VegetationOf& v) {
    if (v.chunk.index < dying.size() && dying[v.chunk.index]) cb.despawn(e);
  });
}

/// Generate: terrain and trail meshes of every full chunk that has none yet.
void generate(ecs::SystemContext& sys) {
  const WorldContext& ctx = *sys.resource<const WorldSource>().ctx;
  sys.parallel_each<const Chunk, ChunkTerrain>(
      [&](const Chunk& c, ChunkTerrain& t) {
        if (!c.halo && !t.ready) t = generate_terrain(ctx, c.coord);
      },
      kPerChunk);
}

/// Place: candidates of every chunk (solids only for halos; with ground vegetation for full chunks).
void place(ecs::SystemContext& sys) {
  const WorldContext& ctx = *sys.resource<const WorldSource>().ctx;
  sys.parallel_each<const Chunk, ChunkPlacement>(
      [&](const Chunk& c, ChunkPlacement& p) {
        const bool want_ground = !c.halo;
        if (p.placed && (p.with_ground || !want_ground)) return;
        const auto t0 = std::chrono::steady_clock::now();
        p.candidates = place_candidates(ctx, c.coord, want_ground);
        p.place_s = since(t0);
        p.placed = true;
        p.with_ground = want_ground;
      },
      kPerChunk);
}

/// Resolve: final objects of every full chunk not resolved yet, against its neighbours' candidates.
void resolve(ecs::SystemContext& sys) {
  const WorldContext& ctx = *sys.resource<const WorldSource>().ctx;
  std::map<ChunkCoord, const ChunkCandidates*> table;
  sys.each<const Chunk, const ChunkPlacement>(
      [&](const Chunk& c, const ChunkPlacement& p) { table.emplace(c.coord, &p.candidates); });
  const CandidateLookup lookup = [&](ChunkCoord c) -> const ChunkCandidates& { return *table.at(c); };
  sys.parallel_each<const Chunk, const ChunkPlacement, ChunkObjects>(
      [&](const Chunk& c, const ChunkPlacement& p, ChunkObjects& o) {
        if (c.halo || o.resolved) return;
        o = resolve_objects(ctx, c.coord, p.candidates, lookup);
        o.stats.place_s = p.place_s;
      },
      kPerChunk);
}

/// Populate: one Vegetation entity (owned by its chunk) per final object of newly resolved chunks.
void populate(ecs::SystemContext& sys) {
  if (!sys.resource<const StreamSettings>().vegetation_entities) return;
  sys.parallel_each<const Chunk, ChunkObjects>(
      [](ecs::CommandBuffer& cb, ecs::Entity e, const Chunk& c, ChunkObjects& o) {
        if (c.halo || !o.resolved || o.populated) return;
        for (const Vegetation& v : o.objects) cb.spawn(v, VegetationOf{e});
        o.populated = true;
      },
      kPerChunk);
}

}  // namespace

StreamSettings default_stream_settings(const WorldContext& ctx) {
  StreamSettings s;
  s.render_distance = ctx.config.world.render_distance;
  s.hysteresis = ctx.chunk_size();
  return s;
}

void install_world_systems(ecs::World& world, const WorldContext& ctx, StreamSettings settings) {
  world.set_resource(WorldSource{&ctx});
  world.set_resource(std::move(settings));
  world.system("stream")
      .phase(WorldPhase::Stream)
      .reads_resource<WorldSource, StreamSettings>()
      .reads<WorldCamera, VegetationOf>()
      .writes<Chunk>()
      .run(stream);
  world.system("generate")
      .phase(WorldPhase::Generate)
      .reads_resource<WorldSource>()
      .reads<Chunk>()
      .writes<ChunkTerrain>()
      .run(generate);
  world.system("place")
      .phase(WorldPhase::Place)
      .reads_resource<WorldSource>()
      .reads<Chunk>()
      .writes<ChunkPlacement>()
      .run(place);
  world.system("resolve")
      .phase(WorldPhase::Resolve)
      .reads_resource<WorldSource>()
      .reads<Chunk, ChunkPlacement>()
      .writes<ChunkObjects>()
      .run(resolve);
  world.system("populate")
      .phase(WorldPhase::Resolve)
      .after("resolve")
      .reads_resource<StreamSettings>()
      .reads<Chunk>()
      .writes<ChunkObjects>()
      .run(populate);
  world.build_schedule();
}

size_t full_chunk_count(ecs::World& world) {
  size_t n = 0;
  world.view<const Chunk>().each([&](const Chunk& c) { n += c.halo ? 0 : 1; });
  return n;
}

}  // namespace silva::world
