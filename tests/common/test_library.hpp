#pragma once
/// @file A small in-memory asset library for world tests: one or two box meshes per kind with
/// simple collision proxies, so the tests do not depend on the procedural asset generators.
#include "assets/library.hpp"
#include "core/config.hpp"
#include "world/world_context.hpp"
#include "world/world_summary.hpp"

namespace silva::test {

/// The fixture library (index_kinds() already called).
const assets::AssetLibrary& small_library();

/// A config for small, fast worlds: the given seed and density, a 128 m capture region,
/// render distance 32 m, a trail of 12 points 10 m apart.
Config small_world_config(int64_t seed, double density = 5);

/// The chunks `coords` built by the world library alone (world::generate_chunk per chunk, in
/// parallel on `threads` threads) and summarised: the reference the schedule must equal.
world::BuiltWorld build_world(const world::WorldContext& ctx, std::vector<ChunkCoord> coords, int threads);

}  // namespace silva::test
