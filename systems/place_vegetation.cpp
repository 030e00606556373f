#include "systems/place_vegetation.hpp"

#include "components/chunk.hpp"
#include "components/phase.hpp"
#include "components/world_source.hpp"
#include "core/stopwatch.hpp"
#include "world/chunk_content.hpp"
#include "world/placement.hpp"

namespace silva::systems {

void install_place_vegetation(ecs::World& world) {
  world.system("place_vegetation")
      .phase(Phase::Place)
      .reads_resource<WorldSource>()
      .reads<Chunk>()
      .writes<ChunkPlacement>()
      .run([](ecs::SystemContext& sys) {
        const world::WorldContext& ctx = *sys.resource<const WorldSource>().ctx;
        sys.parallel_each<const Chunk, ChunkPlacement>(
            [&](const Chunk& c, ChunkPlacement& p) {
              const Stopwatch clock;
              p.candidates = world::place_candidates(ctx, c.coord, !c.halo);
              p.place_s = clock.seconds();
            },
            1);
      });
}

}  // namespace silva::systems
