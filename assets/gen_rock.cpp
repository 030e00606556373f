#include <cmath>
#include <numbers>

#include "assets/generators.hpp"

namespace silva::assets {

GeneratedAsset generate_rock(Rng& rng) {
  constexpr float kPi = std::numbers::pi_v<float>;
  Mesh m = unit_icosphere(2);
  struct Wave {
    Vec3f dir;
    float freq, amp, phase;
  };
  std::vector<Wave> waves;
  waves.reserve(5);
  for (int k = 0; k < 5; ++k)
    waves.push_back({random_direction(rng), rng.range(1.5f, 4.0f), rng.range(0.04f, 0.12f), rng.range(0.0f, 2.0f * kPi)});
  const Vec3f stretch(1.0f, rng.range(0.6f, 1.0f), rng.range(0.4f, 0.8f));
  for (Vec3f& p : m.positions) {
    float r = 1.0f;
    for (const Wave& w : waves) r += w.amp * std::sin(w.freq * w.dir.dot(p) + w.phase);
    p = (r * p).cwiseProduct(stretch);
  }
  // Scale so the largest extent is the drawn size, then sink 15 % of the height into the ground.
  const float size = rng.range(0.3f, 1.5f);
  AABB box = m.bounds();
  const float s = size / box.size().maxCoeff();
  const Vec3f shift(-box.center().x() * s, -box.center().y() * s, -box.min.z() * s - 0.15f * box.size().z() * s);
  for (Vec3f& p : m.positions) p = s * p + shift;
  m.compute_normals();
  MeshPart part;
  part.index_count = uint32_t(m.indices.size());
  part.role = Role::Obstacle;
  part.material = Material::Rock;
  m.parts = {part};

  box = m.bounds();
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
  return {std::move(m), Role::Obstacle, proxy};
}

}  // namespace silva::assets
