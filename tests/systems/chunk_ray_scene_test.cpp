// The LiDAR's chunk scene leaves out the ground cover of chunks beyond its cut-off from the eye: a
// sweep through it equals, point for point, a sweep through a scene holding every instance.
#include <gtest/gtest.h>

#include "raycast/lidar.hpp"
#include "systems/cast_lidar.hpp"
#include "tests/common/default_world.hpp"
#include "world/chunk_cache.hpp"
#include "world/chunk_regions.hpp"

namespace silva {
namespace {

/// 32 beams from -25 to +6 degrees, 512 columns, the default noise and dropout.
raycast::LidarPreset thirty_two_beams() {
  raycast::LidarPreset p;
  p.name = "test32";
  for (int r = 0; r < 32; ++r) p.elevations_deg.push_back(-25.0 + r);
  p.columns = 512;
  p.max_range = 50;
  return p;
}

/// True when the two sweeps hold the same points, field for field.
bool same_points(const std::vector<LidarPoint>& a, const std::vector<LidarPoint>& b) {
  if (a.size() != b.size()) return false;
  for (size_t i = 0; i < a.size(); ++i)
    if (a[i].position != b[i].position || a[i].intensity != b[i].intensity || a[i].range != b[i].range ||
        a[i].time != b[i].time || a[i].ring != b[i].ring || a[i].column != b[i].column || a[i].role != b[i].role ||
        a[i].instance_id != b[i].instance_id)
      return false;
  return true;
}

TEST(ChunkRayScene, GroundCoverOutOfReachIsLeftOutWithoutChangingASweep) {
  const test::DefaultWorld w;
  const Vec3d eye = w.camera.position();
  const raycast::LidarPreset preset = thirty_two_beams();
  world::ChunkCache cache(256);
  const auto chunks =
      cache.require(w.ctx, world::chunks_in_disc(eye.x(), eye.y(), preset.max_range, w.ctx.chunk_size()));
  const systems::SceneBuilder builder(*w.library);
  const double distance = w.cfg.render.ground_cover_distance;

  raycast::RayScene everything;
  size_t all_instances = 0;
  for (const auto& c : chunks) {
    systems::ChunkRays rays = builder.ray_instances(*c, distance);
    rays.solid.insert(rays.solid.end(), rays.ground_cover.begin(), rays.ground_cover.end());
    everything.add_group(c->coord.key(), rays.solid);
    all_instances += rays.solid.size();
  }
  everything.commit();

  systems::ChunkRayScene pruned;
  const Vec3d far_away = eye + Vec3d(10 * distance, 0, 0);
  pruned.sync(chunks, builder, distance, far_away);
  const size_t far_instances = pruned.scene->instance_count();
  pruned.sync(chunks, builder, distance, eye);  // the eye comes back: the near ground cover returns
  EXPECT_LT(far_instances, pruned.scene->instance_count());
  EXPECT_LT(pruned.scene->instance_count(), all_instances);

  raycast::SweepPose pose;
  pose.position = eye;
  pose.seed = 3;
  pose.key = 4;
  raycast::CastOptions options;
  options.eye = eye;
  const std::vector<LidarPoint> reference = raycast::cast_sweep(everything, preset, pose, options);
  const std::vector<LidarPoint> points = raycast::cast_sweep(*pruned.scene, preset, pose, options);
  size_t ground_cover = 0;
  for (const LidarPoint& p : points) ground_cover += p.role == Role::GroundVegetation ? 1 : 0;
  EXPECT_GT(ground_cover, 0u) << "the sweep should meet ground cover near the eye";
  EXPECT_TRUE(same_points(points, reference));
}

}  // namespace
}  // namespace silva
