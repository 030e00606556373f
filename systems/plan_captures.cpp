#include "systems/plan_captures.hpp"

#include <tbb/parallel_for.h>

#include <utility>

#include "assets/foliage_sprays.hpp"
#include "assets/mesh_cache.hpp"
#include "components/phase.hpp"
#include "components/world_source.hpp"
#include "world/chunk_cache.hpp"

namespace silva::systems {

namespace {

/// Draws every tree spray family at once, one per task: planning probes crowns on one thread, and the
/// first tree it meshes would otherwise draw its family's masks there, one family after another. Not
/// when the mesh cache is warm: the trees' meshes and masks are then read, and no family is drawn.
void draw_spray_families() {
  const std::span<const assets::SprayFamily> families = assets::spray_families();
  tbb::parallel_for(size_t(0), families.size(), [&](size_t i) { families[i](assets::kSprayClassSide); });
}

}  // namespace

void install_plan_captures(ecs::World& world, CapturePlan plan) {
  world.set_resource(std::move(plan));
  world.system("plan_captures")
      .phase(Phase::Plan)
      .reads_resource<WorldSource>()
      .writes_resource<CapturePlan, world::ChunkCache>()
      .writes<world::PlannedFrame>()
      .run([](ecs::SystemContext& sys) {
        CapturePlan& p = sys.resource<CapturePlan>();
        if (p.planned) return;
        const world::WorldContext& ctx = *sys.resource<const WorldSource>().ctx;
        if (!assets::process_mesh_cache_warm()) draw_spray_families();
        p.frames = world::plan_captures(ctx, sys.resource<world::ChunkCache>(), p.custom_poses, p.warn);
        for (const world::PlannedFrame& f : p.frames) sys.commands().spawn(world::PlannedFrame(f));
        p.planned = true;
      });
}

}  // namespace silva::systems
