#include "assets/factory.hpp"

#include <cstdio>
#include <memory>

#include "assets/lod.hpp"

namespace silva::assets {

namespace {
constexpr Factory kFactories[] = {
    {AssetKind::ConiferTree, "spruce", 8, generate_spruce},
    {AssetKind::ConiferTree, "pine", 8, generate_pine},
    {AssetKind::ConiferTree, "larch", 8, generate_larch},
    {AssetKind::BroadleafTree, "beech", 8, generate_beech},
    {AssetKind::BroadleafTree, "birch", 8, generate_birch},
    {AssetKind::BroadleafTree, "oak", 8, generate_oak},
    {AssetKind::DeadTree, "dead_tree", 6, generate_dead_tree},
    {AssetKind::Stump, "stump", 4, generate_stump},
    {AssetKind::Grass, "grass", 6, generate_grass},
    {AssetKind::Fern, "fern", 4, generate_fern},
    {AssetKind::Shrub, "shrub", 5, generate_shrub},
    {AssetKind::Rock, "rock", 6, generate_rock},
    {AssetKind::Log, "log", 4, generate_log},
    {AssetKind::Log, "fallen_tree", 4, generate_fallen_tree},
};

/// "<prefix>_<ii>".
std::string variant_name(const Factory& factory, uint32_t variant) {
  char name[96];
  std::snprintf(name, sizeof name, "%s_%02u", factory.prefix, variant);
  return name;
}

}  // namespace

std::span<const Factory> factories() { return kFactories; }

const Factory* find_factory(const std::string& prefix) {
  for (const Factory& f : kFactories)
    if (prefix == f.prefix) return &f;
  return nullptr;
}

GeneratedAsset generate_variant(const Factory& factory, uint64_t seed, uint32_t variant) {
  uint64_t key = 0;
  for (const char* c = factory.prefix; *c; ++c) key = hash_combine(key, uint64_t(uint8_t(*c)));
  Rng rng(seed, hash_combine(key, variant), Purpose::AssetShape);
  return factory.generate(rng);
}

Asset make_asset(const Factory& factory, uint64_t seed, uint32_t variant) {
  GeneratedAsset g = generate_variant(factory, seed, variant);
  Asset a;
  a.name = variant_name(factory, variant);
  a.source = ProceduralSource{factory.prefix, variant, seed};
  a.kind = factory.kind;
  a.role = g.role;
  auto geometry = std::make_shared<const AssetGeometry>(build_lods(g.mesh));
  a.lod_screen_sizes.assign(std::begin(kLodScreenSizes), std::begin(kLodScreenSizes) + (geometry->lods().size() - 1));
  a.geometry = std::move(geometry);
  a.proxy = g.proxy;
  return a;
}

Asset lazy_asset(const Factory& factory, uint64_t seed, uint32_t variant, Role role, const CollisionProxy& proxy,
                 std::vector<float> lod_screen_sizes) {
  Asset a;
  a.name = variant_name(factory, variant);
  a.source = ProceduralSource{factory.prefix, variant, seed};
  a.kind = factory.kind;
  a.role = role;
  a.geometry = std::make_shared<const AssetGeometry>(
      [&factory, seed, variant] { return build_lods(generate_variant(factory, seed, variant).mesh); });
  a.lod_screen_sizes = std::move(lod_screen_sizes);
  a.proxy = proxy;
  return a;
}

AssetLibrary generate_library(uint64_t seed) {
  AssetLibrary lib;
  for (const Factory& f : factories())
    for (uint32_t v = 0; v < f.variants; ++v) lib.assets.push_back(make_asset(f, seed, v));
  lib.index_kinds();
  return lib;
}

}  // namespace silva::assets
