#pragma once
/// @file Procedural bark of the grown tree species (core/material.hpp BarkSpruce ... BarkOak).
#include "render/materials.hpp"

namespace silva::render {

/// Linear-RGB albedo of a species bark point; uv.y is the height fraction in the tree (0 at the
/// ground, 1 at the top), which decides pine's orange upper bark and birch's dark base.
Vec3f species_bark_albedo(const SurfacePoint& s);

}  // namespace silva::render
