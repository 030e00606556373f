#pragma once
/// @file Resolve phase, last step: finished chunks into the chunk cache (system "store_chunks").
#include "ecs/world.hpp"

namespace silva::systems {

/// Registers "store_chunks" (phase Resolve, after "resolve_overlaps"): moves each full chunk
/// entity's ChunkContent out, adds its coarse terrain level when a camera is active or
/// PinnedChunks::for_drawing is set (chunks that get drawn), inserts the chunks into the ChunkCache
/// resource in (i, j) order and despawns every chunk entity, halos included.
void install_store_chunks(ecs::World& world);

}  // namespace silva::systems
