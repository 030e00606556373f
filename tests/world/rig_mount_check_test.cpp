// A rig's cameras never sit inside a solid object: the right camera of a stereo pair placed in a real trunk fails
// the plan with one line naming the camera, frame and object; the same pose with one camera, or with the right
// camera in the open, passes. The rig's height and tilt place the trajectory walk's camera.
#include "world/rig_mount_check.hpp"

#include <gtest/gtest.h>

#include <optional>

#include "assets/factory.hpp"
#include "core/error.hpp"
#include "world/plan_captures.hpp"
#include "world/pose_clearance.hpp"
#include "world/terrain.hpp"
#include "world/world_generator.hpp"
#include "tests/common/test_library.hpp"

namespace silva::world {
namespace {

/// The procedural library (real proxies), built once.
const assets::AssetLibrary& library() {
  static const assets::AssetLibrary lib = assets::generate_library();
  return lib;
}

/// A point 1 m above the ground contact of the first tree with a solid proxy in chunk (0, 0) of `ctx`.
std::optional<Vec3d> trunk_point(const WorldContext& ctx) {
  for (const Vegetation& v : generate_chunk(ctx, ChunkCoord{0, 0}).objects) {
    const assets::Asset& a = ctx.library->assets[v.asset];
    if ((a.kind == AssetKind::ConiferTree || a.kind == AssetKind::BroadleafTree) &&
        a.proxy.shape != assets::CollisionProxy::Shape::None)
      return v.position.cast<double>() + Vec3d(0, 0, 1.0);
  }
  return std::nullopt;
}

/// One custom frame whose left camera (world-aligned axes: its x is world +X) is at `left`.
std::vector<PlannedFrame> custom_frame(const WorldContext& ctx, const Vec3d& left) {
  PoseEntry pose;
  pose.position = left;
  return plan_custom(ctx, {pose});
}

TEST(RigMountCheck, RightCameraInsideATrunkFailsWithOneLineNamingIt) {
  Config cfg = test::small_world_config(7);
  cfg.rig.cameras = 2;
  cfg.rig.baseline_m = 0.5;
  const WorldContext ctx = make_world_context(cfg, library());
  const std::optional<Vec3d> trunk = trunk_point(ctx);
  ASSERT_TRUE(trunk.has_value());
  ChunkCache cache(64);
  const std::vector<PlannedFrame> frames = custom_frame(ctx, *trunk - Vec3d(0.5, 0, 0));
  try {
    check_rig_mounts(ctx, cache, frames);
    FAIL() << "a right camera inside a trunk passed";
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("rig.cameras = 2, rig.baseline_m = 0.5"), std::string::npos) << what;
    EXPECT_NE(what.find("the right camera of custom frame 0"), std::string::npos) << what;
    EXPECT_NE(what.find("_tree"), std::string::npos) << what;
    EXPECT_EQ(what.find('\n'), std::string::npos) << what;
  }
}

TEST(RigMountCheck, OneCameraOrARightCameraInTheOpenPasses) {
  Config cfg = test::small_world_config(7);
  const WorldContext mono_ctx = make_world_context(cfg, library());
  const std::optional<Vec3d> trunk = trunk_point(mono_ctx);
  ASSERT_TRUE(trunk.has_value());
  ChunkCache cache(64);
  // Mono: the same left camera has no mount to check.
  EXPECT_NO_THROW(check_rig_mounts(mono_ctx, cache, custom_frame(mono_ctx, *trunk - Vec3d(0.5, 0, 0))));
  // Stereo with the left camera in the trunk (a user's custom pose, not a mount) and the right one in the open.
  cfg.rig.cameras = 2;
  cfg.rig.baseline_m = 2.0;
  const WorldContext ctx = make_world_context(cfg, library());
  const std::vector<PlannedFrame> frames = custom_frame(ctx, *trunk);
  const Vec3d right = *trunk + Vec3d(2.0, 0, 0);
  const CrownProfiles crowns(library());
  const ClearanceProbe probe(ctx, crowns,
                             cache.require(ctx, {ChunkCoord{-1, -1}, ChunkCoord{-1, 0}, ChunkCoord{0, -1}, ChunkCoord{0, 0},
                                                 ChunkCoord{1, 0}, ChunkCoord{0, 1}, ChunkCoord{1, 1}, ChunkCoord{-1, 1},
                                                 ChunkCoord{1, -1}}),
                             right.x(), right.y(), 0.0);
  ASSERT_EQ(probe.solid_at(right, cfg.camera.near), nullptr) << "pick another seed: the right camera meets an object";
  EXPECT_NO_THROW(check_rig_mounts(ctx, cache, frames));
}

TEST(RigHeight, TrajectoryCamerasWalkAtTheRigsHeightAndTilt) {
  for (const auto& [height, pitch, expected] : {std::tuple{0.55, 0.0, 0.55}, std::tuple{3.0, -15.0, 3.0},
                                                std::tuple{0.0, 0.0, 1.5}}) {  // 0: camera.ground_height
    Config cfg = test::small_world_config(7);
    cfg.rig.height_m = height;
    cfg.rig.pitch_deg = pitch;
    cfg.trajectory.duration_s = 1;
    cfg.trajectory.bob_m = 0;
    cfg.trajectory.sway_deg = 0;
    const WorldContext ctx = make_world_context(cfg, library());
    for (const PlannedFrame& f : plan_trajectory(ctx)) {
      const Vec3d p = f.camera.position();
      EXPECT_NEAR(p.z() - terrain_height(ctx.terrain, p.x(), p.y()), expected, 1e-3) << height << " frame " << f.frame;
      EXPECT_NEAR(f.pitch_deg, pitch, 1e-9) << height;
    }
  }
}

}  // namespace
}  // namespace silva::world
