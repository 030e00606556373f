#include <algorithm>
#include <cmath>
#include <numbers>

#include "assets/generators.hpp"
#include "assets/strips.hpp"
#include "assets/shrub_parts.hpp"
#include "assets/understory_masks.hpp"

namespace silva::assets {

namespace {

/// A hazel stem from the stool: rises at `lean` (radians from vertical) along azimuth `az`,
/// curving outward near the top; base radius r.
StemNodes hazel_stem(Rng& rng, float height, float az, float lean, float r) {
  const Vec3f base = rng.range(0.02f, 0.12f) * horizontal(az) - Vec3f(0, 0, 0.02f);
  const float h = height * rng.range(0.7f, 1.0f);
  const Vec3f out = horizontal(az);
  const Vec3f tip = base + h * (std::cos(lean) * Vec3f::UnitZ() + std::sin(lean) * out) + 0.1f * h * out;
  const Vec3f ctrl = base + 0.55f * h * std::cos(lean) * Vec3f::UnitZ() + 0.25f * h * std::sin(lean) * out;
  return bent_stem(base, ctrl, tip, r, 0.003f, 4);
}

/// A side branch leaving `stem` at fraction t, heading outward and up.
StemNodes hazel_branch(Rng& rng, const StemNodes& stem, float t, float height, float az) {
  const Vec3f start = stem_point(stem, t);
  const float len = height * rng.range(0.2f, 0.35f) * (1.2f - 0.5f * t);
  const Vec3f dir = (horizontal(az + rng.range(-1.2f, 1.2f)) + Vec3f(0, 0, rng.range(0.2f, 0.9f))).normalized();
  const Vec3f tip = start + len * dir - Vec3f(0, 0, 0.15f * len);
  return bent_stem(start, start + 0.5f * len * dir, tip, 0.008f, 0.002f, 2);
}

}  // namespace

GeneratedAsset generate_hazel(Rng& rng) {
  constexpr float kPi = std::numbers::pi_v<float>;
  const float height = rng.range(2.0f, 5.0f);
  const int count = 5 + int(rng.below(7));
  std::vector<StemNodes> stems, branches;
  for (int i = 0; i < count; ++i) {
    const float az = 2.0f * kPi * (float(i) + rng.range(-0.4f, 0.4f)) / float(count);
    stems.push_back(hazel_stem(rng, height, az, rng.range(0.08f, 0.4f), rng.range(0.015f, 0.04f)));
    const int n = 4 + int(rng.below(3));
    for (int k = 0; k < n; ++k) branches.push_back(hazel_branch(rng, stems.back(), rng.range(0.35f, 0.9f), height, az));
  }
  float reach = 0;
  for (const auto* group : {&stems, &branches})
    for (const StemNodes& s : *group) reach = std::max(reach, s.back().p.head<2>().norm());
  std::vector<StemNodes> all = stems;
  all.insert(all.end(), branches.begin(), branches.end());
  MeshBuilder b;
  add_stems(b, all, Role::Shrub, Material::BarkBroadleaf);
  b.begin_part(Role::Shrub, Material::ShrubLeaves, hazel_leaves_mask(), true);
  const float half = rng.range(0.15f, 0.2f) * std::sqrt(height / 3.0f);
  for (const StemNodes& s : all) {
    const int cards = s.size() > 3 ? 16 : 12;
    for (int k = 0; k < cards; ++k) {
      const Vec3f c = stem_point(s, rng.range(0.3f, 1.0f)) + 0.5f * half * random_direction(rng);
      const Vec3f facing = Vec3f(0, 0, 1.2f) + Vec3f(c.x(), c.y(), 0).normalized();
      add_leaf_card(b, rng, c, facing, 0.9f, half);
    }
  }
  return {b.finish(), Role::Shrub, cylinder_proxy(0.5f * reach, height)};
}

}  // namespace silva::assets
