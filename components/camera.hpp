#pragma once
/// @file Camera entities: one per planned capture (its world::PlannedFrame is the component),
/// and the queue that says which camera each frame renders.
#include <cstddef>
#include <vector>

#include "ecs/entity.hpp"

namespace silva {

/// Resource: the camera entities to capture, in capture order, and the one this frame renders.
struct CaptureQueue {
  std::vector<ecs::Entity> cameras;       ///< Cameras still to capture, in order.
  std::size_t next = 0;                   ///< Index of the camera the next frame renders.
  ecs::Entity active = ecs::null_entity;  ///< The camera of the current frame (null: none).
  /// True while cameras remain to be captured.
  bool pending() const { return next < cameras.size(); }
};

}  // namespace silva
