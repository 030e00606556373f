#pragma once
/// @file A whole frame of linear RGB radiance (before exposure), for the camera model's optics.
#include <algorithm>
#include <cmath>
#include <vector>

#include "core/types.hpp"

namespace silva::render {

/// Linear RGB radiance per pixel, row-major; pixel (u, v)'s centre is at (u + 0.5, v + 0.5).
struct LinearFrame {
  int width = 0, height = 0;  ///< Size in pixels.
  std::vector<Vec3f> rgb;     ///< width * height values.

  /// Resizes to width x height (values unspecified).
  void resize(int w, int h) {
    width = w;
    height = h;
    rgb.resize(size_t(w) * size_t(h));
  }

  /// The value of pixel (u, v), clamped to the frame.
  const Vec3f& at(int u, int v) const {
    return rgb[size_t(std::clamp(v, 0, height - 1)) * size_t(width) + size_t(std::clamp(u, 0, width - 1))];
  }

  /// Bilinear value at image point (x, y) in pixel units (pixel centres at .5), edges clamped.
  Vec3f bilinear(float x, float y) const {
    const float fx = x - 0.5f, fy = y - 0.5f;
    const float x0 = std::floor(fx), y0 = std::floor(fy);
    const float ax = fx - x0, ay = fy - y0;
    const int u = int(x0), v = int(y0);
    const Vec3f top = at(u, v) * (1.0f - ax) + at(u + 1, v) * ax;
    const Vec3f bottom = at(u, v + 1) * (1.0f - ax) + at(u + 1, v + 1) * ax;
    return top * (1.0f - ay) + bottom * ay;
  }
};

}  // namespace silva::render
