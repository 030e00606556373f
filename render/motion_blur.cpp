#include "render/motion_blur.hpp"

#include <algorithm>
#include <cmath>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

namespace silva::render {

namespace {

/// Maps points in the frame camera's axes to a shutter camera's axes.
Mat4d relative(const Camera& camera, const Mat4d& shutter_to_world) {
  return shutter_to_world.inverse() * camera.camera_to_world;
}

/// Image point of homogeneous camera-axes point `x`; false when it is not in front of the camera.
bool project(const Camera& camera, const Eigen::Vector4d& x, Vec2f& out) {
  if (x.z() <= 1e-9) return false;
  out = Vec2f(float(camera.fx * x.x() / x.z() + camera.cx), float(camera.fy * x.y() / x.z() + camera.cy));
  return true;
}

/// motion_endpoints with the shutter cameras' relative transforms given.
bool endpoints(const Camera& camera, const Mat4d& to_open, const Mat4d& to_close, int u, int v, float z, Vec2f& open,
               Vec2f& close) {
  const double x = (double(u) + 0.5 - camera.cx) / camera.fx, y = (double(v) + 0.5 - camera.cy) / camera.fy;
  const Eigen::Vector4d point = z > 0.0f ? Eigen::Vector4d(x * z, y * z, z, 1.0) : Eigen::Vector4d(x, y, 1.0, 0.0);
  return project(camera, to_open * point, open) && project(camera, to_close * point, close);
}

}  // namespace

bool motion_endpoints(const Camera& camera, const ExposureMotion& motion, int u, int v, float z, Vec2f& open,
                      Vec2f& close) {
  return endpoints(camera, relative(camera, motion.open_to_world), relative(camera, motion.close_to_world), u, v, z,
                   open, close);
}

void apply_motion_blur(const LinearFrame& in, const std::vector<float>& depth, const Camera& camera,
                       const ExposureMotion& motion, LinearFrame& out) {
  out.resize(in.width, in.height);
  const Mat4d to_open = relative(camera, motion.open_to_world), to_close = relative(camera, motion.close_to_world);
  tbb::parallel_for(tbb::blocked_range<int>(0, in.height), [&](const tbb::blocked_range<int>& rows) {
    for (int v = rows.begin(); v < rows.end(); ++v)
      for (int u = 0; u < in.width; ++u) {
        const size_t i = size_t(v) * size_t(in.width) + size_t(u);
        Vec2f open, close;
        if (!endpoints(camera, to_open, to_close, u, v, depth[i], open, close)) {
          out.rgb[i] = in.rgb[i];
          continue;
        }
        const Vec2f path = close - open;
        const int n = std::clamp(int(std::ceil(path.norm())), 1, kMaxMotionSamples);
        Vec3f sum = Vec3f::Zero();
        for (int k = 0; k < n; ++k) {
          const Vec2f p = open + path * ((float(k) + 0.5f) / float(n));
          sum += in.bilinear(p.x(), p.y());
        }
        out.rgb[i] = sum / float(n);
      }
  });
}

}  // namespace silva::render
