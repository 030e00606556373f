#pragma once
/// @file The world on the ECS (DESIGN.md "Phases"): camera and chunk entities, and the systems
/// Stream -> Generate -> Place -> Resolve that world.run_frame() runs.
#include <vector>

#include "core/types.hpp"
#include "ecs/world.hpp"
#include "systems/world_context.hpp"

namespace silva::world {

/// The world-generation phases, in run order.
enum class WorldPhase : int { Stream = 0, Generate = 1, Place = 2, Resolve = 3 };

/// Resource: the immutable generation inputs (not owned; must outlive the ECS world).
struct WorldSource {
  const WorldContext* ctx = nullptr;  ///< Config, assets, terrain field, trail.
};

/// Resource: what the Stream phase keeps loaded.
struct StreamSettings {
  double render_distance = 250;     ///< Chunks closer than this to a camera (or in its view) are full.
  double hysteresis = 32;           ///< Full chunks stay until they are this much farther.
  std::vector<ChunkCoord> pinned;   ///< Chunks that are always full (e.g. the default world).
  bool vegetation_entities = true;  ///< Spawn one Vegetation entity per final object.
};

/// Stream settings for a context: world.render_distance and one chunk of hysteresis.
StreamSettings default_stream_settings(const WorldContext& ctx);

/// Sets the WorldSource and StreamSettings resources and registers the systems:
/// "stream" (spawns/promotes/despawns chunk entities and their vegetation, through the
/// command buffer), "generate" (terrain + trail meshes), "place" (candidates), "resolve"
/// (final objects) and "populate" (Vegetation entities), the last three in parallel over chunks.
void install_world_systems(ecs::World& world, const WorldContext& ctx, StreamSettings settings);

/// Number of live full (non-halo) chunk entities.
size_t full_chunk_count(ecs::World& world);

}  // namespace silva::world
