#pragma once
/// @file Stream phase, first step: the frame's camera and the chunks its view needs (system "aim_camera").
#include "ecs/world.hpp"

namespace silva::systems {

/// Registers "aim_camera" (phase Stream): makes the next camera of the CaptureQueue resource active
/// (none when the queue is done) and sets the ViewChunks resource to the chunks its view needs:
/// those meeting its frustum plus the disc whose objects may cast shadows into it.
void install_aim_camera(ecs::World& world);

}  // namespace silva::systems
