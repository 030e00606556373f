#pragma once
/// @file What kind of object an asset is: shared by the asset library, placement and the outputs.
#include <cstdint>

namespace silva {

/// What kind of object an asset is, which decides how placement uses it.
enum class AssetKind : uint8_t {
  ConiferTree,
  BroadleafTree,
  DeadTree,
  Stump,
  Grass,
  Fern,         ///< The fern layer of ground vegetation: ferns and forest herbs (wood sorrel).
  Shrub,
  Rock,
  Log,
  GroundCover,  ///< Small forest-floor debris (twigs, cones, litter, moss): labelled as ground.
  Count,
};

}  // namespace silva
