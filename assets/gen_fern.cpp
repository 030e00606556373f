#include <algorithm>
#include <cmath>
#include <numbers>

#include "assets/generators.hpp"
#include "assets/strips.hpp"
#include "assets/understory_masks.hpp"

namespace silva::assets {

namespace {

constexpr float kPi = std::numbers::pi_v<float>;

/// A frond's rachis for unit length: leaves the crown at elevation `rise` (radians above
/// horizontal) and bends down by `droop` towards the tip, heading along azimuth `az`.
std::vector<Vec3f> unit_rachis(float az, float rise, float droop) {
  std::vector<Vec3f> pts = {Vec3f::Zero()};
  const Vec3f out = horizontal(az);
  for (int i = 0; i < kFrondSegments; ++i) {
    const float f = (float(i) + 0.5f) / float(kFrondSegments);
    const float el = rise - droop * f * f;  // the tip bends most
    pts.push_back(pts.back() + (std::cos(el) * out + Vec3f(0, 0, std::sin(el))) / float(kFrondSegments));
  }
  return pts;
}

/// Size class: height range (m) and frond count range.
struct FernClass {
  float min_h, max_h;
  int min_fronds, max_fronds;
};
constexpr FernClass kClasses[] = {{0.18f, 0.4f, 5, 8}, {0.4f, 0.7f, 6, 10}, {0.7f, 1.05f, 8, 12}};

/// One frond of a fern: its grown rachis for unit length, length (m) and the roll of its blade.
struct Frond {
  std::vector<Vec3f> rachis;
  float len, roll, az;
};

/// A fern's fronds at their grown size and the blade's half width per metre of frond.
struct FernPlan {
  std::vector<Frond> fronds;
  float width_ratio;
};

/// Draws a fern: size class, height, fronds (their arching and length scaled so the tallest grown
/// frond reaches the drawn height).
FernPlan plan_fern(Rng& rng) {
  const FernClass& cls = kClasses[rng.below(3)];
  const float height = rng.range(cls.min_h, cls.max_h);
  const int fronds = cls.min_fronds + int(rng.below(uint32_t(cls.max_fronds - cls.min_fronds + 1)));
  const float rise = rng.range(45.0f, 70.0f) * kPi / 180.0f, droop = rng.range(55.0f, 100.0f) * kPi / 180.0f;
  FernPlan plan{{}, rng.range(0.11f, 0.15f)};
  float top = 0;
  for (int i = 0; i < fronds; ++i) {
    Frond f;
    f.az = 2.0f * kPi * (float(i) + rng.range(-0.3f, 0.3f)) / float(fronds);
    f.len = rng.range(0.7f, 1.0f);
    f.roll = rng.range(-0.35f, 0.35f);
    f.rachis = unit_rachis(f.az, rise + rng.range(-0.2f, 0.15f), droop * rng.range(0.8f, 1.25f));
    for (const Vec3f& p : f.rachis) top = std::max(top, f.len * p.z());
    plan.fronds.push_back(std::move(f));
  }
  for (Frond& f : plan.fronds) f.len *= height / top;  // the tallest point of the tallest frond is the fern's height
  return plan;
}

/// The direction across a frond's blade: horizontal, square to its azimuth, rolled by `roll`.
Vec3f blade_side(const Frond& f) {
  return std::cos(f.roll) * horizontal(f.az - 0.5f * kPi) + std::sin(f.roll) * Vec3f::UnitZ();
}

/// A young frond: its unrolled blade and the crozier rolled up above it.
struct YoungFrond {
  std::vector<StripNode> blade;
  std::vector<TubeNode> crozier;
};

/// A young frond: its unrolled share `open` of the grown length stands steeply (elevation `rise`, bending
/// out by kYoungFrondBend), a blade `half_width` across each side; above it the rest is rolled up in a
/// crozier, a spiral turning forward and down whose radius shrinks to a third, kCrozierThickness thick.
YoungFrond young_frond(const Frond& f, float open, float rise, float half_width) {
  const Vec3f out = horizontal(f.az), up = Vec3f::UnitZ();
  YoungFrond y;
  y.blade.push_back({0.03f * f.len * out - Vec3f(0, 0, 0.01f), half_width});
  float el = rise;
  for (int i = 0; i < kYoungFrondSegments; ++i) {
    el = rise - kYoungFrondBend * (float(i) + 0.5f) / float(kYoungFrondSegments);
    y.blade.push_back({y.blade.back().p + open * f.len / float(kYoungFrondSegments) * (std::cos(el) * out + std::sin(el) * up),
                       half_width});
  }
  const float radius = std::clamp(kCrozierRadiusPerLength * f.len * (1.5f - open), kCrozierRadius[0], kCrozierRadius[1]);
  const float turn = kPi * (1.0f + 2.0f * (1.0f - open));  // a tight crozier rolls more than one near open
  const float step = turn / float(kCrozierSegments);
  y.crozier.push_back({y.blade.back().p, kCrozierThickness * radius});
  for (int i = 0; i < kCrozierSegments; ++i) {
    const float f_end = float(i + 1) / float(kCrozierSegments);
    const float r = radius * (1.0f - 0.67f * (float(i) + 0.5f) / float(kCrozierSegments));
    el -= step;
    y.crozier.push_back({y.crozier.back().p + r * step * (std::cos(el) * out + std::sin(el) * up),
                         kCrozierThickness * radius * (1.0f - 0.6f * f_end)});
  }
  return y;
}

}  // namespace

GeneratedAsset generate_fern(Rng& rng) {
  const FernPlan plan = plan_fern(rng);
  MeshBuilder b;
  b.begin_part(Role::GroundVegetation, Material::Fern, pinnate_frond_mask(), true);
  for (const Frond& f : plan.fronds) {
    const Vec3f base = 0.03f * f.len * horizontal(f.az) - Vec3f(0, 0, 0.01f);
    std::vector<StripNode> spine;
    for (const Vec3f& p : f.rachis) spine.push_back({base + f.len * p, plan.width_ratio * f.len});
    add_strip(b, spine, blade_side(f));
  }
  return {b.finish(), Role::GroundVegetation, CollisionProxy{}};
}

GeneratedAsset generate_young_fern(Rng& rng) {
  const FernPlan plan = plan_fern(rng);
  std::vector<YoungFrond> young;
  MeshBuilder b;
  b.begin_part(Role::GroundVegetation, Material::SpringLeaves, pinnate_frond_mask(), true);
  for (const Frond& f : plan.fronds) {
    const float open = rng.range(kYoungFrondOpen[0], kYoungFrondOpen[1]);
    const float rise = rng.range(70.0f, 85.0f) * kPi / 180.0f;  // young fronds stand steeply
    const float half_width = plan.width_ratio * f.len * (0.4f + 0.6f * open);  // pinnae spread as they unroll
    young.push_back(young_frond(f, open, rise, half_width));
    add_strip(b, young.back().blade, blade_side(f));
  }
  b.begin_part(Role::GroundVegetation, Material::SpringLeaves);  // the croziers: solid coils
  for (const YoungFrond& y : young) add_tube(b, y.crozier, kCrozierSides);
  return {b.finish(), Role::GroundVegetation, CollisionProxy{}};
}

}  // namespace silva::assets
