#pragma once
/// @file Which trail surface family a world's trail gets (trail.surface, drawn from the seed for "random").
#include <cstdint>
#include <string>

#include "core/trail_surface.hpp"

namespace silva::world {

/// The family trail.surface = `name` names, or for `random` one drawn from `seed` (each equally
/// likely). Throws InputError for any other name, listing the allowed ones.
TrailSurface trail_surface_of(const std::string& name, uint64_t seed);

}  // namespace silva::world
