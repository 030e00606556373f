// Binning (render/bin.hpp): a triangle lands in exactly the tiles where each of its edges is
// non-negative at some pixel centre of the part of the tile inside its bounds, checked pixel by
// pixel over slivers that cross many tiles.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <set>
#include <utility>
#include <vector>

#include "render/bin.hpp"

namespace silva::render {
namespace {

/// (tile, triangle index) pairs.
using Placements = std::set<std::pair<int, uint32_t>>;

/// The pairs brute force expects: for every tile the triangle's bounds touch, each edge's largest
/// value over the pixel centres of the tile's part inside the bounds, found by visiting them all.
Placements expected(const GeometryStore& store, const std::vector<TriBounds>& bounds, const TileGrid& grid) {
  Placements out;
  for (uint32_t i = 0; i < store.tris.size(); ++i) {
    const TriBounds& b = bounds[i];
    for (int ty = b.y0 / grid.tile_size; ty <= b.y1 / grid.tile_size; ++ty)
      for (int tx = b.x0 / grid.tile_size; tx <= b.x1 / grid.tile_size; ++tx) {
        const int x0 = std::max(b.x0, tx * grid.tile_size), x1 = std::min(b.x1, (tx + 1) * grid.tile_size - 1);
        const int y0 = std::max(b.y0, ty * grid.tile_size), y1 = std::min(b.y1, (ty + 1) * grid.tile_size - 1);
        bool all = true;
        for (const EdgeFunction& e : store.tris[i].edge) {
          double best = -1e300;
          for (int y = y0; y <= y1; ++y)
            for (int x = x0; x <= x1; ++x) best = std::max(best, e.at(double(x), double(y)));
          all = all && best >= 0.0;
        }
        if (all) out.emplace(ty * grid.tiles_x + tx, i);
      }
  }
  return out;
}

/// The pairs the store's bins hold, checking each entry's pixel range against the bounds.
Placements binned(const GeometryStore& store, const std::vector<TriBounds>& bounds, const TileGrid& grid) {
  Placements out;
  for (int tile = 0; tile < grid.count(); ++tile)
    for (const BinEntry& e : store.bins[size_t(tile)]) {
      const TriBounds& b = bounds[e.index];
      const int ox = (tile % grid.tiles_x) * grid.tile_size, oy = (tile / grid.tiles_x) * grid.tile_size;
      EXPECT_EQ(ox + e.x0, std::max(b.x0, ox));
      EXPECT_EQ(oy + e.y1, std::min(b.y1, oy + grid.tile_size - 1));
      EXPECT_EQ(e.depth_max, b.depth_max);
      EXPECT_TRUE(out.emplace(tile, e.index).second) << "triangle " << e.index << " twice in tile " << tile;
    }
  return out;
}

TEST(RasterBin, SliversLandInExactlyTheTilesTheyMayCover) {
  const ViewProjection view = ViewProjection::from_camera(Camera::from_fov(320, 200, 90.0, 0.05, 100.0));
  const SetupView sv(view);
  const TileGrid grid = TileGrid::make(320, 200, 16);
  GeometryStore store;
  store.reset(grid.count());
  std::vector<TriBounds> all_bounds;
  std::mt19937 gen(5);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  size_t crossing = 0;
  for (uint32_t t = 0; t < 300; ++t) {
    // A long, thin triangle: two far-apart points and a third just off their line.
    const Vec3d a(u(gen) * 9, u(gen) * 6, 10), b(u(gen) * 9, u(gen) * 6, 10);
    const Vec3d c = a + 0.3 * (b - a) + 0.02 * Vec3d(u(gen), u(gen), 0);
    SetupVertex v[3];
    v[0].p = a;
    v[1].p = b;
    v[2].p = c;
    TriangleInput in;
    in.cull_back = false;
    in.inside_view = false;
    for (int k = 0; k < 3; ++k) in.v[k] = &v[k];
    in.key = t;
    TriBounds bounds[kMaxSetupTriangles];
    const size_t first = store.tris.size();
    const int emitted = setup_triangle(sv, in, store.tris, store.alphas, bounds, store.counters);
    for (int k = 0; k < emitted; ++k) {
      all_bounds.push_back(bounds[k]);
      store.bin(uint32_t(first + size_t(k)), bounds[k], grid);
      crossing += grid.tile_of(bounds[k].x0) != grid.tile_of(bounds[k].x1) ? 1 : 0;
    }
  }
  ASSERT_GT(crossing, 200u);
  const Placements want = expected(store, all_bounds, grid);
  EXPECT_EQ(binned(store, all_bounds, grid), want);
  // Slivers leave most of their bounds' tiles out: the test has rejections to check.
  size_t bounds_tiles = 0;
  for (const TriBounds& b : all_bounds)
    bounds_tiles += size_t(b.x1 / 16 - b.x0 / 16 + 1) * size_t(b.y1 / 16 - b.y0 / 16 + 1);
  EXPECT_LT(want.size() * 2, bounds_tiles);
}

}  // namespace
}  // namespace silva::render
