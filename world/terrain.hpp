#pragma once
/// @file The terrain heightfield: a pure function of world position (fractal simplex noise),
/// and the per-chunk terrain mesh built from it. Neighbouring chunks share border vertices
/// bit for bit because every vertex is computed from its global grid index.
#include "core/config.hpp"
#include "core/mesh.hpp"
#include "core/noise.hpp"
#include "core/types.hpp"

namespace silva::world {

/// The seeded height function of a world.
struct TerrainField {
  FbmParams noise;             ///< Fractal noise parameters with the seeded offset.
  double max_elevation = 1.5;  ///< Height = max_elevation * fbm (metres).
  double vertex_spacing = 0.5; ///< Mesh vertex spacing (metres), for surface_height.
};

/// Texture coordinates of the ground are world x, y divided by this many metres.
inline constexpr double kGroundUvMetres = 4.0;

/// Builds the height function of a world from the config (terrain.*) and seed.
TerrainField make_terrain_field(const Config& cfg);

/// Height of the terrain function at world (x, y), metres.
float terrain_height(const TerrainField& field, double x, double y);

/// Height of the triangulated terrain mesh surface at (x, y): the function sampled at the
/// vertex grid and interpolated over the same triangle the mesh uses (for draping).
float surface_height(const TerrainField& field, double x, double y);

/// Unit normal of the terrain function at (x, y) by central differences over one vertex spacing.
Vec3f terrain_normal(const TerrainField& field, double x, double y);

/// Terrain mesh of one chunk in world coordinates: (n+1)^2 vertices, n = chunk_size/vertex_spacing,
/// one part with role Ground and material Ground; uvs are world x, y / kGroundUvMetres.
Mesh build_terrain_mesh(const TerrainField& field, double chunk_size, ChunkCoord coord);

}  // namespace silva::world
