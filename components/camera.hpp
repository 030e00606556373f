#pragma once
/// @file Camera entity component: a view whose surroundings the Stream phase keeps loaded.
#include "core/camera.hpp"

namespace silva {

/// A camera entity's pose and intrinsics (the frustum that Stream loads chunks for).
struct WorldCamera {
  Camera camera;  ///< Intrinsics, pose, near and far.
};

}  // namespace silva
