#pragma once
/// @file The built-in asset factories (Infinigen habit): each variant i of a factory is seeded by
/// hash(seed, prefix, i), so a variant never depends on which other variants were generated,
/// and factories sharing a kind (several tree species) draw independent streams.
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "assets/generators.hpp"
#include "assets/library.hpp"
#include "core/season.hpp"

namespace silva::assets {

/// Seed of the library that `silva assets build` writes when none is given.
inline constexpr uint64_t kDefaultAssetSeed = 0x5117A0A55E7ull;

/// A generator of one asset kind with its variant count and asset-name prefix.
struct Factory {
  AssetKind kind;                     ///< Kind of every asset it makes.
  const char* prefix;                 ///< Asset names are "<prefix>_<ii>".
  uint32_t variants;                  ///< Variants in the built-in library.
  GeneratedAsset (*generate)(Rng&);   ///< The generator.
  /// The plant young, for spring (the same draws where it can), or null where spring changes only colours.
  GeneratedAsset (*young)(Rng&) = nullptr;
};

/// Every built-in factory, in library order (AssetKind order; several may share a kind).
std::span<const Factory> factories();

/// The factory whose prefix is `prefix`, or null.
const Factory* find_factory(const std::string& prefix);

/// Runs `factory` for `variant` (RNG keyed by the prefix and variant, Purpose::AssetShape), its `young`
/// generator in spring where it has one, and dresses the mesh for `season` (dress_for_season).
GeneratedAsset generate_variant(const Factory& factory, uint64_t seed, uint32_t variant,
                                Season season = Season::Summer);

/// Runs `factory` for `variant` and builds the LODs and thresholds now; no file.
Asset make_asset(const Factory& factory, uint64_t seed, uint32_t variant, Season season = Season::Summer);

/// Variant `variant` of `factory` with the given metadata (from library.json); its meshes are
/// generated for `season` and their LODs built when first used.
Asset lazy_asset(const Factory& factory, uint64_t seed, uint32_t variant, Role role, const CollisionProxy& proxy,
                 std::vector<float> lod_screen_sizes, Season season = Season::Summer);

/// The whole built-in library (every factory, every variant) for `season`, kinds indexed.
AssetLibrary generate_library(uint64_t seed = kDefaultAssetSeed, Season season = Season::Summer);

}  // namespace silva::assets
