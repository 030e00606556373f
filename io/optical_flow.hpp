#pragma once
/// @file Exact optical flow between two views of a static scene (CONTRACT.md "Optical flow"): each pixel
/// of the first view lifted to the world by its depth and projected into the second, with occlusion and
/// out-of-view masks; encoded as KITTI flow PNGs and Middlebury .flo files.
#include <cstdint>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "core/camera.hpp"

namespace silva::io {

/// What the flow of a pixel is.
enum class FlowState : uint8_t {
  Valid = 0,      ///< The pixel's scene point is seen by the second view where the flow points.
  Occluded = 1,   ///< In the second view's image, but the pixel it lands on sees another surface (nearer: hidden).
  OutOfView = 2,  ///< Leaves the second view's image (the flow is its projection) or goes behind the camera (flow 0).
  NoDepth = 3,    ///< The pixel hit nothing (sky): no flow.
};

/// Per-pixel flow from one view to another, pixels in row-major order.
struct FlowField {
  int width = 0, height = 0;
  std::vector<float> u, v;         ///< Displacement in pixels (x right, y down); 0 where NoDepth.
  std::vector<FlowState> state;    ///< What each pixel's flow is.
};

/// Relative depth difference (plus 1 cm) within which the second view sees the projected point's surface.
inline constexpr float kOcclusionTolerance = 0.02f;

/// The flow of every pixel of view `from` (depth `from_depth`: CV_32FC1 metres along the optical axis, +inf or
/// 0 for no hit) into view `to` (its depth `to_depth` decides occlusion: Valid only when the projected point's
/// depth is within kOcclusionTolerance of the depth at the pixel it lands on, plus 1 cm). Pixel centres are at
/// (x + 0.5, y + 0.5) (core/camera.hpp).
FlowField optical_flow(const Camera& from, const cv::Mat& from_depth, const Camera& to, const cv::Mat& to_depth);

/// KITTI's flow PNG: 16-bit RGB, R = u·64 + 2^15, G = v·64 + 2^15 (rounded, clamped to 0 ... 65535), B = 1 for a
/// Valid pixel and 0 otherwise (then R = G = 0).
std::string encode_kitti_flow_png(const FlowField& flow);

/// Middlebury's .flo: "PIEH", width and height (int32), then u, v per pixel (float32, little-endian); pixels
/// without flow (NoDepth) hold 1e10 (Middlebury's unknown), the others their projection.
std::string encode_middlebury_flo(const FlowField& flow);

/// The per-pixel FlowState as an 8-bit grey PNG (0 valid, 1 occluded, 2 out of view, 3 no depth).
std::string encode_flow_mask_png(const FlowField& flow);

}  // namespace silva::io
