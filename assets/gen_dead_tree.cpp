#include <cmath>
#include <numbers>

#include "assets/generators.hpp"

namespace silva::assets {

namespace {
/// A point on a polyline at height fraction f of its vertical extent (nodes rise monotonically).
Vec3f along(const std::vector<TubeNode>& nodes, float z) {
  for (size_t i = 1; i < nodes.size(); ++i)
    if (nodes[i].p.z() >= z) {
      const float t = (z - nodes[i - 1].p.z()) / (nodes[i].p.z() - nodes[i - 1].p.z());
      return nodes[i - 1].p + t * (nodes[i].p - nodes[i - 1].p);
    }
  return nodes.back().p;
}
}  // namespace

GeneratedAsset generate_dead_tree(Rng& rng) {
  constexpr float kPi = std::numbers::pi_v<float>;
  const float full_height = rng.range(8.0f, 15.0f);
  const float r0 = rng.range(0.15f, 0.35f);
  const bool snapped = rng.uniform() < 0.35f;
  const float height = snapped ? full_height * rng.range(0.55f, 0.8f) : full_height;
  const float top_radius = snapped ? 0.5f * r0 : 0.05f * r0;

  std::vector<TubeNode> trunk;
  Vec3f p = Vec3f::Zero();
  constexpr int kNodes = 6;
  for (int i = 0; i < kNodes; ++i) {
    const float f = float(i) / float(kNodes - 1);
    trunk.push_back({p, r0 * (1.1f - f) + top_radius * f});
    p += Vec3f(rng.range(-0.03f, 0.03f) * height, rng.range(-0.03f, 0.03f) * height, height / float(kNodes - 1));
  }
  MeshBuilder b;
  b.begin_part(Role::DeadTree, Material::BarkDead);
  add_tube(b, trunk, 8);
  const int branches = 4 + int(rng.below(6));
  for (int i = 0; i < branches; ++i) {
    const float az = rng.range(0.0f, 2.0f * kPi);
    const float el = rng.range(-0.15f, 0.8f);
    const float len = full_height * rng.range(0.12f, 0.3f);
    const float z = height * rng.range(0.3f, 0.9f);
    const Vec3f dir(std::cos(el) * std::cos(az), std::cos(el) * std::sin(az), std::sin(el));
    const Vec3f start = along(trunk, z);
    const float r = 0.3f * r0 * (1.0f - 0.5f * z / height);
    const Vec3f mid = start + 0.5f * len * dir;
    const TubeNode branch[] = {{start, r}, {mid, 0.6f * r}, {start + len * dir + Vec3f(0, 0, 0.05f * len), 0.15f * r}};
    add_tube(b, branch, 5);
    if (rng.uniform() < 0.5f) {
      const Vec3f twig_dir = (dir + 0.8f * random_direction(rng)).normalized();
      const TubeNode twig[] = {{mid, 0.4f * r}, {mid + 0.4f * len * twig_dir, 0.1f * r}};
      add_tube(b, twig, 4);
    }
  }
  if (snapped) {
    b.begin_part(Role::DeadTree, Material::Wood);
    const Vec3f top_dir = (trunk.back().p - trunk[kNodes - 2].p).normalized();
    add_disc(b, trunk.back().p, top_dir, top_radius, 8);
  }
  return {b.finish(), Role::DeadTree, cylinder_proxy(r0, height)};
}

}  // namespace silva::assets
