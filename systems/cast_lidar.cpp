#include "systems/cast_lidar.hpp"

#include <cmath>
#include <optional>
#include <set>

#include "components/camera.hpp"
#include "components/phase.hpp"
#include "components/sensor.hpp"
#include "components/world_source.hpp"
#include "core/stopwatch.hpp"
#include "raycast/lidar.hpp"
#include "render/post.hpp"
#include "systems/render_views.hpp"
#include "world/plan_captures.hpp"
#include "world/world_context.hpp"

namespace silva::systems {

namespace {

/// Distance from `p` to the box `b` (0 inside it).
double distance_to_box(const Vec3d& p, const AABB& b) {
  const Vec3d nearest = p.cwiseMax(b.min.cast<double>()).cwiseMin(b.max.cast<double>());
  return (p - nearest).norm();
}

}  // namespace

size_t ChunkRayScene::sync(const std::vector<std::shared_ptr<const ChunkContent>>& wanted, const SceneBuilder& builder,
                           double ground_cover_distance, const Vec3d& eye) {
  std::set<uint64_t> keep;
  for (const auto& c : wanted) keep.insert(c->coord.key());
  for (auto it = chunks.begin(); it != chunks.end();) {
    if (keep.count(it->first)) {
      ++it;
      continue;
    }
    drop(it->second);
    it = chunks.erase(it);
  }
  size_t added = 0;
  for (const auto& c : wanted) {
    Held& held = chunks[c->coord.key()];
    if (held.content != c) {
      if (held.content) drop(held);
      ChunkRays rays = builder.ray_instances(*c, ground_cover_distance);
      held = Held{};
      held.content = c;
      held.solid_key = next_key++;
      held.cover_key = next_key++;
      held.ground_cover = std::move(rays.ground_cover);
      for (const raycast::RayInstance& r : held.ground_cover) {
        held.anchors.extend(r.anchor);
        held.reach = std::max(held.reach, r.cutoff);
      }
      scene->add_group(held.solid_key, rays.solid);
      ++added;
    }
    const bool show = !held.ground_cover.empty() && distance_to_box(eye, held.anchors) <= held.reach;
    const bool shown = scene->has_group(held.cover_key);
    if (show && !shown) scene->add_group(held.cover_key, held.ground_cover);
    if (!show && shown) scene->remove_group(held.cover_key);
  }
  scene->commit();
  return added;
}

void ChunkRayScene::drop(const Held& held) {
  scene->remove_group(held.solid_key);
  scene->remove_group(held.cover_key);
}

Mat4d lidar_to_camera(const LidarConfig& mount) {
  constexpr double kDeg = 3.14159265358979323846 / 180.0;
  Mat3d flu_to_cv;  // columns: forward, left, up in OpenCV camera axes
  flu_to_cv << 0, -1, 0, 0, 0, -1, 1, 0, 0;
  const Mat3d rpy = (Eigen::AngleAxisd(mount.mount_rpy_deg[2] * kDeg, Vec3d::UnitZ()) *
                     Eigen::AngleAxisd(mount.mount_rpy_deg[1] * kDeg, Vec3d::UnitY()) *
                     Eigen::AngleAxisd(mount.mount_rpy_deg[0] * kDeg, Vec3d::UnitX()))
                        .toRotationMatrix();
  Mat4d m = Mat4d::Identity();
  m.block<3, 3>(0, 0) = flu_to_cv * rpy;
  m.block<3, 1>(0, 3) = flu_to_cv * Vec3d(mount.mount_offset[0], mount.mount_offset[1], mount.mount_offset[2]);
  return m;
}

void install_cast_lidar(ecs::World& world, const assets::AssetLibrary& library) {
  world.set_resource(ChunkRayScene{});
  world.system("cast_lidar")
      .phase(Phase::Render)
      .after("render_views")
      .reads_resource<WorldSource, CaptureSettings, PreparedScene>()
      .writes_resource<FrameSlots, ChunkRayScene>()
      .reads<LidarSensor>()
      .run([builder = SceneBuilder(library)](ecs::SystemContext& sys) {
        FrameSlots& slots = sys.resource<FrameSlots>();
        std::optional<Mat4d> mount;  // the rig's LiDAR, if it carries one
        sys.each<const LidarSensor>([&](const LidarSensor& l) { mount = l.sensor_to_camera; });
        if (!slots.current || !mount) return;
        const CaptureSettings& settings = sys.resource<const CaptureSettings>();
        const Stopwatch clock;
        FrameWork& work = *slots.current;
        const world::WorldContext& ctx = *sys.resource<const WorldSource>().ctx;
        const Config& config = ctx.config;
        ChunkRayScene& rays = sys.resource<ChunkRayScene>();
        const Camera& camera = work.frame.camera;
        rays.sync(sys.resource<const PreparedScene>().frame.chunks, builder, config.render.ground_cover_distance,
                  camera.position());
        const Mat4d sensor = camera.camera_to_world * *mount;
        raycast::SweepPose pose;
        pose.sensor_to_world = sensor.block<3, 3>(0, 0);
        pose.position = sensor.block<3, 1>(0, 3);
        pose.seed = uint64_t(config.seed);
        pose.key = render::noise_key(work.frame.sequence, uint64_t(work.frame.frame));
        if (config.lidar.motion_distortion && (work.frame.trail_s || work.frame.walk)) {
          const Mat4d end = world::sweep_end_pose(ctx, work.frame, settings.lidar.rotation_hz) * *mount;
          pose.end = raycast::SweepEnd{end.block<3, 3>(0, 0), end.block<3, 1>(0, 3)};
        }
        raycast::CastOptions options;
        options.eye = camera.position();
        work.lidar = raycast::cast_sweep(*rays.scene, settings.lidar, pose, options);
        work.lidar_s = clock.seconds();
      });
}

}  // namespace silva::systems
