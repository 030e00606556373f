#include <cmath>
#include <numbers>

#include "assets/generators.hpp"
#include "assets/strips.hpp"
#include "assets/shrub_parts.hpp"

namespace silva::assets {

namespace {

/// A stick lying on the ground from `start` along azimuth `az`: `nodes` points that wander
/// sideways and sag onto the ground, radius r0 tapering to r1.
StemNodes lying_stick(Rng& rng, const Vec3f& start, float az, float len, float r0, float r1, int nodes) {
  StemNodes out;
  Vec3f p = start;
  for (int i = 0; i < nodes; ++i) {
    const float f = float(i) / float(nodes - 1);
    out.push_back({p + Vec3f(0, 0, r0 + (r1 - r0) * f), r0 + (r1 - r0) * f});
    az += rng.range(-0.35f, 0.35f);
    p += len / float(nodes - 1) * horizontal(az) + Vec3f(0, 0, rng.range(-0.2f, 0.6f) * r0);
  }
  return out;
}

/// Side twigs forking off `stem` along the ground, as thin ribbons.
void add_side_twigs(std::vector<StemNodes>& out, Rng& rng, const StemNodes& stem, float len, float r, int count) {
  for (int i = 0; i < count; ++i) {
    const Vec3f at = stem_point(stem, rng.range(0.2f, 0.85f));
    const Vec3f along = stem.back().p - stem.front().p;
    const float az = std::atan2(along.y(), along.x()) + (rng.uniform() < 0.5f ? 1.0f : -1.0f) * rng.range(0.4f, 1.0f);
    StemNodes twig = lying_stick(rng, at - Vec3f(0, 0, r), az, len * rng.range(0.25f, 0.5f), r, 0.4f * r, 3);
    out.push_back(std::move(twig));
  }
}

/// Lying stick of length `len` and base radius `r` with side twigs, centred on the origin.
GeneratedAsset stick(Rng& rng, float len, float r, int side_twigs) {
  const float az = rng.range(0.0f, 2.0f * std::numbers::pi_v<float>);
  const Vec3f start = -0.5f * len * horizontal(az) - Vec3f(0, 0, 0.3f * r);
  std::vector<StemNodes> sticks = {lying_stick(rng, start, az, len, r, 0.5f * r, 4)};
  const StemNodes main = sticks.front();
  add_side_twigs(sticks, rng, main, len, 0.5f * r, side_twigs);
  MeshBuilder b;
  add_stems(b, sticks, Role::Ground, Material::LogBark);
  return {b.finish(), Role::Ground, CollisionProxy{}};
}

}  // namespace

GeneratedAsset generate_twig(Rng& rng) {
  const float len = rng.range(0.15f, 0.4f);
  return stick(rng, len, rng.range(0.003f, 0.008f), int(rng.below(4)));
}

GeneratedAsset generate_fallen_branch(Rng& rng) {
  const float len = rng.range(0.28f, 0.42f);
  return stick(rng, len, rng.range(0.015f, 0.03f), 1 + int(rng.below(3)));
}

}  // namespace silva::assets
