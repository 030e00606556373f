#pragma once
/// @file The world inputs every generating system reads, as a resource.

namespace silva::world {
struct WorldContext;
}

namespace silva {

/// Resource: the immutable generation inputs (config, assets, terrain field, trail); not owned,
/// set by the command before the schedule runs and outliving it.
struct WorldSource {
  const world::WorldContext* ctx = nullptr;  ///< The world context.
};

}  // namespace silva
