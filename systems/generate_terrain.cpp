#include "systems/generate_terrain.hpp"

#include "components/chunk.hpp"
#include "components/phase.hpp"
#include "components/world_source.hpp"
#include "world/world_generator.hpp"

namespace silva::systems {

void install_generate_terrain(ecs::World& world) {
  world.system("generate_terrain")
      .phase(Phase::Generate)
      .reads_resource<WorldSource>()
      .writes<ChunkContent>()
      .run([](ecs::SystemContext& sys) {
        const world::WorldContext& ctx = *sys.resource<const WorldSource>().ctx;
        sys.parallel_each<ChunkContent>([&](ChunkContent& chunk) { world::add_terrain(ctx, chunk); }, 1);
      });
}

}  // namespace silva::systems
