#include "assets/tree_skeleton.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace silva::assets {

namespace {

constexpr float kDeg = std::numbers::pi_v<float> / 180.0f;

/// Length factor of a first-order branch at position x in the crown (0 = crown base, 1 = top).
float shape_ratio(CrownShape s, float x) {
  switch (s) {
    case CrownShape::Conical: return 0.15f + 0.85f * (1.0f - x);
    case CrownShape::Spherical: return 0.25f + 0.75f * std::sin(std::numbers::pi_v<float> * (0.15f + 0.85f * x));
    case CrownShape::Flame: return std::max(0.15f, x <= 0.6f ? 0.4f + x : 1.0f - 2.0f * (x - 0.6f));
    case CrownShape::Domed: return 0.2f + 0.8f * std::sqrt(std::max(0.0f, 1.0f - x * x));
  }
  return 1.0f;
}

/// Unit direction at fraction t of a branch (the segment containing t).
Vec3f tangent_along(const Branch& b, float t) {
  const size_t segs = b.nodes.size() - 1;
  const size_t i = std::min(segs - 1, size_t(t * float(segs)));
  return (b.nodes[i + 1].p - b.nodes[i].p).normalized();
}

/// Grows one branch polyline from `base` along `dir` with the level's bending and taper.
Branch grow_branch(const LevelParams& lv, Vec3f base, Vec3f dir, float length, float r0, Rng& rng) {
  Branch b;
  b.length = length;
  const int n = std::max(1, lv.segments);
  const float step = length / float(n);
  b.nodes.push_back({base, r0});
  for (int i = 1; i <= n; ++i) {
    Vec3f side, up;
    perpendicular_frame(dir, side, up);  // side horizontal, up towards +z where dir is not vertical
    const float wiggle = lv.curve_var * kDeg * rng.range(-1.0f, 1.0f);
    const float turn = lv.curve * kDeg / float(n);
    dir = (dir + std::tan(turn) * up + std::tan(wiggle) * (rng.uniform() < 0.5f ? side : up) -
           lv.tropism * step * Vec3f::UnitZ())
              .normalized();
    base += step * dir;
    const float t = float(i) / float(n);
    b.nodes.push_back({base, r0 * (1.0f - (1.0f - lv.tip_radius) * t)});
  }
  return b;
}

/// Fractions along a branch and azimuths (rad) of its children, by whorls or alternately.
void child_positions(const LevelParams& lv, Rng& rng, std::vector<float>& ts, std::vector<float>& az) {
  const int w = std::max(1, lv.whorl);
  const int groups = (lv.children + w - 1) / w;
  float azimuth = rng.range(0.0f, 360.0f);
  for (int g = 0, made = 0; g < groups; ++g) {
    const float t = lv.start + (1.0f - lv.start) * (float(g) + rng.range(0.25f, 0.75f)) / float(groups);
    for (int k = 0; k < w && made < lv.children; ++k, ++made) {
      ts.push_back(t);
      az.push_back((azimuth + 360.0f * float(k) / float(w) + rng.range(-12.0f, 12.0f)) * kDeg);
    }
    azimuth += lv.rotate + rng.range(-10.0f, 10.0f);
  }
}

}  // namespace

int Skeleton::count(int level) const {
  return int(std::count_if(branches.begin(), branches.end(), [&](const Branch& b) { return b.level == level; }));
}

TubeNode point_along(const Branch& b, float t) {
  float want = std::clamp(t, 0.0f, 1.0f) * b.length;
  for (size_t i = 1; i < b.nodes.size(); ++i) {
    const float seg = (b.nodes[i].p - b.nodes[i - 1].p).norm();
    if (want <= seg || i + 1 == b.nodes.size()) {
      const float f = seg > 0 ? std::min(1.0f, want / seg) : 0.0f;
      return {b.nodes[i - 1].p + f * (b.nodes[i].p - b.nodes[i - 1].p),
              b.nodes[i - 1].r + f * (b.nodes[i].r - b.nodes[i - 1].r)};
    }
    want -= seg;
  }
  return b.nodes.back();
}

Skeleton grow_skeleton(const SkeletonParams& p, Rng& rng) {
  Skeleton s;
  const Vec3f lean(rng.range(-0.03f, 0.03f), rng.range(-0.03f, 0.03f), 1.0f);
  s.branches.push_back(grow_branch(p.levels[0], Vec3f::Zero(), lean.normalized(), p.height, p.base_radius, rng));
  for (size_t i = 0; i < s.branches.size(); ++i) {
    const int level = s.branches[i].level;
    if (level + 1 >= int(p.levels.size())) continue;
    const LevelParams& own = p.levels[size_t(level)];
    const LevelParams& lv = p.levels[size_t(level) + 1];
    std::vector<float> ts, az;
    child_positions(own, rng, ts, az);
    for (size_t c = 0; c < ts.size(); ++c) {
      const Branch& parent = s.branches[i];
      const float t = ts[c];
      const float x = (t - own.start) / std::max(1e-3f, 1.0f - own.start);
      const float ratio = level == 0 ? shape_ratio(p.shape, x) : 1.0f - lv.apical * t;
      const float length = parent.length * lv.length * ratio * (1.0f + lv.length_var * rng.range(-1.0f, 1.0f));
      if (length < 0.05f) continue;
      const TubeNode at = point_along(parent, t);
      const float r = std::min(0.9f * at.r, at.r * std::pow(length / parent.length, p.radius_power));
      const Vec3f along = tangent_along(parent, t);
      Vec3f side, up;
      perpendicular_frame(along, side, up);
      const float down = (lv.down + (lv.down_tip - lv.down) * t + lv.down_var * rng.range(-1.0f, 1.0f)) * kDeg;
      const Vec3f radial = std::cos(az[c]) * side + std::sin(az[c]) * up;
      Branch child = grow_branch(lv, at.p, std::cos(down) * along + std::sin(down) * radial, length, r, rng);
      child.parent = int(i);
      child.level = level + 1;
      child.parent_t = t;
      s.branches.push_back(std::move(child));
    }
  }
  return s;
}

}  // namespace silva::assets
