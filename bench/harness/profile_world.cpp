#include "bench/harness/profile_world.hpp"

#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>

#include "pipeline/schedule/world_schedule.hpp"
#include "core/stopwatch.hpp"
#include "world/placement.hpp"
#include "bench/harness/pipeline_names.hpp"

namespace silva::bench {

namespace {

/// Per chunk: candidates per role and the time placement took.
struct ChunkPlacement {
  std::array<uint64_t, kRoleCount> by_role{};
  double seconds = 0;
};

/// Re-runs placement of each chunk's own candidates (pure, so identical to the build's) to count
/// candidates per class and time it per chunk.
std::vector<ChunkPlacement> count_candidates(const world::WorldContext& ctx, const std::vector<ChunkCoord>& coords,
                                             int threads) {
  std::vector<ChunkPlacement> out(coords.size());
  tbb::task_arena(threads).execute([&] {
    tbb::parallel_for(size_t(0), coords.size(), [&](size_t k) {
      const Stopwatch clock;
      const world::ChunkCandidates c = world::place_candidates(ctx, coords[k], true);
      out[k].seconds = clock.seconds();
      for (const auto* list : {&c.solids, &c.ground})
        for (const world::Candidate& cand : *list) ++out[k].by_role[size_t(ctx.library->assets[cand.asset].role)];
    });
  });
  return out;
}

/// True for roles that are things (trees, dead trees, stumps, shrubs, obstacles), not stuff.
bool is_thing(Role r) { return r != Role::GroundVegetation && r != Role::Ground && r != Role::Trail; }

}  // namespace

WorldProfile profile_world(const world::WorldContext& ctx, const std::vector<ChunkCoord>& coords, int threads) {
  const world::BuiltWorld w = build_world(ctx, coords, threads);
  const std::vector<ChunkPlacement> placement = count_candidates(ctx, coords, threads);
  const double s = ctx.chunk_size();
  WorldProfile p;
  p.chunks = w.totals.chunks;
  p.area_ha = double(p.chunks) * s * s / 1e4;
  p.objects = w.totals.objects;
  p.broad_queries = w.totals.broad_queries;
  p.narrow_queries = w.totals.narrow_queries;
  p.build_s = w.totals.total_s;

  int i0 = 0, j0 = 0, i1 = -1, j1 = -1;
  if (!w.chunks.empty()) {
    i0 = i1 = w.chunks[0].coord.i;
    j0 = j1 = w.chunks[0].coord.j;
  }
  for (const ChunkContent& c : w.chunks) {
    i0 = std::min(i0, c.coord.i), i1 = std::max(i1, c.coord.i);
    j0 = std::min(j0, c.coord.j), j1 = std::max(j1, c.coord.j);
  }
  const int cw = i1 - i0 + 1, ch = j1 - j0 + 1;
  std::vector<bool> inside(size_t(std::max(0, cw * ch)), false);
  for (const ChunkContent& c : w.chunks) inside[size_t(c.coord.j - j0) * cw + (c.coord.i - i0)] = true;

  const int per_chunk = std::max(1, int(std::lround(s / kHeatCell)));
  p.heat_width = cw * per_chunk;
  p.heat_height = ch * per_chunk;
  p.heat.assign(size_t(std::max(0, p.heat_width * p.heat_height)), 0);
  p.heat_inside.assign(p.heat.size(), false);
  for (int y = 0; y < p.heat_height; ++y)
    for (int x = 0; x < p.heat_width; ++x)
      p.heat_inside[size_t(y) * p.heat_width + x] = inside[size_t(y / per_chunk) * cw + x / per_chunk];

  std::vector<double> crowns(ctx.library->assets.size());
  for (size_t a = 0; a < crowns.size(); ++a) crowns[a] = crown_radius(ctx.library->assets[a]);
  constexpr int kCanopyLayer = 7;  // roles use layers 0..6 (see layer_of), canopy the last
  // Stuff on the ground itself (ground-cover debris, role ground) covers no layer: -1.
  const auto layer_of = [](Role r) { return r < Role::TreeTrunk ? -1 : std::min(6, int(r) - int(Role::TreeTrunk)); };
  CoverGrid cover(i0, j0, i1, j1, s, kCoverCell, inside);
  std::array<std::vector<Eigen::Vector2d>, kRoleCount> points;
  for (size_t k = 0; k < w.chunks.size(); ++k) {
    const ChunkContent& c = w.chunks[k];
    p.generate_ms_per_chunk += c.stats.generate_s * 1e3;
    p.resolve_ms_per_chunk += c.stats.resolve_s * 1e3;
    for (const Vegetation& v : c.objects) {
      ClassProfile& cls = p.classes[size_t(v.role)];
      ++cls.placed;
      cls.adjusted += v.placement == Placement::Adjusted ? 1 : 0;
      const Eigen::Vector2d at(v.position.x(), v.position.y());
      points[size_t(v.role)].push_back(at);
      const Disc crown{at, crowns[v.asset] * v.scale};
      if (layer_of(v.role) >= 0) cover.add(crown, layer_of(v.role));
      if (ctx.library->assets[v.asset].role == Role::TreeTrunk) cover.add(crown, kCanopyLayer);
      if (is_thing(v.role)) {
        const int hx = int(std::floor((at.x() - i0 * s) / kHeatCell)), hy = int(std::floor((at.y() - j0 * s) / kHeatCell));
        if (hx >= 0 && hx < p.heat_width && hy >= 0 && hy < p.heat_height) ++p.heat[size_t(hy) * p.heat_width + hx];
      }
    }
  }
  for (const ChunkPlacement& cp : placement) {
    p.place_ms_per_chunk += cp.seconds * 1e3;
    for (int r = 0; r < kRoleCount; ++r) p.classes[size_t(r)].candidates += cp.by_role[size_t(r)];
  }
  const double n = std::max<double>(1, double(p.chunks));
  p.generate_ms_per_chunk /= n;
  p.place_ms_per_chunk /= n;
  p.resolve_ms_per_chunk /= n;
  p.canopy_cover_pct = cover.percent(kCanopyLayer);
  for (int r = 0; r < kRoleCount; ++r) {
    ClassProfile& cls = p.classes[size_t(r)];
    p.candidates += cls.candidates;
    cls.dropped = cls.candidates >= cls.placed ? cls.candidates - cls.placed : 0;
    cls.per_ha = p.area_ha > 0 ? double(cls.placed) / p.area_ha : 0;
    if (cls.placed && layer_of(Role(r)) >= 0) cls.cover_pct = cover.percent(layer_of(Role(r)));
    cls.nearest = nearest_neighbours(points[size_t(r)]);
  }
  return p;
}

}  // namespace silva::bench
