#include "assets/generators.hpp"

namespace silva::assets {

GeneratedAsset generate_stump(Rng& rng) {
  const float height = rng.range(0.3f, 0.9f);
  const float r = rng.range(0.2f, 0.45f);
  MeshBuilder b;
  b.begin_part(Role::Stump, Material::BarkDead);
  const TubeNode sides[] = {{Vec3f(0, 0, 0), 1.25f * r}, {Vec3f(0, 0, 0.15f * height), 1.05f * r},
                            {Vec3f(0, 0, height), r}};
  add_tube(b, sides, 12);
  b.begin_part(Role::Stump, Material::Wood);
  add_disc(b, Vec3f(0, 0, height), Vec3f::UnitZ(), r, 12);
  return {b.finish(), Role::Stump, cylinder_proxy(1.1f * r, height)};
}

}  // namespace silva::assets
