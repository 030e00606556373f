// `silva verify`'s LiDAR check (see verify_lidar.hpp).
#include "app/commands/verify/verify_lidar.hpp"

#include <algorithm>
#include <cmath>

namespace silva::app {

void LidarTally::merge(const LidarTally& o) {
  points += o.points;
  in_view += o.in_view;
  compared += o.compared;
  hidden += o.hidden;
  class_agree += o.class_agree;
  range_error_m.merge(o.range_error_m);
}

LidarTally compare_lidar(const FrameTruth& truth, const Camera& camera, const Mat4d& lidar_to_camera,
                         std::span<const Vec3f> points, std::span<const uint32_t> labels) {
  LidarTally t;
  t.points = points.size();
  const int w = truth.width, h = truth.height;
  for (size_t i = 0; i < points.size(); ++i) {
    const Vec3d q = (lidar_to_camera * points[i].cast<double>().homogeneous()).head<3>();
    if (q.z() <= camera.near) continue;
    // Image position in pixel-centre coordinates: pixel (u, v)'s centre is at (u, v).
    const double px = camera.fx * q.x() / q.z() + camera.cx - 0.5, py = camera.fy * q.y() / q.z() + camera.cy - 0.5;
    if (!(px > -0.5 && py > -0.5 && px < w - 0.5 && py < h - 0.5)) continue;
    ++t.in_view;
    const int u = int(std::lround(px)), v = int(std::lround(py));
    const uint32_t p = uint32_t(v) * uint32_t(w) + uint32_t(u);
    if (!interior_pixel(truth.semantic, w, h, p)) continue;
    const int u0 = std::clamp(int(std::floor(px)), 0, w - 2), v0 = std::clamp(int(std::floor(py)), 0, h - 2);
    const double fx = std::clamp(px - u0, 0.0, 1.0), fy = std::clamp(py - v0, 0.0, 1.0);
    // Inverse depth is linear across a planar surface in the image, so it is what is interpolated.
    double inverse = 0, nearest = INFINITY, farthest = 0;
    bool surface = true;
    for (int k = 0; k < 4; ++k) {
      const size_t at = size_t(v0 + k / 2) * size_t(w) + size_t(u0 + k % 2);
      const double d = truth.depth[at];
      surface = surface && d > 0 && truth.semantic[at] == truth.semantic[p];
      if (!surface) break;
      inverse += (k % 2 ? fx : 1 - fx) * (k / 2 ? fy : 1 - fy) / d;
      nearest = std::min(nearest, d), farthest = std::max(farthest, d);
    }
    if (!surface || farthest > kLidarDepthStep * nearest) continue;
    const double z = 1.0 / inverse;
    // Both ranges along the camera ray through the point: the point's, and the depth file's.
    const double range = q.norm(), file_range = range * z / q.z();
    if (range - file_range > kLidarOcclusionMargin + 0.02 * file_range) {
      ++t.hidden;
      continue;
    }
    ++t.compared;
    t.class_agree += (labels[i] & 0xffffu) == truth.semantic[p];
    t.range_error_m.add(std::abs(range - file_range));
  }
  return t;
}

}  // namespace silva::app
