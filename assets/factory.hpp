#pragma once
/// @file The built-in asset factories (Infinigen habit): each variant i of a factory is seeded by
/// hash(seed, kind, prefix, i), so a variant never depends on which other variants were
/// generated, and factories sharing a kind (several tree species) draw independent streams.
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
};

/// Every built-in factory, in library order (AssetKind order; several may share a kind).
std::span<const Factory> factories();

/// Runs `factory` for `variant` (RNG keyed by the kind, prefix and variant, Purpose::AssetShape) and
/// builds the LODs and thresholds; the asset's file is "<name>.glb".
Asset make_asset(const Factory& factory, uint64_t seed, uint32_t variant);

/// The whole built-in library (every factory, every variant), kinds indexed.
AssetLibrary generate_library(uint64_t seed = kDefaultAssetSeed);

}  // namespace silva::assets
