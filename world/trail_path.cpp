#include "world/trail_path.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/error.hpp"
#include "core/rng.hpp"
#include "world/nav_spline.hpp"

namespace silva::world {

namespace {

using V2 = Eigen::Vector2d;
constexpr double kPi = 3.14159265358979323846;
/// Most grid cells along one axis (the cell grows for longer trails).
constexpr double kMaxGridCells = 1024.0;

/// Reflects a coordinate into [-limit, limit], flipping the heading component when it bounces.
void reflect(double& x, double& dir, double limit) {
  while (x > limit || x < -limit) {
    x = x > limit ? 2.0 * limit - x : -2.0 * limit - x;
    dir = -dir;
  }
}

/// Natural heights along the centre line averaged over +-kTrailBedSmoothing of arc length.
std::vector<double> smoothed_bed(const TrailPath& p, const std::vector<double>& natural) {
  const size_t n = natural.size();
  std::vector<double> prefix(n + 1, 0.0);
  for (size_t k = 0; k < n; ++k) prefix[k + 1] = prefix[k] + natural[k];
  std::vector<double> bed(n);
  size_t lo = 0, hi = 0;  // window [lo, hi) of samples within the smoothing distance
  for (size_t k = 0; k < n; ++k) {
    while (p.along[k] - p.along[lo] > kTrailBedSmoothing) ++lo;
    while (hi < n && p.along[hi] - p.along[k] <= kTrailBedSmoothing) ++hi;
    bed[k] = (prefix[hi] - prefix[lo]) / double(hi - lo);
  }
  return bed;
}

/// Fills the segment grid: every segment is listed in each cell its box, padded by query_radius(), meets.
void build_grid(TrailPath& p) {
  const double pad = p.query_radius();
  V2 lo = p.centre[0], hi = p.centre[0];
  for (const V2& c : p.centre) lo = lo.cwiseMin(c), hi = hi.cwiseMax(c);
  lo -= V2(pad, pad);
  hi += V2(pad, pad);
  p.cell = std::max(p.cell, (hi - lo).maxCoeff() / kMaxGridCells);
  p.grid_x0 = lo.x();
  p.grid_y0 = lo.y();
  p.grid_nx = int(std::floor((hi.x() - lo.x()) / p.cell)) + 1;
  p.grid_ny = int(std::floor((hi.y() - lo.y()) / p.cell)) + 1;
  std::vector<std::vector<uint32_t>> cells(size_t(p.grid_nx) * size_t(p.grid_ny));
  for (size_t k = 0; k + 1 < p.centre.size(); ++k) {
    const V2 a = p.centre[k].cwiseMin(p.centre[k + 1]), b = p.centre[k].cwiseMax(p.centre[k + 1]);
    const int x0 = int(std::floor((a.x() - pad - p.grid_x0) / p.cell)), x1 = int(std::floor((b.x() + pad - p.grid_x0) / p.cell));
    const int y0 = int(std::floor((a.y() - pad - p.grid_y0) / p.cell)), y1 = int(std::floor((b.y() + pad - p.grid_y0) / p.cell));
    for (int y = std::max(y0, 0); y <= std::min(y1, p.grid_ny - 1); ++y)
      for (int x = std::max(x0, 0); x <= std::min(x1, p.grid_nx - 1); ++x)
        cells[size_t(y) * size_t(p.grid_nx) + size_t(x)].push_back(uint32_t(k));
  }
  p.cell_start.assign(1, 0);
  for (const auto& c : cells) {
    p.cell_segments.insert(p.cell_segments.end(), c.begin(), c.end());
    p.cell_start.push_back(uint32_t(p.cell_segments.size()));
  }
}

}  // namespace

std::vector<V2> trail_control_points(const Config& cfg) {
  const double limit = 0.5 * cfg.world.extent - kTrailEdgeInset;
  if (limit <= 0)
    throw InputError("world.extent = " + std::to_string(cfg.world.extent) + ": with trail.enabled the capture " +
                     "region must be wider than " + std::to_string(2 * kTrailEdgeInset) + " m");
  Rng rng(uint64_t(cfg.seed), 0, Purpose::TrailWalk);
  std::vector<V2> pts;
  pts.reserve(size_t(std::max(cfg.trail.control_points, 2)));
  V2 p(0, 0);
  double heading = 2.0 * kPi * rng.uniform_double();
  pts.push_back(p);
  for (int k = 1; k < std::max(cfg.trail.control_points, 2); ++k) {
    heading += rng.normal(0.0f, 0.5f);  // gentle bends, ~30 degrees per step
    V2 d(std::cos(heading), std::sin(heading));
    p += cfg.trail.control_spacing * d;
    reflect(p.x(), d.x(), limit);
    reflect(p.y(), d.y(), limit);
    heading = std::atan2(d.y(), d.x());
    pts.push_back(p);
  }
  return pts;
}

TrailPath make_trail_path(const Config& cfg, const std::function<double(double, double)>& natural_height) {
  TrailPath p;
  p.half_width = 0.5 * cfg.trail.width;
  p.control = trail_control_points(cfg);
  p.centre = catmull_rom_centripetal(p.control, kTrailResample);
  const size_t n = p.centre.size();
  p.along.assign(n, 0.0);
  std::vector<double> natural(n);
  for (size_t k = 0; k < n; ++k) {
    if (k > 0) p.along[k] = p.along[k - 1] + (p.centre[k] - p.centre[k - 1]).norm();
    natural[k] = natural_height(p.centre[k].x(), p.centre[k].y());
  }
  p.bed = smoothed_bed(p, natural);
  build_grid(p);
  return p;
}

TrailPoint nearest_trail_point(const TrailPath& path, double x, double y) {
  TrailPoint out;
  const double fx = std::floor((x - path.grid_x0) / path.cell), fy = std::floor((y - path.grid_y0) / path.cell);
  if (!(fx >= 0 && fy >= 0 && fx < path.grid_nx && fy < path.grid_ny)) return out;
  const size_t c = size_t(fy) * size_t(path.grid_nx) + size_t(fx);
  const V2 q(x, y);
  double best2 = path.query_radius() * path.query_radius();
  for (uint32_t i = path.cell_start[c]; i < path.cell_start[c + 1]; ++i) {
    const uint32_t k = path.cell_segments[i];
    const V2 a = path.centre[k], ab = path.centre[k + 1] - a;
    const double len2 = ab.squaredNorm();
    const double t = len2 > 0 ? std::clamp((q - a).dot(ab) / len2, 0.0, 1.0) : 0.0;
    const double d2 = (q - (a + t * ab)).squaredNorm();
    if (d2 >= best2) continue;
    best2 = d2;
    out.distance = std::sqrt(d2);
    out.along = path.along[k] + t * (path.along[k + 1] - path.along[k]);
    out.bed = path.bed[k] + t * (path.bed[k + 1] - path.bed[k]);
  }
  return out;
}

double shaped_height(const TrailPath& path, const TrailPoint& p, double natural) {
  if (!(p.distance < path.reach())) return natural;
  const double r = p.distance / path.half_width;
  const double target = r < 1.0 ? p.bed - kTrailWear * (1.0 - r * r) : p.bed;
  const double u = std::clamp((p.distance - path.half_width) / kTrailShoulder, 0.0, 1.0);
  const double keep = u * u * (3.0 - 2.0 * u);  // share of the natural height
  return target + keep * (natural - target);
}

}  // namespace silva::world
