#include <cmath>
#include <numbers>

#include "assets/alpha_masks.hpp"
#include "assets/generators.hpp"

namespace silva::assets {

namespace {
/// One needle tier: a cone from base height z (radius r) up to z + h.
struct Tier {
  float z, h, r;
};
}  // namespace

GeneratedAsset generate_conifer(Rng& rng) {
  constexpr float kPi = std::numbers::pi_v<float>;
  const float height = rng.range(12.0f, 25.0f);
  const float r0 = rng.range(0.15f, 0.4f);
  const Vec2f lean(rng.range(-0.3f, 0.3f), rng.range(-0.3f, 0.3f));
  auto axis = [&](float z) { return Vec3f(lean.x() * z / height, lean.y() * z / height, z); };

  MeshBuilder b;
  b.begin_part(Role::TreeTrunk, Material::BarkConifer);
  const TubeNode trunk[] = {{axis(0), 1.15f * r0}, {axis(0.08f * height), 0.95f * r0}, {axis(0.35f * height), 0.75f * r0},
                            {axis(0.7f * height), 0.4f * r0}, {axis(0.97f * height), 0.06f * r0}};
  add_tube(b, trunk, 10);

  const float crown_base = height * rng.range(0.25f, 0.4f);
  const float max_radius = height * rng.range(0.14f, 0.2f);
  const int tiers = 7 + int(rng.below(4));
  std::vector<Tier> tier;
  for (int t = 0; t < tiers; ++t) {
    const float f = float(t) / float(tiers - 1);
    const float h = 1.8f * (height - crown_base) / float(tiers);
    const float z = crown_base + f * (height - h - crown_base);
    tier.push_back({z, h, max_radius * (1.0f - 0.8f * f) * rng.range(0.9f, 1.1f)});
  }
  b.begin_part(Role::TreeCanopy, Material::Needles);
  for (const Tier& t : tier) {
    const TubeNode cone[] = {{axis(t.z), t.r}, {axis(t.z + t.h), 0.02f * t.r}};
    add_tube(b, cone, 10);
    add_disc(b, axis(t.z), -Vec3f::UnitZ(), t.r, 10);
  }
  b.begin_part(Role::TreeCanopy, Material::Needles, needle_spray_mask(), true);
  for (const Tier& t : tier) {
    const int cards = 14;
    for (int k = 0; k < cards; ++k) {
      const float a = 2.0f * kPi * (float(k) + rng.range(-0.3f, 0.3f)) / float(cards);
      const float droop = rng.range(0.15f, 0.45f);
      const Vec3f out(std::cos(a), std::sin(a), 0), tangent(-std::sin(a), std::cos(a), 0);
      const Vec3f up = std::cos(droop) * out - std::sin(droop) * Vec3f::UnitZ();
      const Vec3f center = axis(t.z + 0.1f * t.h) + 0.8f * t.r * out;
      add_card(b, center, 0.3f * t.r * tangent, 0.4f * t.r * up);
    }
  }
  return {b.finish(), Role::TreeTrunk, cylinder_proxy(r0, height)};
}

}  // namespace silva::assets
