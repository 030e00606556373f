#pragma once
/// @file Which chunks a region needs (CONTRACT.md "World geometry": a chunk intersects a region
/// when their overlap has positive area; chunks are returned in (i, j) order, i first).
#include <vector>

#include "core/camera.hpp"
#include "core/config.hpp"
#include "core/types.hpp"

namespace silva::world {

/// Chunks whose footprint comes closer than r to the point (cx, cy).
std::vector<ChunkCoord> chunks_in_disc(double cx, double cy, double r, double chunk_size);

/// The default world: every chunk closer than world.render_distance to the capture region
/// (the world.extent square centred on the origin).
std::vector<ChunkCoord> default_world_chunks(const Config& cfg);

/// Chunks whose footprint meets the horizontal projection of the camera's view frustum
/// between its near and far planes (the convex hull of the 8 frustum corners).
std::vector<ChunkCoord> chunks_in_view(const Camera& camera, double chunk_size);

/// The chunks a view needs: those meeting its frustum, plus the disc of radius `shadow_reach`
/// around the camera whose objects may cast shadows into the view; sorted, unique.
std::vector<ChunkCoord> chunks_for_view(const Camera& camera, double chunk_size, double shadow_reach);

/// The chunks within `ring` chunks (in i and in j) of one of `coords`, other than that chunk itself; sorted,
/// unique (a chunk of `coords` is listed when it lies within the ring of another).
std::vector<ChunkCoord> ring_neighbours(const std::vector<ChunkCoord>& coords, int ring);

/// Horizontal distance from (x, y) to the footprint of chunk c (0 inside).
double distance_to_chunk(ChunkCoord c, double chunk_size, double x, double y);

}  // namespace silva::world
