#include "world/trail.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "core/error.hpp"
#include "core/rng.hpp"

namespace silva::world {

namespace {

using V2 = Eigen::Vector2d;
constexpr double kPi = 3.14159265358979323846;

/// Reflects a coordinate into [-limit, limit], flipping the heading component when it bounces.
void reflect(double& x, double& dir, double limit) {
  while (x > limit || x < -limit) {
    x = x > limit ? 2.0 * limit - x : -2.0 * limit - x;
    dir = -dir;
  }
}

/// Chunk coordinate containing world (x, y).
ChunkCoord chunk_of(double x, double y, double s) {
  return ChunkCoord{int32_t(std::floor(x / s)), int32_t(std::floor(y / s))};
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

Trail build_trail(const Config& cfg, const TerrainField& field) {
  Trail t;
  t.enabled = cfg.trail.enabled;
  t.width = cfg.trail.width;
  if (!t.enabled) return t;
  t.control = trail_control_points(cfg);
  t.centre = catmull_rom_centripetal(t.control, kTrailResample);
  const size_t n = t.centre.size();
  std::vector<Vec3d> nav(n);
  t.lateral.resize(n * kTrailLateralSamples);
  for (size_t k = 0; k < n; ++k) {
    const V2 a = t.centre[k > 0 ? k - 1 : k], b = t.centre[k + 1 < n ? k + 1 : k];
    V2 dir = b - a;
    const double len = dir.norm();
    dir = len > 0 ? V2(dir / len) : V2(1, 0);
    const V2 right(dir.y(), -dir.x());
    const V2 c = t.centre[k];
    nav[k] = Vec3d(c.x(), c.y(), surface_height(field, c.x(), c.y()));
    for (int q = 0; q < kTrailLateralSamples; ++q) {
      // Offsets run symmetrically from -w/2 (left) to +w/2 (right).
      const double off = t.width * (double(q) / (kTrailLateralSamples - 1) - 0.5);
      const V2 p = c + off * right;
      t.lateral[k * kTrailLateralSamples + q] =
          Vec3f(float(p.x()), float(p.y()), surface_height(field, p.x(), p.y()) + kTrailLift);
    }
  }
  t.nav = NavSpline(std::move(nav));
  return t;
}

Mesh build_trail_mesh(const Trail& trail, double chunk_size, ChunkCoord coord) {
  Mesh m;
  if (!trail.enabled) return m;
  const size_t n = trail.centre.size();
  const auto& cum = trail.nav.cumulative();
  size_t k = 0;
  while (k + 1 < n) {
    auto owned = [&](size_t s) {
      const V2 mid = 0.5 * (trail.centre[s] + trail.centre[s + 1]);
      return chunk_of(mid.x(), mid.y(), chunk_size) == coord;
    };
    if (!owned(k)) {
      ++k;
      continue;
    }
    size_t end = k;  // run of owned segments [k, end)
    while (end + 1 < n && owned(end)) ++end;
    const uint32_t base = uint32_t(m.positions.size());
    for (size_t r = k; r <= end; ++r) {
      for (int q = 0; q < kTrailLateralSamples; ++q) {
        m.positions.push_back(trail.lateral[r * kTrailLateralSamples + q]);
        m.normals.push_back(Vec3f::UnitZ());
        m.uvs.emplace_back(float(q) / (kTrailLateralSamples - 1), float(cum[r]));
      }
    }
    for (size_t r = 0; r < end - k; ++r) {
      for (int q = 0; q + 1 < kTrailLateralSamples; ++q) {
        // Lateral index grows to the right of travel; rows grow forward: CCW seen from above.
        const uint32_t a = base + uint32_t(r * kTrailLateralSamples + q), b = a + 1;
        const uint32_t c = a + kTrailLateralSamples, d = b + kTrailLateralSamples;
        m.indices.insert(m.indices.end(), {a, b, d, a, d, c});
      }
    }
    k = end;
  }
  if (m.indices.empty()) return Mesh{};
  m.compute_normals();
  MeshPart part;
  part.index_count = uint32_t(m.indices.size());
  part.role = Role::Trail;
  part.material = Material::Trail;
  m.parts.push_back(part);
  return m;
}

std::vector<uint32_t> trail_segments_near(const Trail& trail, double xmin, double ymin, double xmax, double ymax,
                                          double pad) {
  std::vector<uint32_t> out;
  if (!trail.enabled) return out;
  for (size_t k = 0; k + 1 < trail.centre.size(); ++k) {
    const V2 a = trail.centre[k], b = trail.centre[k + 1];
    if (std::max(a.x(), b.x()) + pad < xmin || std::min(a.x(), b.x()) - pad > xmax) continue;
    if (std::max(a.y(), b.y()) + pad < ymin || std::min(a.y(), b.y()) - pad > ymax) continue;
    out.push_back(uint32_t(k));
  }
  return out;
}

double trail_distance(const Trail& trail, const std::vector<uint32_t>& segments, double x, double y) {
  double best = std::numeric_limits<double>::infinity();
  const V2 p(x, y);
  for (uint32_t k : segments) {
    const V2 a = trail.centre[k], ab = trail.centre[k + 1] - a;
    const double len2 = ab.squaredNorm();
    const double t = len2 > 0 ? std::clamp((p - a).dot(ab) / len2, 0.0, 1.0) : 0.0;
    best = std::min(best, (p - (a + t * ab)).norm());
  }
  return best;
}

}  // namespace silva::world
