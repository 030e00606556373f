// Planned poses keep their clearance (captures.clearance from solid proxies, and for aerial
// cameras captures.aerial_crown_clearance from tree crowns), checked against freshly generated
// chunks with the procedural library's real crowns; the search is deterministic.
#include "world/pose_clearance.hpp"

#include <gtest/gtest.h>

#include <fcl/geometry/shape/sphere.h>
#include <tbb/task_arena.h>

#include <cmath>
#include <map>
#include <vector>

#include "assets/factory.hpp"
#include "world/chunk_regions.hpp"
#include "world/collision_proxy.hpp"
#include "world/plan_captures.hpp"
#include "world/terrain.hpp"
#include "world/world_generator.hpp"
#include "tests/common/test_library.hpp"

namespace silva::world {
namespace {

/// The procedural library (real crowns), built once.
const assets::AssetLibrary& library() {
  static const assets::AssetLibrary lib = assets::generate_library();
  return lib;
}

/// Chunks generated afresh (not through the planner's cache), kept per coordinate.
class FreshWorld {
 public:
  explicit FreshWorld(const WorldContext& ctx) : ctx_(ctx) {}
  /// Objects of every chunk within `r` of (x, y).
  std::vector<Vegetation> objects_near(double x, double y, double r) {
    std::vector<Vegetation> out;
    for (ChunkCoord c : chunks_in_disc(x, y, r, ctx_.chunk_size())) {
      auto it = chunks_.find(c);
      if (it == chunks_.end()) it = chunks_.emplace(c, generate_chunk(ctx_, c)).first;
      out.insert(out.end(), it->second.objects.begin(), it->second.objects.end());
    }
    return out;
  }

