#include "assets/library.hpp"

#include "assets/card_thinning.hpp"
#include "assets/lod.hpp"

#include <algorithm>
#include <cmath>

namespace silva::assets {

namespace {
constexpr const char* kKindNames[size_t(AssetKind::Count)] = {
    "conifer_tree", "broadleaf_tree", "dead_tree", "stump", "grass", "fern", "shrub", "rock", "log", "ground_cover"};
}  // namespace

AssetGeometry::AssetGeometry(std::vector<Mesh> lods) : lods_(std::move(lods)) { std::call_once(once_, [] {}); }

AssetGeometry::AssetGeometry(Make make) : make_(std::move(make)) {}

const Mesh& AssetGeometry::shadow_caster() const {
  const Mesh& full = lods().at(0);
  std::call_once(shadow_once_, [&] {
    if (std::any_of(full.parts.begin(), full.parts.end(), [](const MeshPart& p) { return p.mask != nullptr; }))
      shadow_caster_ = with_thinned_cards(lods().size() > 1 ? lods()[1] : full, kShadowCardRatio);
  });
  return shadow_caster_ ? *shadow_caster_ : full;
}

const std::vector<Mesh>& AssetGeometry::lods() const {
  std::call_once(once_, [this] { lods_ = make_(); });
  return lods_;
}

float CollisionProxy::footprint_radius() const {
  const float cxy = std::hypot(center.x(), center.y());
  switch (shape) {
    case Shape::None:
      return 0.0f;
    case Shape::Cylinder:
    case Shape::Capsule: {
      // Horizontal reach of the segment plus the radius.
      const float axial = 0.5f * height * std::hypot(axis.x(), axis.y());
      return cxy + axial + radius;
    }
    case Shape::Sphere:
      return cxy + radius;
    case Shape::Box:
      return cxy + std::hypot(half_extents.x(), half_extents.y());
  }
  return 0.0f;
}

void AssetLibrary::index_kinds() {
  for (auto& v : by_kind) v.clear();
  for (uint32_t i = 0; i < assets.size(); ++i) by_kind[size_t(assets[i].kind)].push_back(i);
}

const char* kind_name(AssetKind k) { return kKindNames[size_t(k)]; }

bool parse_kind(const std::string& name, AssetKind& out) {
  for (size_t i = 0; i < size_t(AssetKind::Count); ++i)
    if (name == kKindNames[i]) {
      out = AssetKind(i);
      return true;
    }
  return false;
}

}  // namespace silva::assets
