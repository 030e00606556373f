#pragma once
/// @file `silva verify`'s LiDAR check: a frame's scan projected into its camera and compared with the
/// depth and semantic files along the same camera rays, away from silhouettes.
#include <cstdint>
#include <span>

#include "app/commands/verify/verify_compare.hpp"
#include "core/camera.hpp"
#include "core/types.hpp"

namespace silva::app {

/// Counts of the scan points of one or more frames.
struct LidarTally {
  uint64_t points = 0;        ///< Points in the scans.
  uint64_t in_view = 0;       ///< Points in front of the camera that project into the image.
  uint64_t compared = 0;      ///< Of those, points on interior pixels (one class in the 3x3 neighbourhood, and
                              ///< at the four nearest pixel centres depths of that class within kLidarDepthStep of
                              ///< each other) not hidden from the camera.
  uint64_t hidden = 0;        ///< Points behind the camera's surface by more than the occlusion margin
                              ///< (seen from the LiDAR's mount, not from the camera).
  uint64_t class_agree = 0;   ///< Compared points whose label class is the semantic PNG's there.
  ErrorHistogram range_error_m;  ///< |range along the camera ray − the depth file's range| (metres), compared points.
  /// Adds `other`'s counts.
  void merge(const LidarTally& other);
};

/// A point farther along its camera ray than the depth file by more than this (metres, plus 2 % of the
/// range) is taken to be hidden from the camera.
inline constexpr double kLidarOcclusionMargin = 0.1;

/// Four pixel centres whose depths differ by more than this factor straddle a depth edge (same class
/// in front of itself, e.g. a leaf card before the canopy behind it): no point is compared there.
inline constexpr double kLidarDepthStep = 1.05;

/// Compares one scan (`points` in the sensor frame, SemanticKITTI `labels` of the same length) with
/// the frame's files: each point goes through `lidar_to_camera` into `camera`; the depth file's value
/// at its exact image position is interpolated (as inverse depth) between the four nearest pixel centres.
LidarTally compare_lidar(const FrameTruth& truth, const Camera& camera, const Mat4d& lidar_to_camera,
                         std::span<const Vec3f> points, std::span<const uint32_t> labels);

}  // namespace silva::app
