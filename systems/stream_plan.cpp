#include "systems/stream_plan.hpp"

#include <algorithm>
#include <set>

#include "systems/chunk_regions.hpp"

namespace silva::world {

namespace {

/// True if sorted `v` holds c.
bool contains(const std::vector<ChunkCoord>& v, ChunkCoord c) { return std::binary_search(v.begin(), v.end(), c); }

}  // namespace

std::vector<ChunkCoord> needed_chunks(const std::vector<Camera>& cameras, const std::vector<ChunkCoord>& pinned,
                                      double radius, double chunk_size) {
  std::vector<ChunkCoord> out = pinned;
  for (const Camera& cam : cameras) {
    const Vec3d p = cam.position();
    const auto disc = chunks_in_disc(p.x(), p.y(), radius, chunk_size);
    const auto view = chunks_in_view(cam, chunk_size);
    out.insert(out.end(), disc.begin(), disc.end());
    out.insert(out.end(), view.begin(), view.end());
  }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

StreamPlan plan_stream(const std::vector<ChunkCoord>& required, const std::vector<ChunkCoord>& keep,
                       const std::map<ChunkCoord, bool>& live, int ring) {
  std::set<ChunkCoord> halo;
  for (ChunkCoord c : required)
    for (int dj = -ring; dj <= ring; ++dj)
      for (int di = -ring; di <= ring; ++di) {
        const ChunkCoord n{c.i + di, c.j + dj};
        if (!contains(required, n)) halo.insert(n);
      }
  StreamPlan plan;
  for (ChunkCoord c : required) {
    const auto it = live.find(c);
    if (it == live.end()) plan.spawn_full.push_back(c);
    else if (it->second) plan.promote.push_back(c);
  }
  for (ChunkCoord c : halo)
    if (!live.count(c)) plan.spawn_halo.push_back(c);
  for (const auto& [c, is_halo] : live) {
    const bool needed = contains(required, c) || halo.count(c) || (!is_halo && contains(keep, c));
    if (!needed) plan.despawn.push_back(c);
  }
  return plan;
}

}  // namespace silva::world
