#pragma once
/// @file The stereo rig: the right camera of a rectified pair from its left (mono) camera.
#include "world/plan_captures.hpp"

namespace silva::world {

/// The right camera of a rectified stereo pair whose left camera is `left`: the same intrinsics, rotation, angles
/// and frame number, its centre (and its motion while the shutter is open) baseline_m along the left's +x axis.
PlannedFrame stereo_right(const PlannedFrame& left, double baseline_m);

}  // namespace silva::world
