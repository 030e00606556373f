#include "world/species_stands.hpp"

#include <algorithm>
#include <string>

#include "core/noise.hpp"

namespace silva::world {

SpeciesStands make_species_stands(const assets::AssetLibrary& library, uint64_t seed, const ForestType& forest,
                                  Season season) {
  SpeciesStands s;
  std::array<std::vector<std::string>, size_t(AssetKind::Count)> names;
  for (uint32_t a = 0; a < library.assets.size(); ++a) {
    const assets::Asset& asset = library.assets[a];
    const std::string group = asset.source ? asset.source->generator : std::string();
    const std::vector<std::string>* grown = asset.kind == AssetKind::ConiferTree     ? &forest.conifers
                                            : asset.kind == AssetKind::BroadleafTree ? &forest.broadleaves
                                            : asset.kind == AssetKind::Shrub         ? &forest.shrubs
                                            : asset.kind == AssetKind::Fern          ? &forest.herbs
                                                                                     : nullptr;
    if (grown && asset.source && !(grows(*grown, group) && shows_in(group, season))) continue;  // user assets always grow
    if (asset.kind == AssetKind::Fern && asset.source && vernal_herb(group)) s.vernal.push_back(a);
    auto& kind_names = names[size_t(asset.kind)];
    auto& kind_groups = s.groups[size_t(asset.kind)];
    const auto it = std::find(kind_names.begin(), kind_names.end(), group);
    if (it == kind_names.end()) {
      kind_names.push_back(group);
      kind_groups.push_back({a});
    } else {
      kind_groups[size_t(it - kind_names.begin())].push_back(a);
    }
  }
  Rng rng(seed, 0, Purpose::PlacementVariant);
  s.offset_x = 1000.0 * rng.uniform_double();
  s.offset_y = 1000.0 * rng.uniform_double();
  return s;
}

uint32_t pick_asset(const SpeciesStands& stands, AssetKind kind, double x, double y, Rng& rng) {
  const auto& groups = stands.groups[size_t(kind)];
  if (groups.empty()) return UINT32_MAX;
  size_t g = 0;
  if (groups.size() > 1) {
    const double stand = 0.5 + 0.5 * simplex2(x / kStandScale + stands.offset_x, y / kStandScale + stands.offset_y);
    const size_t dominant = std::min(groups.size() - 1, size_t(std::max(0.0, stand) * double(groups.size())));
    g = rng.uniform_double() < kDominantShare ? dominant : rng.below(uint32_t(groups.size()));
  }
  return groups[g][rng.below(uint32_t(groups[g].size()))];
}

uint32_t pick_vernal(const SpeciesStands& stands, Rng& rng) {
  return stands.vernal.empty() ? UINT32_MAX : stands.vernal[rng.below(uint32_t(stands.vernal.size()))];
}

}  // namespace silva::world
