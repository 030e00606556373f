#include "assets/factory.hpp"

#include <cstdio>

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

/// FNV-1a of a factory prefix: separates the streams of factories sharing a kind.
constexpr uint64_t prefix_hash(const char* s) {
  uint64_t h = 0xcbf29ce484222325ull;
  for (; *s; ++s) h = (h ^ uint8_t(*s)) * 0x100000001b3ull;
  return h;
}
}  // namespace

std::span<const Factory> factories() { return kFactories; }

Asset make_asset(const Factory& factory, uint64_t seed, uint32_t variant) {
  const uint64_t stream = hash_combine(uint64_t(factory.kind), prefix_hash(factory.prefix));
  Rng rng(seed, hash_combine(stream, variant), Purpose::AssetShape);
  GeneratedAsset g = factory.generate(rng);
  char name[64];
  std::snprintf(name, sizeof name, "%s_%02u", factory.prefix, variant);
  Asset a;
  a.name = name;
  a.file = a.name + ".glb";
  a.kind = factory.kind;
  a.role = g.role;
  a.lods = build_lods(g.mesh);
  a.lod_screen_sizes.assign(std::begin(kLodScreenSizes), std::begin(kLodScreenSizes) + (a.lods.size() - 1));
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
