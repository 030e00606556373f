#pragma once
/// @file A 3D polyline parameterised by arc length: the terrain-following navigation spline.
#include <vector>

#include "core/types.hpp"

namespace silva::world {

/// Polyline through dense samples with position/tangent lookup by arc length s in [0, length()].
class NavSpline {
 public:
  NavSpline() = default;
  /// Builds from at least two samples (consecutive duplicates are kept; their segment has length 0).
  explicit NavSpline(std::vector<Vec3d> points);
  /// Total arc length L (metres).
  double length() const { return cumulative_.empty() ? 0.0 : cumulative_.back(); }
  /// Point at arc length s (clamped to [0, L]), linear between samples.
  Vec3d position(double s) const;
  /// Unit tangent (direction of travel) of the segment containing s.
  Vec3d tangent(double s) const;
  /// The samples.
  const std::vector<Vec3d>& points() const { return points_; }
  /// Arc length at each sample (same size as points()).
  const std::vector<double>& cumulative() const { return cumulative_; }

 private:
  /// Index k of the segment [k, k+1] containing s.
  size_t segment(double s) const;
  std::vector<Vec3d> points_;
  std::vector<double> cumulative_;
};

/// Centripetal Catmull-Rom spline through control points (xy), sampled `per_segment` times per
/// segment: (n-1)*per_segment + 1 points, both ends included. Ends use mirrored phantom points.
std::vector<Eigen::Vector2d> catmull_rom_centripetal(const std::vector<Eigen::Vector2d>& control, int per_segment);

}  // namespace silva::world
