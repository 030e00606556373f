#pragma once
/// @file Stereo disparity ground truth in KITTI's 16-bit PNG encoding (CONTRACT.md "File formats").
#include <cstdint>
#include <span>
#include <vector>

namespace silva::io {

/// The left camera's disparity, fx · baseline / depth pixels, as KITTI stores it: round(256 · disparity) per pixel,
/// 0 (invalid) where the pixel saw nothing (depth 0) or the value does not fit 1 … 65535 (disparity over 255.996 px:
/// closer than fx · baseline / 256).
std::vector<uint16_t> kitti_disparity(std::span<const float> depth, double fx, double baseline_m);

}  // namespace silva::io
