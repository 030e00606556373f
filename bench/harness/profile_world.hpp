#pragma once
/// @file One world of a `silva profile placement` sweep: what it holds per class and what it cost.
#include <array>
#include <optional>
#include <vector>

#include "bench/harness/profile_metrics.hpp"
#include "core/ontology.hpp"
#include "world/world_context.hpp"
#include "world/world_summary.hpp"

namespace silva::bench {

/// Per class (role) figures of one world.
struct ClassProfile {
  uint64_t candidates = 0;  ///< Proposed by placement in the built chunks (trail corridor excluded).
  uint64_t placed = 0;      ///< Final objects.
  uint64_t adjusted = 0;    ///< Final objects moved by overlap resolution.
  uint64_t dropped = 0;     ///< candidates - placed: removed by overlap resolution.
  double per_ha = 0;        ///< placed / area in hectares.
  double cover_pct = 0;     ///< Ground area under the class's crowns (footprint discs seen from above), %.
  std::optional<NearestStats> nearest;  ///< Same-class nearest-neighbour distances.
};

/// Whole-world figures of one world.
struct WorldProfile {
  uint64_t chunks = 0;             ///< Chunks built.
  double area_ha = 0;              ///< chunks x chunk_size^2 / 10 000.
  uint64_t objects = 0;            ///< All final objects.
  uint64_t candidates = 0;         ///< All candidates (= objects + dropped of every class).
  double canopy_cover_pct = 0;     ///< Ground under tree canopy (crowns of assets with canopy parts), %.
  uint64_t broad_queries = 0;      ///< Broad-phase queries of overlap resolution.
  uint64_t narrow_queries = 0;     ///< Narrow-phase fcl::collide calls.
  double generate_ms_per_chunk = 0;  ///< Terrain mesh (trail included), mean per chunk (ms).
  double place_ms_per_chunk = 0;     ///< Placement of the chunk's own candidates, mean per chunk (ms).
  double resolve_ms_per_chunk = 0;   ///< Overlap resolution, mean per chunk (ms).
  double build_s = 0;              ///< Wall time of build_world.
  std::array<ClassProfile, kRoleCount> classes{};  ///< Indexed by role.
  /// Solid objects ("things") per heatmap cell, row-major from the south-west corner.
  std::vector<uint32_t> heat;
  int heat_width = 0, heat_height = 0;  ///< Heatmap size in cells.
  std::vector<bool> heat_inside;        ///< Cells inside built chunks.
};

/// Side of a heatmap cell, metres.
inline constexpr double kHeatCell = 8.0;
/// Side of a cover-grid cell, metres.
inline constexpr double kCoverCell = 0.25;

/// Builds `coords` of `ctx` on `threads` threads and profiles the result.
WorldProfile profile_world(const world::WorldContext& ctx, const std::vector<ChunkCoord>& coords, int threads);

}  // namespace silva::bench
