#pragma once
/// @file Species stands: trees of one kind grow in patches where one species dominates, as in real
/// managed forests, instead of every species mixed uniformly. A kind's assets are grouped by the
/// generator (species) that made them; a low-frequency noise field picks each spot's dominant group.
#include <array>
#include <cstdint>
#include <vector>

#include "assets/library.hpp"
#include "core/rng.hpp"
#include "core/season.hpp"
#include "world/forest_types.hpp"

namespace silva::world {

/// Share of a kind's objects that take their spot's dominant species (the rest draw any species).
inline constexpr double kDominantShare = 0.7;
/// Stand size: wavelength of the stand noise, metres.
inline constexpr double kStandScale = 80.0;

/// A kind's assets grouped by species, and the seeded stand field that chooses among them.
struct SpeciesStands {
  /// Per kind: asset indices grouped by generator (procedural source; file assets form one group),
  /// groups in order of first appearance in the library.
  std::array<std::vector<std::vector<uint32_t>>, size_t(AssetKind::Count)> groups;
  std::vector<uint32_t> vernal;  ///< The fern-layer assets of vernal herbs (world::vernal_herb) among them.
  double offset_x = 0, offset_y = 0;  ///< Seeded offset of the stand noise.
};

/// Groups `library`'s assets and seeds the stand field from `seed`; conifers, broadleaves, shrubs and
/// fern-layer herbs only of the species `forest` grows (every one by default) and that show in `season`.
SpeciesStands make_species_stands(const assets::AssetLibrary& library, uint64_t seed,
                                  const ForestType& forest = forest_types().front(), Season season = Season::Summer);

/// The asset an object of `kind` at (x, y) uses: its stand's dominant species with probability
/// kDominantShare, else any species; then a uniform variant of that species. Draws from `rng`.
/// Returns UINT32_MAX when the kind has no assets.
uint32_t pick_asset(const SpeciesStands& stands, AssetKind kind, double x, double y, Rng& rng);

/// A uniform choice among stands.vernal, drawn from `rng`; UINT32_MAX when it is empty.
uint32_t pick_vernal(const SpeciesStands& stands, Rng& rng);

}  // namespace silva::world
