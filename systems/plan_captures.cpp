#include "systems/plan_captures.hpp"

#include <utility>

#include "components/phase.hpp"
#include "components/world_source.hpp"
#include "world/chunk_cache.hpp"

namespace silva::systems {

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
        p.frames = world::plan_captures(ctx, sys.resource<world::ChunkCache>(), p.custom_poses, p.warn);
        for (const world::PlannedFrame& f : p.frames) sys.commands().spawn(world::PlannedFrame(f));
        p.planned = true;
      });
}

}  // namespace silva::systems
