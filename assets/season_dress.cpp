#include "assets/season_dress.hpp"

#include <algorithm>

#include "assets/alpha_masks.hpp"
#include "assets/foliage_sprays.hpp"
#include "assets/understory_masks.hpp"

namespace silva::assets {

bool is_deciduous_foliage(Material m) {
  switch (m) {
    case Material::Leaves:
    case Material::ShrubLeaves:
    case Material::NeedlesLarch:
    case Material::LeavesBeech:
    case Material::LeavesBirch:
    case Material::LeavesOak: return true;
    default: return false;
  }
}

void lay_flat(Mesh& mesh) {
  for (Vec3f& p : mesh.positions) p = Vec3f(kFlatBrackenSpread * p.x(), kFlatBrackenSpread * p.y(), kFlatBrackenHeight * p.z());
  for (Vec3f& n : mesh.normals) {
    const Vec3f t(n.x() / kFlatBrackenSpread, n.y() / kFlatBrackenSpread, n.z() / kFlatBrackenHeight);
    n = t.norm() > 0.0f ? Vec3f(t.normalized()) : n;
  }
}

void dress_for_season(Mesh& mesh, Season season) {
  if (season == Season::Summer) return;
  const auto bracken_frond = [](const MeshPart& p) { return p.mask && p.mask == pinnate_frond_mask(); };
  const bool matted = season == Season::EarlySpring && std::any_of(mesh.parts.begin(), mesh.parts.end(), bracken_frond);
  if (matted) lay_flat(mesh);
  const bool dormant = season == Season::Winter || season == Season::EarlySpring;  // bare crowns, dead ferns
  for (MeshPart& part : mesh.parts) {
    if (!part.mask) continue;
    if (season == Season::Spring) {  // young leaves and larch's new needles; ferns and grass as in summer
      if (is_deciduous_foliage(part.material)) part.material = Material::SpringLeaves;
      continue;
    }
    if (part.material == Material::Fern) {  // bracken turns orange-brown, dies back grey-brown, lies rust-brown
      part.material = matted ? Material::MattedBracken : dormant ? Material::DeadBracken : Material::AutumnLeaves;
    } else if (part.material == Material::Grass) {  // straw in autumn, dry and pale in winter
      part.material = dormant ? Material::WinterGrass : Material::AutumnGrass;
    } else if (!is_deciduous_foliage(part.material)) {
      continue;
    } else if (dormant) {
      const auto twigs = bare_twigs_for(part.mask.get());  // trees: twigs at their cards' scale
      part.mask = twigs ? twigs : bare_twig_mask();
      part.material = Material::BareTwigs;
    } else {
      part.material = part.material == Material::NeedlesLarch ? Material::AutumnNeedles : Material::AutumnLeaves;
    }
  }
}

}  // namespace silva::assets
