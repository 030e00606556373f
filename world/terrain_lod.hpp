#pragma once
/// @file The coarser level of a chunk's terrain mesh: simplified by meshoptimizer within a fixed
/// geometric error, with the chunk border locked, so that neighbouring chunks drawn at either
/// level still share every border vertex and edge (no cracks, no T-junctions); the trail's band
/// is kept at full detail.
#include "core/mesh.hpp"

namespace silva::world {

/// Simplification error allowed in the coarse terrain level (meshoptimizer's measure, metres). The
/// largest height change it lets through is up to about twice that (1.8 cm on 3 m relief, see
/// terrain_lod_test); where the level is drawn (kTerrainLodScreenSize) it projects to under 0.3 px.
inline constexpr float kTerrainLodError = 0.01f;

/// Projected-size threshold of the coarse terrain level (fraction of image height, as
/// render::MeshLods::lod_screen_sizes): a 32 m chunk seen by the default camera (90 degrees,
/// 1920x1080, fy = 960 px) switches at about 34 m from its centre, where a 0.5 m grid cell seen
/// from eye height spans under a pixel vertically.
inline constexpr float kTerrainLodScreenSize = 1.2f;

/// The coarse level of terrain chunk mesh `full` (one part): the fewest triangles within
/// kTerrainLodError, border locked. Triangles with a vertex within the trail's shoulder (uv.x <
/// kTrailShoulder, where the part has an overlay) are kept as they are, so the trail's edge
/// coordinate and its label edge stay exact at either level. Empty (no triangles) when that does
/// not shrink the mesh or the mesh is not a one-part terrain mesh.
Mesh build_terrain_lod(const Mesh& full);

}  // namespace silva::world
