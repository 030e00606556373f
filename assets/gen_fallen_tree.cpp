#include <algorithm>
#include <cmath>

#include "assets/dead_wood.hpp"
#include "assets/generators.hpp"
#include "assets/root_plate.hpp"
#include "assets/tree_mesh.hpp"

namespace silva::assets {

namespace {

/// Lays a grown skeleton down: its trunk's base-to-tip chord becomes +x, the base at x = x0, the
/// trunk resting on the ground sunk by 15 % of its radius; branches that would point into the
/// ground are dropped (broken off under the trunk).
Skeleton lay_down(const Skeleton& s, float x0) {
  const auto& trunk = s.branches.front().nodes;
  const Vec3f chord = (trunk.back().p - trunk.front().p).normalized();
  Vec3f side, up;
  perpendicular_frame(chord, side, up);  // (chord, side, up) -> (x, y, z)
  auto lay = [&](const Vec3f& p) { return Vec3f(x0 + p.dot(chord), p.dot(side), p.dot(up)); };
  float lift = 0;
  for (const TubeNode& n : trunk) lift = std::max(lift, 0.85f * n.r - lay(n.p).z());
  Skeleton out;
  std::vector<int> index(s.branches.size(), -1);
  for (size_t i = 0; i < s.branches.size(); ++i) {
    Branch b = s.branches[i];
    if (b.parent >= 0 && index[size_t(b.parent)] < 0) continue;
    for (TubeNode& n : b.nodes) n.p = lay(n.p) + Vec3f(0, 0, lift);
    if (i > 0 && b.nodes.back().p.z() < 0.6f * b.nodes.front().p.z()) continue;
    if (b.parent >= 0) b.parent = index[size_t(b.parent)];
    index[i] = int(out.branches.size());
    out.branches.push_back(std::move(b));
  }
  return out;
}

}  // namespace

GeneratedAsset generate_fallen_tree(Rng& rng) {
  const float length = rng.range(8.0f, 16.0f);
  const float r0 = rng.range(0.12f, 0.22f);
  const float top = rng.range(0.45f, 0.85f);  // broken where the trunk hit the ground
  const Skeleton s = lay_down(dead_skeleton(length, r0, top, rng), -0.5f * length * top);
  MeshBuilder b;
  TreeLook look{Material::LogBark, Role::Obstacle, false, {}};  // fallen wood: furrowed, mossy on top
  look.torn_ends = true;
  mesh_tree(b, s, look, rng);
  const auto& trunk = s.branches.front().nodes;
  b.begin_part(Role::Obstacle, Material::Wood);  // the broken end
  add_disc(b, trunk.back().p, (trunk.back().p - trunk[trunk.size() - 2].p).normalized(), trunk.back().r, 8);
  add_root_plate(b, rng, {-0.5f * length * top, rng.range(4.0f, 6.0f) * r0, r0});
  CollisionProxy proxy;
  proxy.shape = CollisionProxy::Shape::Capsule;
  proxy.center = Vec3f(0, 0, 0.85f * r0);
  proxy.axis = Vec3f::UnitX();
  proxy.radius = r0;
  proxy.height = std::max(0.1f, length * top - 2.0f * r0);
  return {b.finish(), Role::Obstacle, proxy};
}

}  // namespace silva::assets
