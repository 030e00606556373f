#pragma once
/// @file Procedural bark of the grown tree species (core/material.hpp BarkSpruce ... BarkOak).
#include "render/materials.hpp"

namespace silva::render {

/// Steepest fissure wall the bark relief gives (rise over run): 45 degrees.
inline constexpr float kMaxBarkSlope = 1.0f;

/// True for the grown species' barks (core/material.hpp BarkSpruce ... BarkOak).
bool is_species_bark(Material m);

/// A species bark point's look: its colour and the relief its shading normal adds.
struct SpeciesBark {
  Vec3f albedo;  ///< Linear-RGB albedo.
  /// Gradient (rise per metre, world axes) of the walls of the fissures between its plates (3 cm deep
  /// on pine and oak, 2 cm on larch, 1.5 cm on birch's base, 5 mm between spruce's scales); zero on
  /// plate tops and on beech's smooth bark.
  Vec3f slope;
};

/// The look of species bark point `s`, from one lookup of the plate under it: uv.y is the height
/// fraction in the tree (0 at the ground, 1 at the top), which decides pine's orange upper bark and
/// birch's dark base; past two fissure widths per pixel (SurfacePoint::footprint) the plates give way
/// to their mean colour and the relief fades out.
SpeciesBark species_bark(const SurfacePoint& s);

}  // namespace silva::render
