// SIMD triangle setup (render/setup_lanes.hpp): the scalar setup_triangle + GeometryStore::bin
// bits, field by field, on every Highway target, over triangles that exercise every rejection.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include <Eigen/Geometry>

#include "highway_targets.hpp"
#include "render/setup_lanes.hpp"

namespace silva::render {
namespace {

/// A soup of view-space triangles in front of the camera with projected vertices and uvs.
struct Soup {
  std::vector<SetupVertex> vertices;  ///< Projected vertices.
  std::vector<Vec2f> uvs;             ///< One per vertex.
  std::vector<uint32_t> indices;      ///< 3 per triangle.
};

/// Adds a projected vertex at view position p with uv (u, v); returns its index.
uint32_t add_vertex(Soup& s, const ViewProjection& view, const Vec3d& p, float u, float v) {
  SetupVertex sv;
  sv.p = p;
  project_vertex(view, sv);
  s.vertices.push_back(sv);
  s.uvs.emplace_back(u, v);
  return uint32_t(s.vertices.size() - 1);
}

/// Random triangles z_near..z_far m away, centred within `spread` times the image's half extent
/// (1: inside the 90-degree 16:9 image): large, small, sub-pixel (one candidate pixel), degenerate
/// (repeated vertex), both windings, a few sharing vertices and one with a non-finite vertex.
Soup make_soup(const ViewProjection& view, unsigned seed, double z_near = 4.0, double z_far = 40.0, double spread = 0.8) {
  Soup s;
  std::mt19937 gen(seed);
  std::uniform_real_distribution<double> u01(0.0, 1.0);
  for (int t = 0; t < 603; ++t) {
    const double z = z_near + (z_far - z_near) * u01(gen);
    const Vec3d c((u01(gen) - 0.5) * 2.0 * spread * z, (u01(gen) - 0.5) * 1.125 * spread * z, z);
    const double size = t % 3 == 0 ? 0.002 : (t % 3 == 1 ? 0.05 : 1.5);  // ~0.1 px, a few px, large
    uint32_t v[3];
    for (uint32_t& i : v)
      i = add_vertex(s, view, c + size * Vec3d(u01(gen) - 0.5, u01(gen) - 0.5, u01(gen) - 0.5), float(u01(gen)),
                     float(u01(gen)));
    if (t % 17 == 0) v[2] = v[1];                                       // degenerate: facing 0
    if (t % 29 == 0 && t > 0) v[0] = s.indices[size_t(t - 1) * 3 + 1];  // shares a vertex
    s.indices.insert(s.indices.end(), {v[0], v[1], v[2]});
  }
  s.vertices[s.indices[5 * 3 + 1]].p.y() = std::numeric_limits<double>::quiet_NaN();
  return s;
}

/// The scalar front end: setup_triangle then bin, triangle by triangle.
void scalar_setup(const SetupView& sv, const Soup& soup, const AlphaBits* mask, bool cull_back, uint32_t instance,
                  bool inside_view, const TileGrid& grid, GeometryStore& store) {
  std::vector<SetupVertex> vertices = soup.vertices;
  TriangleInput in;
  in.mask = mask;
  in.cull_back = cull_back;
  in.inside_view = inside_view;
  TriBounds bounds[kMaxSetupTriangles];
  for (uint32_t t = 0; t < soup.indices.size() / 3; ++t) {
    for (int k = 0; k < 3; ++k) {
      in.v[k] = &vertices[soup.indices[t * 3 + uint32_t(k)]];
      in.uv[k] = &soup.uvs[soup.indices[t * 3 + uint32_t(k)]];
    }
    in.key = (uint64_t(instance) << 32) | t;
    const size_t first = store.tris.size();
    const int emitted = setup_triangle(sv, in, store.tris, store.alphas, bounds, store.counters);
    for (int k = 0; k < emitted; ++k) store.bin(uint32_t(first + size_t(k)), bounds[k], grid);
  }
}

/// Bit-for-bit equality of two planes.
bool same(const PixelPlane& a, const PixelPlane& b) { return a.c == b.c && a.a == b.a && a.b == b.b; }

/// Expects the two stores to hold the same triangles, alpha data, bins and counters.
void expect_same_stores(const GeometryStore& want, const GeometryStore& got) {
  ASSERT_EQ(want.tris.size(), got.tris.size());
  for (size_t i = 0; i < want.tris.size(); ++i) {
    const RasterTri &a = want.tris[i], &b = got.tris[i];
    for (int e = 0; e < 3; ++e)
      ASSERT_TRUE(a.edge[e].c == b.edge[e].c && a.edge[e].dx == b.edge[e].dx && a.edge[e].dy == b.edge[e].dy)
          << "triangle " << i << " edge " << e;
    ASSERT_TRUE(same(a.depth, b.depth)) << "triangle " << i;
    ASSERT_EQ(a.key, b.key);
    ASSERT_EQ(a.alpha, b.alpha);
  }
  ASSERT_EQ(want.alphas.size(), got.alphas.size());
  for (size_t i = 0; i < want.alphas.size(); ++i) {
    const AlphaAttrib &a = want.alphas[i], &b = got.alphas[i];
    ASSERT_TRUE(same(a.u, b.u) && same(a.v, b.v) && same(a.w, b.w)) << "alpha " << i;
    ASSERT_EQ(a.bits, b.bits);
  }
  ASSERT_EQ(want.bins.size(), got.bins.size());
  for (size_t tile = 0; tile < want.bins.size(); ++tile) {
    ASSERT_EQ(want.bins[tile].size(), got.bins[tile].size()) << "tile " << tile;
    for (size_t k = 0; k < want.bins[tile].size(); ++k) {
      const BinEntry &a = want.bins[tile][k], &b = got.bins[tile][k];
      ASSERT_TRUE(a.depth_max == b.depth_max && a.index == b.index && a.x0 == b.x0 && a.y0 == b.y0 && a.x1 == b.x1 &&
                  a.y1 == b.y1)
          << "tile " << tile << " entry " << k;
    }
  }
  EXPECT_EQ(want.bin_entries, got.bin_entries);
  EXPECT_EQ(want.counters.after_cull, got.counters.after_cull);
  EXPECT_EQ(want.counters.emitted, got.counters.emitted);
  EXPECT_EQ(want.counters.clipped, got.counters.clipped);
}

/// Expects setup_triangles_lanes of `soup` (frustum test on the lanes when `frustum_test`) to
/// equal the scalar setup on every Highway target, masked or not, culling back faces or not; the
/// soup must emit more than `min_emitted` screen triangles.
void expect_lanes_match_scalar(const Soup& soup, bool frustum_test, uint32_t min_emitted) {
  const SetupView sv(ViewProjection::from_camera(Camera::from_fov(1920, 1080, 90.0, 0.05, 150.0)));
  const TileGrid grid = TileGrid::make(1920, 1080, 64);
  AlphaMask mask;
  mask.width = mask.height = 4;
  mask.alpha.assign(16, 255);
  const AlphaBits bits = AlphaBits::of(mask);
  const uint32_t triangles = uint32_t(soup.indices.size() / 3);
  const std::vector<int64_t> targets = test::highway_targets();
  ASSERT_GE(targets.size(), 2u);
  for (const bool cull_back : {true, false})
    for (const AlphaBits* m : {static_cast<const AlphaBits*>(nullptr), &bits}) {
      GeometryStore want;
      want.reset(grid.count());
      scalar_setup(sv, soup, m, cull_back, 7, !frustum_test, grid, want);
      // The soup exercises every outcome: culled, rejected after culling, emitted over several tiles.
      EXPECT_LT(want.counters.after_cull, triangles);
      EXPECT_LT(want.counters.emitted, want.counters.after_cull);
      EXPECT_GT(want.counters.emitted, min_emitted);
      EXPECT_GT(want.bin_entries, want.counters.emitted);
      EXPECT_EQ(want.counters.clipped, 0u);
      for (const int64_t target : targets) {
        const test::PinnedTarget pinned(target);
        ASSERT_EQ(setup_simd_target(), target);
        SCOPED_TRACE(std::string(hwy::TargetName(target)) + (cull_back ? " cull" : " no cull") + (m ? " masked" : ""));
        GeometryStore got;
        got.reset(grid.count());
        // Two runs, split so that a group boundary falls mid-vector on every target.
        const LaneTriangles head{soup.indices.data(), 0,         13,       soup.vertices.data(), soup.uvs.data(),
                                 m,                   cull_back, uint64_t(7) << 32, frustum_test};
        LaneTriangles tail = head;
        tail.first = 13;
        tail.count = triangles - 13;
        setup_triangles_lanes(sv, head, grid, got);
        setup_triangles_lanes(sv, tail, grid, got);
        expect_same_stores(want, got);
      }
    }
}

TEST(SetupLanes, MatchTheScalarSetupOnEveryHighwayTarget) {
  const ViewProjection view = ViewProjection::from_camera(Camera::from_fov(1920, 1080, 90.0, 0.05, 150.0));
  expect_lanes_match_scalar(make_soup(view, 21), false, 603 / 5);
}

TEST(SetupLanes, TheFrustumTestOnLanesMatchesTheScalarSetupOnEveryHighwayTarget) {
  // Triangles up to 1.6x beyond the image's sides and 40 m beyond the 150 m far plane (inside the
  // guard band, in front of the near plane): the scalar setup tests each against the frustum.
  const ViewProjection view = ViewProjection::from_camera(Camera::from_fov(1920, 1080, 90.0, 0.05, 150.0));
  const Soup soup = make_soup(view, 22, 4.0, 190.0, 1.6);
  {
    // Without the frustum test some of these triangles would be kept: the test has work to do.
    const SetupView sv(view);
    GeometryStore all, tested;
    const TileGrid grid = TileGrid::make(1920, 1080, 64);
    all.reset(grid.count());
    tested.reset(grid.count());
    scalar_setup(sv, soup, nullptr, false, 7, true, grid, all);
    scalar_setup(sv, soup, nullptr, false, 7, false, grid, tested);
    EXPECT_GT(all.counters.after_cull, tested.counters.after_cull);
  }
  expect_lanes_match_scalar(soup, true, 603 / 30);
}

}  // namespace
}  // namespace silva::render
