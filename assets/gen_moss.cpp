#include <algorithm>
#include <cmath>
#include <numbers>

#include "assets/generators.hpp"
#include "assets/strips.hpp"
#include "assets/shape_noise.hpp"

namespace silva::assets {

namespace {

/// A lumpy moss dome of radius r and height h at `center`: the upper half of an icosphere, its
/// rim sunk a little into the ground (the hidden base is left open).
Mesh cushion(const ShapeNoise& lumps, const Vec3f& center, float r, float h, int subdivisions) {
  const Mesh sphere = unit_icosphere(subdivisions);
  std::vector<Vec3f> positions = sphere.positions;
  for (Vec3f& p : positions) {
    const float bump = 1.0f + 0.22f * lumps.fbm(3.0f * p + center * 10.0f, 3);
    p = center + Vec3f(p.x() * r * bump, p.y() * r * bump, std::max(p.z(), 0.0f) * h * bump - 0.05f * h);
  }
  std::vector<uint32_t> upper;
  for (size_t t = 0; t < sphere.indices.size(); t += 3) {
    const uint32_t* tri = sphere.indices.data() + t;
    if (std::min({sphere.positions[tri[0]].z(), sphere.positions[tri[1]].z(), sphere.positions[tri[2]].z()}) > -1e-4f)
      upper.insert(upper.end(), tri, tri + 3);
  }
  Mesh dome = sphere;
  dome.parts = {MeshPart{}};
  dome.parts[0].index_count = uint32_t(upper.size());
  Mesh out = compact_mesh(dome, positions, {upper});
  out.compute_normals();
  return out;
}

}  // namespace

GeneratedAsset generate_moss_cushion(Rng& rng) {
  const ShapeNoise lumps(rng);
  const float r = rng.range(0.05f, 0.13f);
  Mesh m = cushion(lumps, Vec3f::Zero(), r, r * rng.range(0.25f, 0.5f), 2);
  const int satellites = int(rng.below(3));
  for (int i = 0; i < satellites; ++i) {
    const float rs = r * rng.range(0.3f, 0.55f);
    const Vec3f at = (r + 0.6f * rs) * horizontal(rng.range(0.0f, 2.0f * std::numbers::pi_v<float>));
    m.append(cushion(lumps, at, rs, rs * rng.range(0.3f, 0.5f), 1));
  }
  MeshPart part;
  part.index_count = uint32_t(m.indices.size());
  part.role = Role::Ground;
  part.material = Material::Moss;
  m.parts = {part};
  return {std::move(m), Role::Ground, CollisionProxy{}};
}

}  // namespace silva::assets
