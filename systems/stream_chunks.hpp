#pragma once
/// @file Stream phase: chunk entities for every needed chunk the cache lacks (system "stream_chunks").
#include "ecs/world.hpp"

namespace silva::systems {

/// Registers "stream_chunks" (phase Stream, after "aim_camera"): for every chunk of ViewChunks and
/// PinnedChunks missing from the ChunkCache resource, spawns a full chunk entity (Chunk, an empty
/// ChunkPlacement and a ChunkContent holding only its coordinates), and a halo chunk entity for each chunk within
/// the neighbour ring of one that is not itself full (its candidates resolve the full ones).
void install_stream_chunks(ecs::World& world);

}  // namespace silva::systems
