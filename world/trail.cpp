#include "world/trail.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace silva::world {

namespace {
using V2 = Eigen::Vector2d;
}  // namespace

Trail build_trail(const Config& cfg, const TerrainField& field) {
  Trail t;
  t.enabled = cfg.trail.enabled && field.trail != nullptr;
  t.width = cfg.trail.width;
  if (!t.enabled) return t;
  t.path = field.trail;
  std::vector<Vec3d> nav;
  nav.reserve(t.path->centre.size());
  for (const V2& c : t.path->centre) nav.emplace_back(c.x(), c.y(), surface_height(field, c.x(), c.y()));
  t.nav = NavSpline(std::move(nav));
  return t;
}

std::vector<uint32_t> trail_segments_near(const Trail& trail, double xmin, double ymin, double xmax, double ymax,
                                          double pad) {
  std::vector<uint32_t> out;
  if (!trail.enabled) return out;
  const auto& centre = trail.path->centre;
  for (size_t k = 0; k + 1 < centre.size(); ++k) {
    const V2 a = centre[k], b = centre[k + 1];
    if (std::max(a.x(), b.x()) + pad < xmin || std::min(a.x(), b.x()) - pad > xmax) continue;
    if (std::max(a.y(), b.y()) + pad < ymin || std::min(a.y(), b.y()) - pad > ymax) continue;
    out.push_back(uint32_t(k));
  }
  return out;
}

double trail_distance(const Trail& trail, const std::vector<uint32_t>& segments, double x, double y) {
  double best = std::numeric_limits<double>::infinity();
  const V2 p(x, y);
  const auto& centre = trail.path->centre;
  for (uint32_t k : segments) {
    const V2 a = centre[k], ab = centre[k + 1] - a;
    const double len2 = ab.squaredNorm();
    const double t = len2 > 0 ? std::clamp((p - a).dot(ab) / len2, 0.0, 1.0) : 0.0;
    best = std::min(best, (p - (a + t * ab)).norm());
  }
  return best;
}

}  // namespace silva::world
