#include "render/clip.hpp"

namespace silva::render {

namespace {

/// Signed distance-like value of p against a plane (inside when >= 0).
double plane_value(const Vec4d& plane, const Vec3d& p) {
  return plane.x() * p.x() + plane.y() * p.y() + plane.z() * p.z() + plane.w();
}

/// Lexicographic order of points, used to orient an edge before intersecting it.
bool point_less(const Vec3d& a, const Vec3d& b) {
  if (a.x() != b.x()) return a.x() < b.x();
  if (a.y() != b.y()) return a.y() < b.y();
  return a.z() < b.z();
}

/// Where segment a-b crosses the plane, independent of the segment's direction.
Vec3d crossing(const Vec4d& plane, Vec3d a, Vec3d b) {
  if (point_less(b, a)) std::swap(a, b);
  const double da = plane_value(plane, a), db = plane_value(plane, b);
  const double t = da / (da - db);
  return a + t * (b - a);
}

/// Clips a polygon against one plane into `out` (room for 2n); returns the new vertex count.
int clip_against(const Vec4d& plane, const Vec3d* in, int n, Vec3d* out) {
  int m = 0;
  for (int i = 0; i < n; ++i) {
    const Vec3d& a = in[i];
    const Vec3d& b = in[(i + 1) % n];
    const bool a_in = plane_value(plane, a) >= 0.0;
    const bool b_in = plane_value(plane, b) >= 0.0;
    if (a_in) out[m++] = a;
    if (a_in != b_in) out[m++] = crossing(plane, a, b);
  }
  return m;
}

}  // namespace

int clip_polygon(const Vec4d* planes, int plane_count, Vec3d* poly, int n) {
  Vec3d tmp[2 * kMaxClippedVertices];
  for (int k = 0; k < plane_count && n > 0; ++k) {
    bool all_in = true;
    for (int i = 0; i < n; ++i) all_in = all_in && plane_value(planes[k], poly[i]) >= 0.0;
    if (all_in) continue;
    n = clip_against(planes[k], poly, n, tmp);
    if (n > kMaxClippedVertices) return 0;  // only a numerically degenerate sliver gets here
    for (int i = 0; i < n; ++i) poly[i] = tmp[i];
  }
  return n < 3 ? 0 : n;
}

}  // namespace silva::render
