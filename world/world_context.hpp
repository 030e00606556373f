#pragma once
/// @file Everything chunk generation reads, computed once in setup: config, asset tables,
/// terrain field and trail. Immutable afterwards, so chunks can be generated on any thread.
#include <array>
#include <vector>

#include "assets/library.hpp"
#include "core/config.hpp"
#include "core/season.hpp"
#include "core/timed_pose.hpp"
#include "world/forest_types.hpp"
#include "world/species_stands.hpp"
#include "world/terrain.hpp"
#include "world/trail.hpp"
#include "world/trail_surface_choice.hpp"

namespace silva::world {

/// Footprint radius of ground vegetation (grass, ferns) at scale 1, metres.
inline constexpr float kGroundFootprint = 0.1f;

/// The immutable inputs of world generation.
struct WorldContext {
  Config config;                               ///< Resolved config.
  const assets::AssetLibrary* library = nullptr;  ///< Placeable assets (not owned).
  TerrainField terrain;                        ///< Height function.
  Trail trail;                                 ///< The trail (enabled = false when off).
  const ForestType* forest = nullptr;          ///< What grows (vegetation.forest_type, drawn for "random").
  TrailSurface trail_surface{};                ///< How the trail looks (trail.surface, drawn for "random").
  Season season = Season::Summer;              ///< vegetation.season.
  SpeciesStands stands;                        ///< Assets grouped by species, and the stand field.
  std::vector<float> footprint;                ///< Unscaled footprint radius per asset (ground: kGroundFootprint).
  float max_footprint = 0;                     ///< Largest scaled solid footprint radius (rmax), metres.
  int neighbour_ring = 1;                      ///< Chunks on each side whose candidates can touch a chunk's.
  std::vector<TimedPose> walk_poses;           ///< trajectory.file's poses (empty: the walk follows the trail).
  /// Chunk edge length (terrain.chunk_size), metres.
  double chunk_size() const { return config.terrain.chunk_size; }
};

/// Builds the context; throws InputError when chunk_size is not a whole multiple of
/// vertex_spacing and grid_spacing, or when the trail does not fit the capture region.
WorldContext make_world_context(const Config& cfg, const assets::AssetLibrary& library);

}  // namespace silva::world
