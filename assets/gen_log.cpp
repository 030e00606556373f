#include <cmath>

#include "assets/generators.hpp"

namespace silva::assets {

GeneratedAsset generate_log(Rng& rng) {
  const float length = rng.range(3.0f, 6.0f);
  const float r = rng.range(0.15f, 0.3f);
  const float axis_z = 0.85f * r;  // resting slightly sunk into the ground
  const float bend = rng.range(-0.015f, 0.015f) * length;
  constexpr int kNodes = 5;
  std::vector<TubeNode> nodes;
  for (int i = 0; i < kNodes; ++i) {
    const float f = float(i) / float(kNodes - 1);
    const float y = bend * 4.0f * f * (1.0f - f);
    nodes.push_back({Vec3f((f - 0.5f) * length, y, axis_z), r * rng.range(0.93f, 1.0f)});
  }
  MeshBuilder b;
  b.begin_part(Role::Obstacle, Material::BarkDead);
  add_tube(b, nodes, 10);
  b.begin_part(Role::Obstacle, Material::Wood);
  add_disc(b, nodes.front().p, (nodes[0].p - nodes[1].p).normalized(), nodes.front().r, 10);
  add_disc(b, nodes.back().p, (nodes[kNodes - 1].p - nodes[kNodes - 2].p).normalized(), nodes.back().r, 10);
  CollisionProxy proxy;
  proxy.shape = CollisionProxy::Shape::Capsule;
  proxy.center = Vec3f(0, 0, axis_z);
  proxy.axis = Vec3f::UnitX();
  proxy.radius = r + std::abs(bend);
  proxy.height = length - 2.0f * r;
  return {b.finish(), Role::Obstacle, proxy};
}

}  // namespace silva::assets
