#pragma once
/// @file Axis-aligned bounding box.
#include <limits>

#include "core/types.hpp"

namespace silva {

/// Axis-aligned box; empty when min > max.
struct AABB {
  Vec3f min = Vec3f::Constant(std::numeric_limits<float>::max());   ///< Lower corner.
  Vec3f max = Vec3f::Constant(-std::numeric_limits<float>::max());  ///< Upper corner.
  /// Grows the box to contain p.
  void extend(const Vec3f& p) { min = min.cwiseMin(p); max = max.cwiseMax(p); }
  /// Grows the box to contain b.
  void extend(const AABB& b) { min = min.cwiseMin(b.min); max = max.cwiseMax(b.max); }
  /// True when the box contains no point.
  bool empty() const { return (min.array() > max.array()).any(); }
  /// Box centre.
  Vec3f center() const { return 0.5f * (min + max); }
  /// Box extent (max - min).
  Vec3f size() const { return max - min; }
  /// Box transformed by an affine transform (bounds of the 8 transformed corners).
  AABB transformed(const Affine3f& m) const;
};

}  // namespace silva
