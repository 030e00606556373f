#pragma once
/// @file The terrain heightfield: a pure function of world position (fractal simplex noise,
/// flattened along the trail), and the per-chunk terrain mesh built from it, which carries the
/// trail as its overlay. Neighbouring chunks share border vertices bit for bit because every
/// vertex is computed from its global grid index.
#include <memory>

#include "core/config.hpp"
#include "core/mesh.hpp"
#include "core/noise.hpp"
#include "core/types.hpp"
#include "world/trail_path.hpp"

namespace silva::world {

/// The seeded height function of a world.
struct TerrainField {
  FbmParams noise;             ///< Fractal noise parameters with the seeded offset.
  double max_elevation = 1.5;  ///< Height = max_elevation * fbm (metres).
  double vertex_spacing = 0.5; ///< Mesh vertex spacing (metres), for surface_height.
  std::shared_ptr<const TrailPath> trail;  ///< The trail the terrain is flattened along (null: none).
};

/// Builds the height function of a world from the config (terrain.*, trail.*) and seed, with the
/// trail's path when trail.enabled; throws InputError when the capture region is too small for it.
TerrainField make_terrain_field(const Config& cfg);

/// Height of the terrain function at world (x, y), metres (the trail's bed included).
float terrain_height(const TerrainField& field, double x, double y);

/// heights[k] = terrain_height(field, x[k], y[k]) for k < n (the noise n points at a time on SIMD lanes).
void terrain_heights(const TerrainField& field, const double* x, const double* y, float* heights, size_t n);

/// Height of the triangulated terrain mesh surface at (x, y): the function sampled at the
/// vertex grid and interpolated over the same triangle the mesh uses (for draping).
float surface_height(const TerrainField& field, double x, double y);

/// Unit normal of the terrain function at (x, y) by central differences over one vertex spacing.
Vec3f terrain_normal(const TerrainField& field, double x, double y);

/// Terrain mesh of one chunk in world coordinates: (n+1)^2 vertices, n = chunk_size/vertex_spacing,
/// one part with role Ground and material Ground. uv.x is the signed distance to the trail's edge
/// (metres, negative on the trail, at most kTrailShoulder), uv.y the arc length along the trail
/// of the nearest centre-line point (0 where none is within TrailPath::query_radius()); where the
/// trail's shoulder reaches the chunk, the part's overlay is role Trail, material Trail
/// (core/surface_overlay.hpp paints it by uv.x).
Mesh build_terrain_mesh(const TerrainField& field, double chunk_size, ChunkCoord coord);

}  // namespace silva::world
