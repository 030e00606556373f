#pragma once
/// @file Motion blur of the camera model (RGB only): each pixel averages the linear radiance
/// along the path its scene point takes across the image while the shutter is open.
#include <vector>

#include "core/camera.hpp"
#include "core/camera_model.hpp"
#include "render/linear_frame.hpp"

namespace silva::render {

/// Most samples along one pixel's motion path (longer paths are sampled more sparsely).
inline constexpr int kMaxMotionSamples = 32;

/// Image points (pixel units) where pixel (u, v)'s scene point, at depth z (0 = sky, infinitely far),
/// appears when the shutter opens and when it closes; false when it is behind either camera.
bool motion_endpoints(const Camera& camera, const ExposureMotion& motion, int u, int v, float z, Vec2f& open,
                      Vec2f& close);

/// Blurs `in` into `out` (resized): each pixel is the mean of ceil(path length) (1 … kMaxMotionSamples)
/// bilinear samples spread evenly along its motion_endpoints path; a pixel with no path is copied.
/// A gather along each pixel's own path: moving foreground smears over itself, not over the
/// background. Rows run in parallel; the result does not depend on the thread count.
void apply_motion_blur(const LinearFrame& in, const std::vector<float>& depth, const Camera& camera,
                       const ExposureMotion& motion, LinearFrame& out);

}  // namespace silva::render
