#include "world/chunk_regions.hpp"

#include <algorithm>
#include <cmath>

namespace silva::world {

namespace {

using V2 = Eigen::Vector2d;

/// Distance from interval [lo, hi] to the interval [a, b] (0 when they overlap).
double gap(double lo, double hi, double a, double b) { return std::max({0.0, a - hi, lo - b}); }

/// Convex hull (counter-clockwise, Andrew's monotone chain) of points.
std::vector<V2> convex_hull(std::vector<V2> p) {
  std::sort(p.begin(), p.end(), [](const V2& a, const V2& b) { return a.x() != b.x() ? a.x() < b.x() : a.y() < b.y(); });
  if (p.size() < 3) return p;
  auto cross = [](const V2& o, const V2& a, const V2& b) {
    return (a.x() - o.x()) * (b.y() - o.y()) - (a.y() - o.y()) * (b.x() - o.x());
  };
  std::vector<V2> h(2 * p.size());
  size_t k = 0;
  for (size_t i = 0; i < p.size(); ++i) {
    while (k >= 2 && cross(h[k - 2], h[k - 1], p[i]) <= 0) --k;
    h[k++] = p[i];
  }
  for (size_t i = p.size() - 1, t = k + 1; i-- > 0;) {
    while (k >= t && cross(h[k - 2], h[k - 1], p[i]) <= 0) --k;
    h[k++] = p[i];
  }
  h.resize(k - 1);
  return h;
}

/// True when the open square [x0, x1] x [y0, y1] and the convex polygon overlap with positive
/// area (separating axis test over the box axes and the polygon's edge normals).
bool box_meets_polygon(double x0, double y0, double x1, double y1, const std::vector<V2>& poly) {
  const V2 corners[4] = {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
  auto separated = [&](const V2& axis) {
    double pmin = INFINITY, pmax = -INFINITY, bmin = INFINITY, bmax = -INFINITY;
    for (const V2& q : poly) pmin = std::min(pmin, axis.dot(q)), pmax = std::max(pmax, axis.dot(q));
    for (const V2& q : corners) bmin = std::min(bmin, axis.dot(q)), bmax = std::max(bmax, axis.dot(q));
    return pmax <= bmin || bmax <= pmin;
  };
  if (separated(V2(1, 0)) || separated(V2(0, 1))) return false;
  for (size_t k = 0; k < poly.size(); ++k) {
    const V2 e = poly[(k + 1) % poly.size()] - poly[k];
    if (separated(V2(-e.y(), e.x()))) return false;
  }
  return true;
}

}  // namespace

std::vector<ChunkCoord> ring_neighbours(const std::vector<ChunkCoord>& coords, int ring) {
  std::vector<ChunkCoord> out;
  for (ChunkCoord c : coords)
    for (int dj = -ring; dj <= ring; ++dj)
      for (int di = -ring; di <= ring; ++di)
        if (di != 0 || dj != 0) out.push_back(ChunkCoord{c.i + di, c.j + dj});
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

double distance_to_chunk(ChunkCoord c, double s, double x, double y) {
  const double dx = gap(c.i * s, (c.i + 1) * s, x, x), dy = gap(c.j * s, (c.j + 1) * s, y, y);
  return std::sqrt(dx * dx + dy * dy);
}

std::vector<ChunkCoord> chunks_in_disc(double cx, double cy, double r, double s) {
  std::vector<ChunkCoord> out;
  const int i0 = int(std::floor((cx - r) / s)), i1 = int(std::floor((cx + r) / s));
  const int j0 = int(std::floor((cy - r) / s)), j1 = int(std::floor((cy + r) / s));
  for (int i = i0; i <= i1; ++i)
    for (int j = j0; j <= j1; ++j)
      if (distance_to_chunk(ChunkCoord{i, j}, s, cx, cy) < r) out.push_back(ChunkCoord{i, j});
  return out;
}

std::vector<ChunkCoord> default_world_chunks(const Config& cfg) {
  const double s = cfg.terrain.chunk_size, h = 0.5 * cfg.world.extent, r = cfg.world.render_distance;
  std::vector<ChunkCoord> out;
  const int lo = int(std::floor((-h - r) / s)), hi = int(std::floor((h + r) / s));
  for (int i = lo; i <= hi; ++i)
    for (int j = lo; j <= hi; ++j) {
      const double dx = gap(i * s, (i + 1) * s, -h, h), dy = gap(j * s, (j + 1) * s, -h, h);
      if (std::sqrt(dx * dx + dy * dy) < r) out.push_back(ChunkCoord{i, j});
    }
  return out;
}

std::vector<ChunkCoord> chunks_in_view(const Camera& cam, double s) {
  const Mat3d R = cam.camera_to_world.block<3, 3>(0, 0);
  const Vec3d C = cam.position();
  std::vector<V2> pts;
  for (double z : {cam.near, cam.far})
    for (double u : {0.0, double(cam.width)})
      for (double v : {0.0, double(cam.height)}) {
        const Vec3d d((u - cam.cx) / cam.fx, (v - cam.cy) / cam.fy, 1.0);
        const Vec3d p = C + R * (d * z);
        pts.emplace_back(p.x(), p.y());
      }
  std::vector<V2> hull = convex_hull(pts);
  double x0 = INFINITY, x1 = -INFINITY, y0 = INFINITY, y1 = -INFINITY;
  for (const V2& p : pts) x0 = std::min(x0, p.x()), x1 = std::max(x1, p.x()), y0 = std::min(y0, p.y()), y1 = std::max(y1, p.y());
  std::vector<ChunkCoord> out;
  if (hull.size() < 3) {  // degenerate (looking straight down a vertical line): the bounding box
    hull = {V2(x0, y0), V2(x1, y0), V2(x1, y1), V2(x0, y1)};
  }
  for (int i = int(std::floor(x0 / s)); i <= int(std::floor(x1 / s)); ++i)
    for (int j = int(std::floor(y0 / s)); j <= int(std::floor(y1 / s)); ++j)
      if (box_meets_polygon(i * s, j * s, (i + 1) * s, (j + 1) * s, hull)) out.push_back(ChunkCoord{i, j});
  return out;
}

std::vector<ChunkCoord> chunks_for_view(const Camera& camera, double chunk_size, double shadow_reach) {
  std::vector<ChunkCoord> coords = chunks_in_view(camera, chunk_size);
  const Vec3d p = camera.position();
  for (ChunkCoord c : chunks_in_disc(p.x(), p.y(), shadow_reach, chunk_size))
    if (std::find(coords.begin(), coords.end(), c) == coords.end()) coords.push_back(c);
  std::sort(coords.begin(), coords.end());
  return coords;
}

}  // namespace silva::world
