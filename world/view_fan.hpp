#pragma once
/// @file The views taken from one spot (an autopilot point's yaws), which share one sun shadow map.
#include <vector>

#include "core/camera.hpp"
#include "world/plan_captures.hpp"

namespace silva::world {

/// The cameras of every frame taken from `f`'s position: one per yaw of f.fan_yaws_deg, with f's
/// intrinsics, pitch and roll (every frame of an autopilot point gets the same list, bit for bit);
/// f's own camera alone when the fan is empty.
std::vector<Camera> view_fan(const PlannedFrame& f);

}  // namespace silva::world
