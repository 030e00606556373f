#include <cmath>
#include <numbers>

#include "assets/alpha_masks.hpp"
#include "assets/generators.hpp"

namespace silva::assets {

GeneratedAsset generate_broadleaf(Rng& rng) {
  constexpr float kPi = std::numbers::pi_v<float>;
  const float height = rng.range(10.0f, 20.0f);
  const float r0 = rng.range(0.15f, 0.4f);
  const float crown_base = height * rng.range(0.3f, 0.4f);
  const float trunk_top = 0.7f * height;
  const Vec2f lean(rng.range(-0.4f, 0.4f), rng.range(-0.4f, 0.4f));
  auto axis = [&](float z) { return Vec3f(lean.x() * z / height, lean.y() * z / height, z); };

  MeshBuilder b;
  b.begin_part(Role::TreeTrunk, Material::BarkBroadleaf);
  const TubeNode trunk[] = {{axis(0), 1.15f * r0}, {axis(0.05f * height), r0},
                            {axis(crown_base), 0.75f * r0}, {axis(trunk_top), 0.35f * r0}};
  add_tube(b, trunk, 10);

  // Canopy blob radius: the crown's blobs together reach from the crown base to the top.
  const float blob = 0.16f * height;
  std::vector<Vec3f> blob_centers = {axis(height - 0.6f * blob)};
  const int branches = 3 + int(rng.below(4));
  for (int i = 0; i < branches; ++i) {
    const float az = 2.0f * kPi * (float(i) + rng.range(-0.3f, 0.3f)) / float(branches);
    const float el = rng.range(0.45f, 0.8f);
    const float len = height * rng.range(0.18f, 0.24f);
    const Vec3f dir(std::cos(el) * std::cos(az), std::cos(el) * std::sin(az), std::sin(el));
    const Vec3f start = axis(crown_base + rng.range(0.1f, 0.6f) * (trunk_top - crown_base));
    const Vec3f end = start + len * dir + Vec3f(0, 0, 0.1f * len);
    const TubeNode branch[] = {{start, 0.35f * r0}, {start + 0.5f * len * dir, 0.2f * r0}, {end, 0.07f * r0}};
    add_tube(b, branch, 6);
    blob_centers.push_back(end);
  }
  b.begin_part(Role::TreeCanopy, Material::Leaves, leaf_cluster_mask(), true);
  for (const Vec3f& c : blob_centers) {
    const float rb = blob * rng.range(0.85f, 1.1f);
    const Vec3f radii(rb, rb, std::min(0.7f * rb, 0.98f * height - c.z()));
    add_card_blob(b, rng, c, radii, 64, rb * rng.range(0.22f, 0.28f));
  }
  return {b.finish(), Role::TreeTrunk, cylinder_proxy(r0, height)};
}

}  // namespace silva::assets
