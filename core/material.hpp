#pragma once
/// @file Procedural material kinds that mesh parts refer to; shading turns them into colour.
#include <cstdint>

namespace silva {

/// Which procedural shading function a surface uses.
enum class Material : uint8_t {
  Ground = 0,
  Trail,
  BarkConifer,
  BarkBroadleaf,
  BarkDead,
  Needles,
  Leaves,
  Grass,
  Fern,
  ShrubLeaves,
  Rock,
  Wood,
  LogBark,      ///< Bark of fallen wood and stumps: moss where it faces up.
  BrokenWood,   ///< Pale splintered or weathered wood of broken ends.
  Moss,         ///< Moss cushions.
  LeafLitter,   ///< Fallen brown leaves.
  BarkSpruce,     ///< Norway spruce: red-brown, finely scaled.
  BarkPine,       ///< Scots pine: grey-brown furrowed low on the trunk, orange flakes higher up (uv.y = height fraction).
  BarkLarch,      ///< Larch: red-brown, deeply furrowed.
  BarkBeech,      ///< Beech: smooth pale grey.
  BarkBirch,      ///< Silver birch: white with dark marks, dark rough base (uv.y = height fraction).
  BarkOak,        ///< Oak: dark grey-brown, deeply furrowed.
  NeedlesSpruce,  ///< Norway spruce needles: dark blue-green.
  NeedlesPine,    ///< Scots pine needles: grey-green.
  NeedlesLarch,   ///< Larch needles: soft light green.
  LeavesBeech,    ///< Beech leaves: fresh mid green.
  LeavesBirch,    ///< Birch leaves: light yellow-green.
  LeavesOak,      ///< Oak leaves: deep green.
  AutumnLeaves,   ///< Deciduous leaves in autumn: yellow, orange and brown by tree and card.
  AutumnNeedles,  ///< Larch needles in autumn: golden.
  BareTwigs,      ///< Twig cards of deciduous trees and shrubs in winter: grey-brown.
  AutumnGrass,    ///< Grass in autumn: straw and yellow-brown with a little green left.
  WinterGrass,    ///< Grass in winter: dry and pale.
  DeadBracken,    ///< Fern fronds in winter: dull grey-brown standing dead bracken.
  Soil,           ///< Bare forest soil: dark humus, paler mineral patches, small stones (root plates, clods).
  Herb,           ///< Soft leaves of forest herbs (wood sorrel): fresh light green in every season.
  SpringLeaves,   ///< Young leaves of deciduous trees and shrubs, and larch's new needles, in spring: light yellow-green.
  Petals,         ///< White petals of spring flowers (wood anemone).
  MattedBracken,  ///< Last year's bracken lying matted on the litter in early spring: rust to dark brown.
  Count,
};

/// Name of a material (for the asset manifest and glTF material names).
const char* material_name(Material m);

/// Parses a material name; returns false if unknown.
bool parse_material(const char* name, Material& out);

}  // namespace silva
