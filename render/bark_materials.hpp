#pragma once
/// @file Procedural bark of the grown tree species (core/material.hpp BarkSpruce ... BarkOak).
#include "render/materials.hpp"

namespace silva::render {

/// Linear-RGB albedo of a species bark point; uv.y is the height fraction in the tree (0 at the
/// ground, 1 at the top), which decides pine's orange upper bark and birch's dark base; past two
/// fissure widths per pixel (SurfacePoint::footprint) the plates give way to their mean colour.
Vec3f species_bark_albedo(const SurfacePoint& s);

/// Steepest fissure wall the bark relief gives (rise over run): 45 degrees.
inline constexpr float kMaxBarkSlope = 1.0f;

/// Gradient (rise per metre, world axes) of a species bark's relief at a point seen with `footprint`
/// metres per pixel: the walls of the fissures between its plates (3 cm deep on pine and oak, 2 cm on
/// larch, 1.5 cm on birch's base, 5 mm between spruce's scales), fading out where a pixel spans two
/// fissure widths; zero on plate tops, on beech's smooth bark and on other materials.
Vec3f species_bark_slope(const SurfacePoint& s, float footprint);

}  // namespace silva::render
