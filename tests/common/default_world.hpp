#pragma once
/// @file The default world of seed 1234567890 with the generated asset library, and the camera of
/// the middle trail point looking along the trail (bench/default_view's pose), for tests that need
/// the real forest.
#include <memory>
#include <vector>

#include "assets/factory.hpp"
#include "world/plan_captures.hpp"
#include "world/world_context.hpp"

namespace silva::test {

/// The generated library, the default config at seed 1234567890, its world context and the camera.
struct DefaultWorld {
  std::unique_ptr<assets::AssetLibrary> library = std::make_unique<assets::AssetLibrary>(assets::generate_library());
  Config cfg = seeded(1234567890);                                     ///< Defaults but the seed.
  world::WorldContext ctx = world::make_world_context(cfg, *library);  ///< The world.
  Camera camera = middle_of_trail(ctx);                                ///< The middle trail point, looking along it.

  /// The default config with `seed`.
  static Config seeded(int64_t seed) {
    Config c;
    c.seed = seed;
    return c;
  }
  /// The autopilot camera of the middle trail point at the middle yaw.
  static Camera middle_of_trail(const world::WorldContext& ctx) {
    const std::vector<world::PlannedFrame> poses = world::plan_autopilot(ctx);
    const size_t yaws = ctx.config.captures.autopilot_yaws.size();
    return poses[(poses.size() / yaws / 2) * yaws + yaws / 2].camera;
  }
};

}  // namespace silva::test
