#pragma once
/// @file The built-in asset factories (Infinigen habit): variant i of a kind's first factory is seeded
/// by hash(seed, kind, i), of its further factories by hash(seed, kind, i, stream), so a variant never
/// depends on which other variants were generated. Several factories may share a kind.
#include <cstdint>
#include <span>

#include "assets/generators.hpp"
#include "assets/library.hpp"

namespace silva::assets {

/// Seed of the library that `silva assets build` writes when none is given.
inline constexpr uint64_t kDefaultAssetSeed = 0x5117A0A55E7ull;

/// A generator of one asset kind with its variant count and asset-name prefix.
struct Factory {
  AssetKind kind;                     ///< Kind of every asset it makes.
  const char* prefix;                 ///< Asset names are "<prefix>_<ii>".
  uint32_t variants;                  ///< Variants in the built-in library.
  GeneratedAsset (*generate)(Rng&);   ///< The generator.
  uint32_t stream = 0;                ///< 0 for a kind's first factory, 1, 2, ... for the others.
};

/// Every built-in factory, in library order (AssetKind order, then stream).
std::span<const Factory> factories();

/// Runs `factory` for `variant` (RNG keyed by the kind and variant, Purpose::AssetShape) and
/// builds the LODs and thresholds; the asset's file is "<name>.glb".
Asset make_asset(const Factory& factory, uint64_t seed, uint32_t variant);

/// The whole built-in library (every factory, every variant), kinds indexed.
AssetLibrary generate_library(uint64_t seed = kDefaultAssetSeed);

}  // namespace silva::assets
