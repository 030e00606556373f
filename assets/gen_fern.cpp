#include <algorithm>
#include <cmath>
#include <numbers>

#include "assets/generators.hpp"
#include "assets/strips.hpp"
#include "assets/understory_masks.hpp"

namespace silva::assets {

namespace {

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

}  // namespace

GeneratedAsset generate_fern(Rng& rng) {
  constexpr float kPi = std::numbers::pi_v<float>;
  const FernClass& cls = kClasses[rng.below(3)];
  const float height = rng.range(cls.min_h, cls.max_h);
  const int fronds = cls.min_fronds + int(rng.below(uint32_t(cls.max_fronds - cls.min_fronds + 1)));
  const float rise = rng.range(45.0f, 70.0f) * kPi / 180.0f, droop = rng.range(55.0f, 100.0f) * kPi / 180.0f;
  const float width_ratio = rng.range(0.11f, 0.15f);  // frond half-width / length
  struct Frond {
    std::vector<Vec3f> rachis;
    float len, roll, az;
  };
  std::vector<Frond> all;
  float top = 0;
  for (int i = 0; i < fronds; ++i) {
    Frond f;
    f.az = 2.0f * kPi * (float(i) + rng.range(-0.3f, 0.3f)) / float(fronds);
    f.len = rng.range(0.7f, 1.0f);
    f.roll = rng.range(-0.35f, 0.35f);
    f.rachis = unit_rachis(f.az, rise + rng.range(-0.2f, 0.15f), droop * rng.range(0.8f, 1.25f));
    for (const Vec3f& p : f.rachis) top = std::max(top, f.len * p.z());
    all.push_back(std::move(f));
  }
  const float scale = height / top;  // the tallest point of the tallest frond is the fern's height
  MeshBuilder b;
  b.begin_part(Role::GroundVegetation, Material::Fern, pinnate_frond_mask(), true);
  for (const Frond& f : all) {
    const float len = scale * f.len;
    const Vec3f base = 0.03f * len * horizontal(f.az) - Vec3f(0, 0, 0.01f);
    std::vector<StripNode> spine;
    for (const Vec3f& p : f.rachis) spine.push_back({base + len * p, width_ratio * len});
    const Vec3f side = std::cos(f.roll) * horizontal(f.az - 0.5f * kPi) + std::sin(f.roll) * Vec3f::UnitZ();
    add_strip(b, spine, side);
  }
  return {b.finish(), Role::GroundVegetation, CollisionProxy{}};
}

}  // namespace silva::assets
