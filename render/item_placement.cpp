#include "render/item_placement.hpp"

#include <algorithm>
#include <cmath>

namespace silva::render {

namespace {

/// Relative margin that covers the rounding between a box corner's plane value and a vertex's.
constexpr double kPlacementMargin = 1e-9;

/// Where eight view-space corners lie against a set of planes.
struct PlaneVerdict {
  bool outside = false;  ///< All corners behind one plane.
  bool inside = true;    ///< All corners in front of every plane.
};

/// The verdict of the eight view-space corners `c` (at most `extent` from the eye) against
/// `count` planes, each with a margin covering rounding.
PlaneVerdict test_planes(const Vec3d (&c)[8], double extent, const Vec4d* planes, int count) {
  PlaneVerdict verdict;
  for (int k = 0; k < count; ++k) {
    const Vec4d& pl = planes[k];
    const double margin = kPlacementMargin * (std::abs(pl.w()) + pl.head<3>().norm() * extent);
    double lo = INFINITY, hi = -INFINITY;
    for (const Vec3d& p : c) {
      const double v = pl.x() * p.x() + pl.y() * p.y() + pl.z() * p.z() + pl.w();
      lo = std::min(lo, v);
      hi = std::max(hi, v);
    }
    verdict.outside = verdict.outside || hi < -margin;
    verdict.inside = verdict.inside && lo > margin;
  }
  return verdict;
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
  const PlaneVerdict frustum = test_planes(corners, extent, sv.frustum, sv.frustum_count);
  if (frustum.outside) return Placement::Outside;
  if (!test_planes(corners, extent, sv.clip, sv.clip_count).inside) return Placement::Straddles;
  return frustum.inside ? Placement::Inside : Placement::Unclipped;
}

}  // namespace silva::render
