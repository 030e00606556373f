#pragma once
/// @file Resolve phase: final objects of new chunks (system "resolve_overlaps").
#include "ecs/world.hpp"

namespace silva::systems {

/// Registers "resolve_overlaps" (phase Resolve): world::add_objects on the ChunkContent of every full chunk entity
/// against the candidates of its neighbour entities (full or halo), in parallel over the chunks.
void install_resolve_overlaps(ecs::World& world);

}  // namespace silva::systems
