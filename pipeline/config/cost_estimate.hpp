#pragma once
/// @file The "what will this cost" guard: from the config alone, before anything is built or
/// written, estimate the chunks a frame or a world needs, their memory and the placement work,
/// and refuse (exit 2, with the estimate) what this machine cannot do unless `--force` is given.
#include <cstdint>
#include <optional>
#include <string>

#include "core/config.hpp"

namespace silva::pipeline {

/// What a run is expected to need at its peak.
struct CostEstimate {
  double chunks = 0;            ///< Chunks held at once (one frame's view, the cache, or a whole world).
  double bytes = 0;             ///< Memory those chunks take, bytes.
  double points_per_frame = 0;  ///< Placement points one frame (or the world) evaluates.
  double machine_bytes = 0;     ///< Physical memory of this machine, bytes.
};

/// The estimate for `silva generate` with `config`: the chunks of one frame's view (its far
/// plane's footprint) or the chunk cache, whichever is larger.
CostEstimate estimate_generate_cost(const Config& config);

/// The estimate for `silva world`: the chunks of the disc (radius R around any centre) or, without
/// one, of the default world; a world is built once, so only its memory is bounded.
CostEstimate estimate_world_cost(const Config& config, std::optional<double> radius);

/// Throws InputError with the estimate when it exceeds the machine (memory above
/// limits::kMaxMemoryShare of its RAM) or limits::kMaxPlacementPointsPerFrame, unless `force`; `what` names the command ("generate").
void check_cost(const CostEstimate& estimate, bool force, const std::string& what, bool can_force = true);

}  // namespace silva::pipeline
