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
  Count,
};

/// Name of a material (for the asset manifest and glTF material names).
const char* material_name(Material m);

/// Parses a material name; returns false if unknown.
bool parse_material(const char* name, Material& out);

}  // namespace silva
