#pragma once
/// @file Test meshes of alpha-masked cards, alone or with a solid part (LOD and card-thinning tests).
#include "assets/foliage_sprays.hpp"
#include "assets/mesh_builder.hpp"
#include "assets/strips.hpp"

namespace silva::assets::test {

/// `cards` unit cards (1 m x 1 m, 2 triangles each) 3 m apart along x, in one masked part.
inline Mesh row_of_cards(int cards) {
  MeshBuilder b;
  b.begin_part(Role::TreeCanopy, Material::Leaves, beech_spray(1.0f), true);
  for (int i = 0; i < cards; ++i) add_card(b, Vec3f(float(3 * i), 0, 0), Vec3f(0.5f, 0, 0), Vec3f(0, 0, 0.5f));
  return b.finish();
}

/// row_of_cards(cards) (part 0) with a solid unit icosphere of `role` and `material` (part 1).
inline Mesh cards_and_sphere(int cards, Role role, Material material) {
  Mesh m = row_of_cards(cards);
  Mesh sphere = unit_icosphere(3);
  MeshPart part;
  part.index_count = uint32_t(sphere.indices.size());
  part.role = role;
  part.material = material;
  sphere.parts = {part};
  m.append(sphere);
  return m;
}

}  // namespace silva::assets::test
