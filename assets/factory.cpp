#include "assets/factory.hpp"

#include <cstdio>

#include "assets/lod.hpp"

namespace silva::assets {

namespace {
constexpr Factory kFactories[] = {
    {AssetKind::ConiferTree, "conifer", 6, generate_conifer},
    {AssetKind::BroadleafTree, "broadleaf", 6, generate_broadleaf},
    {AssetKind::DeadTree, "dead_tree", 4, generate_dead_tree},
    {AssetKind::Stump, "stump", 4, generate_stump},
    {AssetKind::Grass, "grass", 6, generate_grass},
    {AssetKind::Fern, "fern", 4, generate_fern},
    {AssetKind::Shrub, "shrub", 5, generate_shrub},
    {AssetKind::Rock, "rock", 6, generate_rock},
    {AssetKind::Log, "log", 4, generate_log},
};
static_assert(std::size(kFactories) == size_t(AssetKind::Count), "one factory per asset kind");
}  // namespace

std::span<const Factory> factories() { return kFactories; }

Asset make_asset(const Factory& factory, uint64_t seed, uint32_t variant) {
  Rng rng(seed, hash_combine(uint64_t(factory.kind), variant), Purpose::AssetShape);
  GeneratedAsset g = factory.generate(rng);
  char name[64];
  std::snprintf(name, sizeof name, "%s_%02u", factory.prefix, variant);
  Asset a;
  a.name = name;
  a.file = a.name + ".glb";
  a.kind = factory.kind;
  a.role = g.role;
  LodChain chain = build_lods(g.mesh);
  a.lods = std::move(chain.lods);
  a.lod_screen_sizes = std::move(chain.screen_sizes);
  a.proxy = g.proxy;
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
