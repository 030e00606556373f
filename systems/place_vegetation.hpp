#pragma once
/// @file Place phase: placement candidates of new chunks and their halos (system "place_vegetation").
#include "ecs/world.hpp"

namespace silva::systems {

/// Registers "place_vegetation" (phase Place): world::place_candidates for every chunk entity, in
/// parallel: solids and ground vegetation for full chunks, solids only for halos. The density,
/// class mix and spacing come from the WorldSource's config (vegetation.*).
void install_place_vegetation(ecs::World& world);

}  // namespace silva::systems
