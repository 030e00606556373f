#pragma once
/// @file Generate phase: terrain meshes of new chunks, the trail painted in (system "generate_terrain").
#include "ecs/world.hpp"

namespace silva::systems {

/// Registers "generate_terrain" (phase Generate): world::add_terrain on the ChunkContent of every
/// full chunk entity, in parallel over the entities.
void install_generate_terrain(ecs::World& world);

}  // namespace silva::systems
