#pragma once
/// @file The camera model's optics on a whole linear frame (RGB only): motion blur, depth of
/// field, then lateral chromatic aberration. Vignetting and noise come after, per row
/// (render/camera_encode.hpp).
#include <vector>

#include "core/camera.hpp"
#include "core/camera_model.hpp"
#include "render/linear_frame.hpp"

namespace silva::render {

/// True when `model` has an optic that reads neighbouring pixels (so shading needs the whole frame).
bool needs_whole_frame(const CameraModel& model);

/// Applies `model`'s motion blur, depth of field and chromatic aberration to `frame` in that
/// order, using `scratch` as the second buffer; `depth` is the G-buffer's (0 = sky).
void apply_optics(LinearFrame& frame, LinearFrame& scratch, const std::vector<float>& depth, const Camera& camera,
                  const CameraModel& model);

}  // namespace silva::render
