#pragma once
/// @file Render phase: the active camera's LiDAR sweep through the ray-cast scene of its chunks
/// (system "cast_lidar"), and the scene kept up to date as chunks stream.
#include <cstdint>
#include <map>
#include <memory>
#include <vector>

#include "assets/library.hpp"
#include "core/aabb.hpp"
#include "core/config.hpp"
#include "ecs/world.hpp"
#include "raycast/ray_scene.hpp"
#include "systems/prepare_scene.hpp"

namespace silva::systems {

/// The ray-cast scene of the chunks around the active camera. Each chunk is two groups: its terrain
/// and objects, present while a view needs the chunk, and its ground cover, present only while the
/// eye is within the largest cut-off of it (beyond, every ray would walk its BVHs only for the
/// cut-off filter to reject each hit).
struct ChunkRayScene {
  /// One chunk of the scene.
  struct Held {
    std::shared_ptr<const ChunkContent> content;     ///< Keeps its meshes alive.
    uint64_t solid_key = 0;                           ///< Group of its terrain and objects.
    uint64_t cover_key = 0;                           ///< Group of its ground cover.
    std::vector<raycast::RayInstance> ground_cover;   ///< Its ground-cover instances.
    AABB anchors;                                     ///< Bounds of their anchors.
    double reach = 0;                                 ///< Their largest cut-off.
  };
  std::unique_ptr<raycast::RayScene> scene = std::make_unique<raycast::RayScene>();  ///< The BVHs.
  std::map<uint64_t, Held> chunks;  ///< By chunk key.
  uint64_t next_key = 0;            ///< Next unused group key.
  /// Makes the scene hold exactly `chunks` (a chunk whose content changed is replaced), with the
  /// ground cover of those within reach of `eye`, and commits it; returns how many chunks it added.
  size_t sync(const std::vector<std::shared_ptr<const ChunkContent>>& chunks, const SceneBuilder& builder,
              double ground_cover_distance, const Vec3d& eye);
  /// Removes both groups of `held` from the scene.
  void drop(const Held& held);
};

/// The LiDAR frame in the camera's OpenCV axes (x right, y down, z forward): [lidar] mount offset
/// and roll, pitch, yaw, given along the camera's heading (x forward, y left, z up).
Mat4d lidar_to_camera(const LidarConfig& mount);

/// Registers "cast_lidar" (phase Render, after render_views) and its ChunkRayScene resource: when a
/// camera is active and output type lidar is selected, brings the scene up to the PreparedScene's
/// chunks and casts the sweep of CaptureSettings::lidar from the camera's pose times
/// lidar_to_camera into FrameSlots::current; with lidar.motion_distortion an autopilot frame's sweep moves
/// along the trail at camera.autopilot_speed for one revolution.
void install_cast_lidar(ecs::World& world, const assets::AssetLibrary& library);

}  // namespace silva::systems
