#include <algorithm>

#include "assets/alpha_masks.hpp"
#include "assets/generators.hpp"

namespace silva::assets {

GeneratedAsset generate_shrub(Rng& rng) {
  const float height = rng.range(1.0f, 2.0f);
  const int blobs = 2 + int(rng.below(3));
  std::vector<Vec3f> centers, radii;
  float reach = 0;
  for (int i = 0; i < blobs; ++i) {
    const Vec3f c(rng.range(-0.25f, 0.25f) * height, rng.range(-0.25f, 0.25f) * height, rng.range(0.45f, 0.6f) * height);
    const float rx = rng.range(0.25f, 0.35f) * height;
    centers.push_back(c);
    radii.emplace_back(rx, rx, std::min(0.4f * height, 0.95f * height - c.z()));
    reach = std::max(reach, c.head<2>().norm() + rx);
  }
  MeshBuilder b;
  b.begin_part(Role::Shrub, Material::BarkBroadleaf);
  for (const Vec3f& c : centers) {
    const TubeNode stem[] = {{Vec3f(0.2f * c.x(), 0.2f * c.y(), 0), 0.03f}, {c, 0.012f}};
    add_tube(b, stem, 5);
  }
  b.begin_part(Role::Shrub, Material::ShrubLeaves, shrub_leaves_mask(), true);
  for (size_t i = 0; i < centers.size(); ++i) add_card_blob(b, rng, centers[i], radii[i], 36, 0.12f * height);
  return {b.finish(), Role::Shrub, cylinder_proxy(0.6f * reach, height)};
}

}  // namespace silva::assets
