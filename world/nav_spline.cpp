#include "world/nav_spline.hpp"

#include <algorithm>
#include <cmath>

namespace silva::world {

NavSpline::NavSpline(std::vector<Vec3d> points) : points_(std::move(points)) {
  cumulative_.resize(points_.size(), 0.0);
  for (size_t k = 1; k < points_.size(); ++k)
    cumulative_[k] = cumulative_[k - 1] + (points_[k] - points_[k - 1]).norm();
}

size_t NavSpline::segment(double s) const {
  if (points_.size() < 2) return 0;
  const auto it = std::upper_bound(cumulative_.begin(), cumulative_.end(), s);
  const size_t k = size_t(std::max<ptrdiff_t>(it - cumulative_.begin(), 1)) - 1;
  return std::min(k, points_.size() - 2);
}

Vec3d NavSpline::position(double s) const {
  if (points_.empty()) return Vec3d::Zero();
  if (points_.size() == 1) return points_[0];
  s = std::clamp(s, 0.0, length());
  const size_t k = segment(s);
  const double len = cumulative_[k + 1] - cumulative_[k];
  const double t = len > 0 ? (s - cumulative_[k]) / len : 0.0;
  return points_[k] + t * (points_[k + 1] - points_[k]);
}

Vec3d NavSpline::tangent(double s) const {
  if (points_.size() < 2) return Vec3d::UnitX();
  size_t k = segment(std::clamp(s, 0.0, length()));
  // Skip zero-length segments forward, then backward.
  size_t f = k;
  while (f + 1 < points_.size() - 1 && (points_[f + 1] - points_[f]).squaredNorm() == 0) ++f;
  while (k > 0 && (points_[k + 1] - points_[k]).squaredNorm() == 0) --k;
  const Vec3d d = (points_[f + 1] - points_[f]).squaredNorm() > 0 ? points_[f + 1] - points_[f]
                                                                   : points_[k + 1] - points_[k];
  const double n = d.norm();
  return n > 0 ? Vec3d(d / n) : Vec3d::UnitX();
}

std::vector<Eigen::Vector2d> catmull_rom_centripetal(const std::vector<Eigen::Vector2d>& c, int per_segment) {
  using V = Eigen::Vector2d;
  if (c.size() < 2) return c;
  std::vector<V> out;
  out.reserve((c.size() - 1) * size_t(per_segment) + 1);
  auto knot = [](const V& a, const V& b) { return std::max(std::sqrt((b - a).norm()), 1e-6); };
  for (size_t k = 0; k + 1 < c.size(); ++k) {
    const V &p1 = c[k], &p2 = c[k + 1];
    const V p0 = k > 0 ? c[k - 1] : V(2.0 * p1 - p2);
    const V p3 = k + 2 < c.size() ? c[k + 2] : V(2.0 * p2 - p1);
    const double t0 = 0, t1 = t0 + knot(p0, p1), t2 = t1 + knot(p1, p2), t3 = t2 + knot(p2, p3);
    for (int q = 0; q < per_segment; ++q) {
      const double t = t1 + (t2 - t1) * double(q) / per_segment;
      // Barry-Goldman pyramid.
      const V a1 = ((t1 - t) * p0 + (t - t0) * p1) / (t1 - t0);
      const V a2 = ((t2 - t) * p1 + (t - t1) * p2) / (t2 - t1);
      const V a3 = ((t3 - t) * p2 + (t - t2) * p3) / (t3 - t2);
      const V b1 = ((t2 - t) * a1 + (t - t0) * a2) / (t2 - t0);
      const V b2 = ((t3 - t) * a2 + (t - t1) * a3) / (t3 - t1);
      out.push_back(((t2 - t) * b1 + (t - t1) * b2) / (t2 - t1));
    }
  }
  out.push_back(c.back());
  return out;
}

}  // namespace silva::world
