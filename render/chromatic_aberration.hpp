#pragma once
/// @file Lateral chromatic aberration of the camera model (RGB only).
#include "core/camera.hpp"
#include "render/linear_frame.hpp"

namespace silva::render {

/// Writes `in` with red sampled at the image point scaled about the principal point by (1 - k)
/// and blue by (1 + k) (bilinear), green unchanged, into `out` (resized). Rows run in parallel
/// on the caller's TBB arena; the result does not depend on the thread count.
void apply_chromatic_aberration(const LinearFrame& in, const Camera& camera, float k, LinearFrame& out);

}  // namespace silva::render
