#include "assets/generators.hpp"
#include "assets/rock_shape.hpp"

namespace silva::assets {

namespace {

/// Sphere or box proxy around the rock's bounds.
CollisionProxy rock_proxy(const AABB& box) {
  CollisionProxy proxy;
  proxy.center = box.center();
  const Vec3f ext = box.size();
  if (ext.maxCoeff() < 1.35f * ext.minCoeff()) {
    proxy.shape = CollisionProxy::Shape::Sphere;
    proxy.radius = 0.5f * ext.maxCoeff();
  } else {
    proxy.shape = CollisionProxy::Shape::Box;
    proxy.half_extents = 0.5f * ext;
  }
  return proxy;
}

}  // namespace

GeneratedAsset generate_rock(Rng& rng) {
  Mesh m = unit_icosphere(3);
  const RockShape shape = random_rock_shape(rng);
  const Vec3f stretch(1.0f, rng.range(0.6f, 1.0f), rng.range(0.4f, 0.75f));
  for (Vec3f& p : m.positions) p = (shape.radius(p) * p).cwiseProduct(stretch);
  // Scale so the largest extent is the drawn size, then bury 8-22 % of the height.
  const float size = rng.range(0.3f, 1.5f);
  const float buried = rng.range(0.08f, 0.22f);
  AABB box = m.bounds();
  const float s = size / box.size().maxCoeff();
  const Vec3f shift(-box.center().x() * s, -box.center().y() * s, -box.min.z() * s - buried * box.size().z() * s);
  for (Vec3f& p : m.positions) p = s * p + shift;
  m.compute_normals();
  MeshPart part;
  part.index_count = uint32_t(m.indices.size());
  part.role = Role::Obstacle;
  part.material = Material::Rock;
  m.parts = {part};
  const AABB placed = m.bounds();
  return {std::move(m), Role::Obstacle, rock_proxy(placed)};
}

}  // namespace silva::assets
