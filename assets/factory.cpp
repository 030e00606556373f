#include "assets/factory.hpp"

#include <cstdio>

#include "assets/lod.hpp"

namespace silva::assets {

namespace {
constexpr Factory kFactories[] = {
    {AssetKind::ConiferTree, "conifer", 6, generate_conifer},
    {AssetKind::BroadleafTree, "broadleaf", 6, generate_broadleaf},
    {AssetKind::DeadTree, "dead_tree", 4, generate_dead_tree},
    {AssetKind::Stump, "stump", 20, generate_stump},
    {AssetKind::Grass, "grass", 20, generate_grass},
    {AssetKind::Grass, "grass_tall", 20, generate_tall_grass, 1},
    {AssetKind::Fern, "fern", 20, generate_fern},
    {AssetKind::Shrub, "bilberry", 20, generate_bilberry},
    {AssetKind::Shrub, "hazel", 20, generate_hazel, 1},
    {AssetKind::Shrub, "bramble", 20, generate_bramble, 2},
    {AssetKind::Rock, "rock", 20, generate_rock},
    {AssetKind::Log, "log", 20, generate_log},
    {AssetKind::GroundCover, "twig", 20, generate_twig},
    {AssetKind::GroundCover, "fallen_branch", 20, generate_fallen_branch, 1},
    {AssetKind::GroundCover, "cone", 20, generate_cone, 2},
    {AssetKind::GroundCover, "leaf_litter", 20, generate_leaf_litter, 3},
    {AssetKind::GroundCover, "moss", 20, generate_moss_cushion, 4},
};

/// True when the factories are in AssetKind order and every kind has one whose stream is 0.
constexpr bool covers_every_kind_in_order() {
  size_t next = 0;
  for (const Factory& f : kFactories) {
    if (size_t(f.kind) == next && f.stream == 0) ++next;
    else if (size_t(f.kind) + 1 != next || f.stream == 0) return false;
  }
  return next == size_t(AssetKind::Count);
}
static_assert(covers_every_kind_in_order(), "factories in kind order, each kind's first with stream 0");
}  // namespace

std::span<const Factory> factories() { return kFactories; }

Asset make_asset(const Factory& factory, uint64_t seed, uint32_t variant) {
  uint64_t key = hash_combine(uint64_t(factory.kind), variant);
  if (factory.stream != 0) key = hash_combine(key, factory.stream);
  Rng rng(seed, key, Purpose::AssetShape);
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
