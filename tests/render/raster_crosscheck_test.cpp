// Independent cross-check: the rasteriser against a brute-force double-precision ray caster.
#include <gtest/gtest.h>

#include <algorithm>
#include <limits>
#include <set>
#include <vector>

#include "raster_test_scenes.hpp"
#include "render/renderer.hpp"

namespace silva::render {
namespace {

/// World-space triangles of one instance, in groups with bounding boxes (a tiny BVH of one level).
struct Cluster {
  Vec3d lo, hi;                 ///< Bounds.
  std::vector<Vec3d> tri;       ///< 3 vertices per triangle.
  std::vector<Role> role;       ///< Per triangle.
  uint32_t instance_id = 0;     ///< Instance id of the owner.
};

/// Flattens the scene (LOD 0) into clusters of at most 64 triangles.
std::vector<Cluster> flatten(const Scene& scene) {
  std::vector<Cluster> out;
  for (const Instance& inst : scene.instances) {
    const Mesh& mesh = *scene.meshes[inst.mesh].lods[0];
    const Eigen::Matrix<double, 3, 4> m = inst.object_to_world.cast<double>();
    for (const MeshPart& part : mesh.parts)
      for (uint32_t i = part.first_index; i < part.first_index + part.index_count; i += 3) {
        if (out.empty() || out.back().role.size() == 64 || out.back().instance_id != inst.instance_id ||
            (i == part.first_index)) {
          out.emplace_back();
          out.back().lo = Vec3d::Constant(1e300);
          out.back().hi = Vec3d::Constant(-1e300);
          out.back().instance_id = inst.instance_id;
        }
        Cluster& c = out.back();
        for (int k = 0; k < 3; ++k) {
          const Vec3d p = m.leftCols<3>() * mesh.positions[mesh.indices[i + k]].cast<double>() + m.col(3);
          c.tri.push_back(p);
          c.lo = c.lo.cwiseMin(p);
          c.hi = c.hi.cwiseMax(p);
        }
        c.role.push_back(part.role);
      }
  }
  return out;
}

/// True when the ray o + t d (t in [t0, t1]) meets the box.
bool ray_box(const Vec3d& o, const Vec3d& d, const Vec3d& lo, const Vec3d& hi, double t0, double t1) {
  for (int a = 0; a < 3; ++a) {
    const double inv = 1.0 / d[a];
    double ta = (lo[a] - o[a]) * inv, tb = (hi[a] - o[a]) * inv;
    if (ta > tb) std::swap(ta, tb);
    t0 = std::max(t0, ta);
    t1 = std::min(t1, tb);
    if (t0 > t1) return false;
  }
  return true;
}

/// Nearest hit of the ray (Moller-Trumbore in double): t, role and instance id; t < 0 for none.
struct Hit {
  double t = -1.0;        ///< Ray parameter (= metric z: the direction has camera z 1).
  Role role = Role::Background;  ///< Role of the triangle hit.
  uint32_t instance_id = 0;      ///< Instance id of the triangle hit.
};

Hit cast(const std::vector<Cluster>& clusters, const Vec3d& o, const Vec3d& d, double t_min, double t_max) {
  Hit best;
  double limit = t_max;
  for (const Cluster& c : clusters) {
    if (!ray_box(o, d, c.lo, c.hi, t_min, limit)) continue;
    for (size_t k = 0; k < c.role.size(); ++k) {
      const Vec3d &a = c.tri[3 * k], &b = c.tri[3 * k + 1], &cc = c.tri[3 * k + 2];
      const Vec3d e1 = b - a, e2 = cc - a, p = d.cross(e2);
      const double det = e1.dot(p);
      if (det == 0.0) continue;
      const Vec3d s = o - a, q = s.cross(e1);
      const double u = s.dot(p) / det, v = d.dot(q) / det;
      if (u < 0.0 || v < 0.0 || u + v > 1.0) continue;
      const double t = e2.dot(q) / det;
      if (t < t_min || t > limit) continue;
      limit = t;
      best = Hit{t, c.role[k], c.instance_id};
    }
  }
  return best;
}

TEST(RasterCrossCheck, ForestSceneAgreesWithBruteForceRayCaster) {
  Camera cam;
  test::OwnedScene s = test::forest_scene(cam, 320, 240);
  Renderer renderer;
  GBuffer g;
  RenderOptions opt;
  opt.lod = false;
  RenderStats stats;
  renderer.render_gbuffer(s.scene, cam, opt, g, &stats);
  const std::vector<Cluster> clusters = flatten(s.scene);
  size_t role_agree = 0, id_agree = 0, depth_checked = 0, depth_bad = 0, hits = 0;
  std::set<Role> roles_seen;
  for (int v = 0; v < cam.height; ++v)
    for (int u = 0; u < cam.width; ++u) {
      const size_t i = size_t(v) * size_t(cam.width) + size_t(u);
      const Hit h = cast(clusters, cam.position(), cam.ray_direction(u, v), cam.near, cam.far);
      const Role want = h.t < 0.0 ? Role::Background : h.role;
      roles_seen.insert(want);
      hits += h.t >= 0.0;
      role_agree += g.role[i] == want;
      id_agree += g.instance_id[i] == (h.t < 0.0 ? 0u : h.instance_id);
      if (g.role[i] == want && h.t >= 0.0) {
        ++depth_checked;
        depth_bad += std::abs(double(g.depth[i]) - h.t) > 1e-3 * h.t;
      }
    }
  const double n = double(g.size());
  EXPECT_GE(double(role_agree) / n, 0.995) << role_agree << " of " << n;
  EXPECT_GE(double(id_agree) / n, 0.995) << id_agree << " of " << n;
  EXPECT_EQ(depth_bad, 0u) << "of " << depth_checked;
  // The scene really shows sky, ground, trunks, canopies and rocks.
  EXPECT_EQ(roles_seen.size(), 5u);
  EXPECT_GT(hits, size_t(0.3 * n));
  EXPECT_LT(hits, size_t(0.95 * n));
}

}  // namespace
}  // namespace silva::render
