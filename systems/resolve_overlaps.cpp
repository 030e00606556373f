#include "systems/resolve_overlaps.hpp"

#include <map>

#include "components/chunk.hpp"
#include "components/phase.hpp"
#include "components/world_source.hpp"
#include "world/world_generator.hpp"

namespace silva::systems {

void install_resolve_overlaps(ecs::World& world) {
  world.system("resolve_overlaps")
      .phase(Phase::Resolve)
      .reads_resource<WorldSource>()
      .reads<Chunk, ChunkPlacement>()
      .writes<ChunkContent>()
      .run([](ecs::SystemContext& sys) {
        const world::WorldContext& ctx = *sys.resource<const WorldSource>().ctx;
        std::map<ChunkCoord, const world::ChunkCandidates*> table;
        sys.each<const Chunk, const ChunkPlacement>(
            [&](const Chunk& c, const ChunkPlacement& p) { table.emplace(c.coord, &p.candidates); });
        const world::CandidateLookup lookup = [&](ChunkCoord c) -> const world::ChunkCandidates& {
          return *table.at(c);
        };
        sys.parallel_each<const ChunkPlacement, ChunkContent>(
            [&](const ChunkPlacement& p, ChunkContent& chunk) {
              world::add_objects(ctx, p.candidates, lookup, chunk);
              chunk.stats.place_s = p.place_s;
            },
            1);
      });
}

}  // namespace silva::systems