 private:
  const WorldContext& ctx_;
  std::map<ChunkCoord, ChunkContent> chunks_;
};

/// World positions of the canopy vertices of `v`'s full-detail mesh.
std::vector<Vec3d> canopy_vertices(const Vegetation& v) {
  const Mesh& m = library().assets[v.asset].lods()[0];
  const Eigen::Matrix3d turn = Eigen::AngleAxisd(v.yaw, Vec3d::UnitZ()).toRotationMatrix();
  std::vector<Vec3d> out;
  for (const MeshPart& part : m.parts)
    if (part.role == Role::TreeCanopy)
      for (uint32_t i = part.first_index; i < part.first_index + part.index_count; ++i)
        out.push_back(v.position.cast<double>() + double(v.scale) * (turn * m.positions[m.indices[i]].cast<double>()));
  return out;
}

/// Distance from `p` to the nearest canopy vertex of `v` (world space).
double crown_distance(const Vegetation& v, const Vec3d& p) {
  double d = INFINITY;
  for (const Vec3d& w : canopy_vertices(v)) d = std::min(d, (w - p).norm());
  return d;
}

/// Highest canopy vertex of `v` (world z) within `reach` horizontally of `p`; -inf if none.
double highest_canopy_near(const Vegetation& v, const Vec3d& p, double reach) {
  double top = -INFINITY;
  for (const Vec3d& w : canopy_vertices(v))
    if (std::hypot(w.x() - p.x(), w.y() - p.y()) <= reach) top = std::max(top, w.z());
  return top;
}

/// The plan of `cfg` on `threads` threads with a chunk cache of `capacity`.
std::vector<PlannedFrame> plan(const Config& cfg, int threads, size_t capacity) {
  const WorldContext ctx = make_world_context(cfg, library());
  ChunkCache cache(capacity);
  std::vector<PlannedFrame> frames;
  tbb::task_arena(threads).execute([&] { frames = plan_captures(ctx, cache, {}, [](const std::string&) {}); });
  return frames;
}

TEST(PoseClearance, ThousandPlannedPosesKeepTheirClearanceOrAreCounted) {
  int checked = 0, moved = 0, unresolvable = 0, lifted = 0;
  int by_mode[2][3] = {};  // [aerial][PoseFix]
  for (const int64_t seed : {1, 7, 99, 123456, 2024}) {
    for (const bool aerial : {false, true}) {
      Config cfg = test::small_world_config(seed, 5);  // the default density
      cfg.captures.aerial = aerial;
      cfg.captures.random_count = 100;
      cfg.captures.autopilot_points = 20;
      cfg.captures.autopilot_yaws = {0};
      const WorldContext ctx = make_world_context(cfg, library());
      const std::vector<PlannedFrame> frames = plan(cfg, 2, 64);
      FreshWorld world(ctx);
      for (const PlannedFrame& f : frames) {
        SCOPED_TRACE("seed " + std::to_string(seed) + (aerial ? " aerial " : " ground ") + f.sequence + " " +
                     std::to_string(f.frame));
        ++checked;
        moved += f.pose_fix == PoseFix::Moved;
        ++by_mode[aerial][int(f.pose_fix)];
        if (f.pose_fix == PoseFix::Unresolvable) {
          ++unresolvable;
          continue;
        }
        const Vec3d eye = f.camera.position();
        const double ground = terrain_height(ctx.terrain, eye.x(), eye.y());
        if (aerial) {  // aerial_height above the ground and every crown within the margin, and no higher than needed
          const double base = eye.z() - cfg.camera.aerial_height;
          double under = ground, any = ground;
          for (const Vegetation& v : world.objects_near(eye.x(), eye.y(), 20.0)) {
            under = std::max(under, highest_canopy_near(v, eye, kAerialCanopyMargin));
            any = std::max(any, highest_canopy_near(v, eye, INFINITY));
          }
          EXPECT_GE(base, under - 1e-3);
          EXPECT_LE(base, any + 1e-3);
          lifted += base > ground + 1.0;
        } else {
          EXPECT_NEAR(eye.z() - ground, cfg.camera.ground_height, 1e-3);
        }
        // Probes: the eye, and for ground cameras the column below it.
        std::vector<Vec3d> probes = {eye};
        if (!aerial)
          for (double h = 0.1; h < eye.z() - ground; h += 0.1) probes.emplace_back(eye.x(), eye.y(), ground + h);
        for (const Vegetation& v : world.objects_near(eye.x(), eye.y(), 20.0)) {
          const auto& proxy = library().assets[v.asset].proxy;
          if (proxy.shape != assets::CollisionProxy::Shape::None) {
            const PlacedProxy placed = place_proxy(proxy, v.position, v.yaw, v.scale);
            for (const Vec3d& p : probes) {
              PlacedProxy ball;
              ball.geometry = std::make_shared<fcl::Spheref>(float(cfg.captures.clearance) - 1e-3f);
              ball.transform.translation() = p.cast<float>();
              EXPECT_FALSE(proxies_collide(ball, placed)) << library().assets[v.asset].name;
            }
          }
          EXPECT_GE(crown_distance(v, eye),
                    (aerial ? cfg.captures.aerial_crown_clearance : cfg.captures.ground_crown_clearance) - 1e-3);
        }
      }
    }
  }
  std::printf("%d poses planned, %d moved, %d unresolvable (ground: %d clear, %d moved, %d unresolvable; "
              "aerial: %d clear, %d moved, %d unresolvable)\n",
              checked, moved, unresolvable, by_mode[0][0], by_mode[0][1], by_mode[0][2], by_mode[1][0], by_mode[1][1],
              by_mode[1][2]);
  EXPECT_GE(checked, 1000);
  EXPECT_GT(moved, 0);
  // Ground poses always find room; aerial eyes fly above the canopy under them, clear of every crown.
  EXPECT_EQ(by_mode[0][int(PoseFix::Unresolvable)], 0);
  EXPECT_EQ(by_mode[1][int(PoseFix::Unresolvable)], 0);
  EXPECT_EQ(by_mode[1][int(PoseFix::Moved)], 0);
  EXPECT_GT(lifted, (by_mode[1][0] + by_mode[1][1]) / 4);  // most stand over trees
}

TEST(PoseClearance, SearchIsDeterministicForAnyThreadCountAndCache) {
  for (const bool aerial : {false, true}) {
    Config cfg = test::small_world_config(7, 15);
    cfg.captures.aerial = aerial;
    cfg.captures.random_count = 30;
    cfg.captures.autopilot_points = 12;
    const std::vector<PlannedFrame> a = plan(cfg, 1, 4), b = plan(cfg, 2, 256);
    ASSERT_EQ(a.size(), b.size());
    int moved = 0;
    for (size_t k = 0; k < a.size(); ++k) {
      EXPECT_EQ(a[k].camera.camera_to_world, b[k].camera.camera_to_world);
      EXPECT_EQ(a[k].pose_fix, b[k].pose_fix);
      EXPECT_EQ(a[k].trail_s, b[k].trail_s);
      moved += a[k].pose_fix == PoseFix::Moved;
    }
    if (!aerial) {
      EXPECT_GT(moved, 0) << "a dense forest should make the search move some ground poses";
    }
  }
}

}  // namespace
}  // namespace silva::world
