#pragma once
/// @file Thin-lens depth of field of the camera model (RGB only): a gather blur of the linear
/// radiance by each pixel's circle of confusion, from the exact depth buffer.
#include <vector>

#include "core/camera.hpp"
#include "core/camera_model.hpp"
#include "render/linear_frame.hpp"

namespace silva::render {

/// Largest circle-of-confusion radius the blur gathers, pixels (larger circles are capped).
inline constexpr float kMaxCocRadius = 16.0f;

/// Circle-of-confusion diameter in pixels of a point at depth z (metres along the optical axis;
/// 0 = sky, infinitely far): fx * f / (N (s - f)) * |z - s| / z for focal length f, f-number N and
/// focus distance s.
float coc_diameter_px(const DepthOfField& dof, const Camera& camera, float z);

/// Blurs `in` into `out` (resized): each pixel gathers a fixed 64-point disc around it, scaled to
/// the largest circle of confusion near it; a sample counts when its own circle covers the pixel
/// and, if it lies behind the pixel, when the pixel's circle covers it too (so sharp foreground is
/// not overrun by blurred background); weights 1 / max(r, 1)^2. A pixel with no circle of half a
/// pixel or more around it is copied. Rows run in parallel; the result does not depend on threads.
void apply_depth_of_field(const LinearFrame& in, const std::vector<float>& depth, const Camera& camera,
                          const DepthOfField& dof, LinearFrame& out);

}  // namespace silva::render
