#include "assets/factory.hpp"

#include <cstdio>
#include <memory>

#include "assets/lod.hpp"
#include "assets/mesh_cache.hpp"
#include "assets/season_dress.hpp"

namespace silva::assets {

namespace {
constexpr Factory kFactories[] = {
    {AssetKind::ConiferTree, "spruce", 50, generate_spruce},
    {AssetKind::ConiferTree, "pine", 50, generate_pine},
    {AssetKind::ConiferTree, "larch", 50, generate_larch},
    {AssetKind::BroadleafTree, "beech", 50, generate_beech},
    {AssetKind::BroadleafTree, "birch", 50, generate_birch},
    {AssetKind::BroadleafTree, "oak", 50, generate_oak},
    {AssetKind::DeadTree, "dead_tree", 20, generate_dead_tree},
    {AssetKind::Stump, "stump", 20, generate_stump},
    {AssetKind::Grass, "grass", 20, generate_grass},
    {AssetKind::Grass, "grass_tall", 20, generate_tall_grass},
    {AssetKind::Grass, "grass_sward", 20, generate_grass_sward},
    {AssetKind::Fern, "fern", 20, generate_fern, generate_young_fern},
    {AssetKind::Fern, "wood_sorrel", 20, generate_wood_sorrel},
    {AssetKind::Fern, "woodruff", 20, generate_woodruff},
    {AssetKind::Fern, "nettle", 20, generate_nettle, generate_young_nettle},
    {AssetKind::Fern, "wood_anemone", 20, generate_wood_anemone},
    {AssetKind::Shrub, "bilberry", 20, generate_bilberry},
    {AssetKind::Shrub, "hazel", 20, generate_hazel},
    {AssetKind::Shrub, "bramble", 20, generate_bramble},
    {AssetKind::Rock, "rock", 20, generate_rock},
    {AssetKind::Log, "log", 20, generate_log},
    {AssetKind::Log, "fallen_tree", 20, generate_fallen_tree},
    {AssetKind::GroundCover, "twig", 20, generate_twig},
    {AssetKind::GroundCover, "fallen_branch", 20, generate_fallen_branch},
    {AssetKind::GroundCover, "cone", 20, generate_cone},
    {AssetKind::GroundCover, "leaf_litter", 20, generate_leaf_litter},
    {AssetKind::GroundCover, "moss", 20, generate_moss_cushion},
};

/// "<prefix>_<ii>".
std::string variant_name(const Factory& factory, uint32_t variant) {
  char name[96];
  std::snprintf(name, sizeof name, "%s_%02u", factory.prefix, variant);
  return name;
}

/// True when the factories are in AssetKind order and every kind has at least one.
constexpr bool covers_every_kind_in_order() {
  size_t next = 0;
  for (const Factory& f : kFactories) {
    if (size_t(f.kind) == next) ++next;
    else if (size_t(f.kind) + 1 != next) return false;
  }
  return next == size_t(AssetKind::Count);
}
static_assert(covers_every_kind_in_order(), "factories in kind order, every kind covered");

}  // namespace

std::span<const Factory> factories() { return kFactories; }

const Factory* find_factory(const std::string& prefix) {
  for (const Factory& f : kFactories)
    if (prefix == f.prefix) return &f;
  return nullptr;
}

GeneratedAsset generate_variant(const Factory& factory, uint64_t seed, uint32_t variant, Season season) {
  uint64_t key = 0;
  for (const char* c = factory.prefix; *c; ++c) key = hash_combine(key, uint64_t(uint8_t(*c)));
  Rng rng(seed, hash_combine(key, variant), Purpose::AssetShape);
  GeneratedAsset g = season == Season::Spring && factory.young ? factory.young(rng) : factory.generate(rng);
  dress_for_season(g.mesh, season);
  return g;
}

Asset make_asset(const Factory& factory, uint64_t seed, uint32_t variant, Season season) {
  GeneratedAsset g = generate_variant(factory, seed, variant, season);
  Asset a;
  a.name = variant_name(factory, variant);
  a.source = ProceduralSource{factory.prefix, variant, seed};
  a.kind = factory.kind;
  a.role = g.role;
  LodChain chain = build_lods(g.mesh);
  a.lod_screen_sizes = std::move(chain.screen_sizes);
  a.geometry = std::make_shared<const AssetGeometry>(std::move(chain.lods));
  a.proxy = g.proxy;
  return a;
}

Asset lazy_asset(const Factory& factory, uint64_t seed, uint32_t variant, Role role, const CollisionProxy& proxy,
                 std::vector<float> lod_screen_sizes, Season season) {
  Asset a;
  a.name = variant_name(factory, variant);
  a.source = ProceduralSource{factory.prefix, variant, seed};
  a.kind = factory.kind;
  a.role = role;
  a.geometry = std::make_shared<const AssetGeometry>([&factory, source = *a.source, season] {
    return cached_lods(process_mesh_cache(), source, season, [&] {
      return build_lods(generate_variant(factory, source.seed, source.variant, season).mesh).lods;
    });
  });
  a.lod_screen_sizes = std::move(lod_screen_sizes);
  a.proxy = proxy;
  return a;
}

AssetLibrary generate_library(uint64_t seed, Season season) {
  AssetLibrary lib;
  for (const Factory& f : factories())
    for (uint32_t v = 0; v < f.variants; ++v) lib.assets.push_back(make_asset(f, seed, v, season));
  lib.index_kinds();
  return lib;
}

}  // namespace silva::assets
