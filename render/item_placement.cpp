#include "render/item_placement.hpp"

#include <algorithm>
#include <cmath>

namespace silva::render {

namespace {

/// Relative margin that covers the rounding between a box corner's plane value and a vertex's.
constexpr double kPlacementMargin = 1e-9;

/// The verdict of the eight view-space corners `c` against `count` planes: `any_outside` when
/// all corners are behind one plane, `all_inside` stays true while all are in front of every plane.
void test_planes(const Vec3d (&c)[8], double extent, const Vec4d* planes, int count, bool& any_outside,
                 bool& all_inside) {
  for (int k = 0; k < count; ++k) {
    const Vec4d& pl = planes[k];
    const double margin = kPlacementMargin * (std::abs(pl.w()) + pl.head<3>().norm() * extent);
    double lo = INFINITY, hi = -INFINITY;
    for (const Vec3d& p : c) {
      const double v = pl.x() * p.x() + pl.y() * p.y() + pl.z() * p.z() + pl.w();
      lo = std::min(lo, v);
      hi = std::max(hi, v);
    }
    any_outside = any_outside || hi < -margin;
    all_inside = all_inside && lo > margin;
  }
}

}  // namespace

Placement place_points(std::span<const Vec3f> positions, const Eigen::Matrix<double, 3, 4>& m, const SetupView& sv) {
  if (positions.empty()) return Placement::Straddles;
  Vec3f lo = positions[0], hi = positions[0];
  bool finite = true;
  for (const Vec3f& p : positions) {
    finite = finite && p.allFinite();
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  if (!finite) return Placement::Straddles;
  Vec3d corners[8];
  double extent = 0;
  for (int k = 0; k < 8; ++k) {
    const Vec3f o((k & 1 ? hi : lo).x(), (k & 2 ? hi : lo).y(), (k & 4 ? hi : lo).z());
    corners[k] = to_view(m, o);
    extent = std::max(extent, corners[k].norm());
  }
  bool outside = false, inside = true;
  test_planes(corners, extent, sv.frustum, sv.frustum_count, outside, inside);
  if (outside) return Placement::Outside;
  bool clip_outside = false, clip_inside = true;
  test_planes(corners, extent, sv.clip, sv.clip_count, clip_outside, clip_inside);
  if (!clip_inside) return Placement::Straddles;
  return inside ? Placement::Inside : Placement::Unclipped;
}

}  // namespace silva::render
