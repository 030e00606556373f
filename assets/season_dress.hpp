#pragma once
/// @file Dresses a generated mesh for its season: deciduous leaf cards are young and light in spring, turn
/// autumn-coloured, or become bare twig cards in winter (their coverage, and so the labels, follow the new mask).
#include "core/mesh.hpp"
#include "core/season.hpp"

namespace silva::assets {

/// True for the card materials of deciduous trees and shrubs (larch needles included).
bool is_deciduous_foliage(Material m);

/// Summer: unchanged. Autumn: deciduous leaf parts get AutumnLeaves, larch needles AutumnNeedles.
/// Winter: deciduous foliage parts get the bare twig mask and BareTwigs (role unchanged: the bare
/// crown is still canopy). Fern fronds get AutumnLeaves in autumn and DeadBracken in winter;
/// grass cards AutumnGrass or WinterGrass. Spring: deciduous foliage parts (larch needles included) get
/// SpringLeaves, the rest stays as in summer. Early spring: as winter, and bracken (fern fronds) laid flat
/// (lay_flat) and MattedBracken. Evergreen needles and everything solid stay as they are.
void dress_for_season(Mesh& mesh, Season season);

/// Height factor of last year's bracken in early spring: winter's snow and storms have laid its dead fronds on the litter.
inline constexpr float kFlatBrackenHeight = 0.15f;
/// Factor on the horizontal reach of flattened bracken: the fronds fall outwards from the crown.
inline constexpr float kFlatBrackenSpread = 1.3f;

/// Lays a plant flat: heights times kFlatBrackenHeight and horizontal offsets from its base times
/// kFlatBrackenSpread, normals transformed alike (by the inverse transpose).
void lay_flat(Mesh& mesh);

}  // namespace silva::assets
