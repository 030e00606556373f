#include "io/optical_flow.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <stdexcept>

#include "io/png_writer.hpp"

namespace silva::io {

FlowField optical_flow(const Camera& from, const cv::Mat& from_depth, const Camera& to, const cv::Mat& to_depth) {
  if (from_depth.type() != CV_32FC1 || to_depth.type() != CV_32FC1 || from_depth.cols != from.width ||
      from_depth.rows != from.height || to_depth.cols != to.width || to_depth.rows != to.height)
    throw std::invalid_argument("optical_flow: depth images must be CV_32FC1 of their cameras' sizes");
  FlowField flow;
  flow.width = from.width;
  flow.height = from.height;
  const size_t n = size_t(from.width) * size_t(from.height);
  flow.u.assign(n, 0.0f);
  flow.v.assign(n, 0.0f);
  flow.state.assign(n, FlowState::NoDepth);
  // Points of `from`'s camera frame into `to`'s: one rigid transform.
  const Mat4d relative = to.world_to_camera() * from.camera_to_world;
  const Mat3d r = relative.block<3, 3>(0, 0);
  const Vec3d t = relative.block<3, 1>(0, 3);
  for (int y = 0; y < from.height; ++y) {
    const float* depth_row = from_depth.ptr<float>(y);
    for (int x = 0; x < from.width; ++x) {
      const double z = depth_row[x];
      if (!(z > 0) || std::isinf(z)) continue;
      const double u0 = x + 0.5, v0 = y + 0.5;
      const Vec3d p = r * Vec3d((u0 - from.cx) / from.fx * z, (v0 - from.cy) / from.fy * z, z) + t;
      const size_t i = size_t(y) * size_t(from.width) + size_t(x);
      if (p.z() <= 0) {
        flow.state[i] = FlowState::OutOfView;
        continue;
      }
      const double u1 = to.fx * p.x() / p.z() + to.cx, v1 = to.fy * p.y() / p.z() + to.cy;
      flow.u[i] = float(u1 - u0);
      flow.v[i] = float(v1 - v0);
      if (!(u1 >= 0 && u1 < to.width && v1 >= 0 && v1 < to.height)) {
        flow.state[i] = FlowState::OutOfView;
        continue;
      }
      const double seen = to_depth.at<float>(int(v1), int(u1));
      // The pixel it lands on must see this surface: a nearer one hides it, a farther one means the point covers
      // less of that pixel than its centre (a leaf's edge), so neither pixel's label describes the other.
      const bool same = std::isfinite(seen) && std::abs(p.z() - seen) <= kOcclusionTolerance * seen + 0.01;
      flow.state[i] = same ? FlowState::Valid : FlowState::Occluded;
    }
  }
  return flow;
}

std::string encode_kitti_flow_png(const FlowField& flow) {
  std::vector<uint16_t> rgb(flow.u.size() * 3, 0);
  const auto encode = [](float d) { return uint16_t(std::clamp(std::lround(double(d) * 64.0 + 32768.0), 0L, 65535L)); };
  for (size_t i = 0; i < flow.u.size(); ++i) {
    if (flow.state[i] != FlowState::Valid) continue;
    rgb[3 * i] = encode(flow.u[i]);
    rgb[3 * i + 1] = encode(flow.v[i]);
    rgb[3 * i + 2] = 1;
  }
  const std::vector<uint8_t> png = encode_png_rgb16(rgb, flow.width, flow.height);
  return {png.begin(), png.end()};
}

std::string encode_middlebury_flo(const FlowField& flow) {
  std::string out(12 + flow.u.size() * 8, '\0');
  const int32_t size[2] = {flow.width, flow.height};
  std::memcpy(out.data(), "PIEH", 4);  // the float 202021.25, as Middlebury's readers check it
  std::memcpy(out.data() + 4, size, 8);
  char* at = out.data() + 12;
  for (size_t i = 0; i < flow.u.size(); ++i, at += 8) {
    const bool known = flow.state[i] != FlowState::NoDepth;
    const float uv[2] = {known ? flow.u[i] : 1e10f, known ? flow.v[i] : 1e10f};
    std::memcpy(at, uv, 8);  // little-endian, as every machine Silva builds for
  }
  return out;
}

std::string encode_flow_mask_png(const FlowField& flow) {
  std::vector<uint8_t> grey(flow.state.size());
  std::transform(flow.state.begin(), flow.state.end(), grey.begin(), [](FlowState s) { return uint8_t(s); });
  const std::vector<uint8_t> png = encode_png_grey8(grey, flow.width, flow.height);
  return {png.begin(), png.end()};
}

}  // namespace silva::io
