#include "assets/lod.hpp"

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include <meshoptimizer.h>

namespace silva::assets {

namespace {

/// Simplifies one solid part's triangles (indices into `full`) to about `ratio` of them.
std::vector<uint32_t> simplify_part(const Mesh& full, const MeshPart& part, float ratio) {
  const uint32_t* src = full.indices.data() + part.first_index;
  const size_t triangles = part.index_count / 3;
  const size_t target = std::max<size_t>(3, size_t(std::lround(float(triangles) * ratio)) * 3);
  std::vector<uint32_t> out(part.index_count);
  const float* pos = full.positions[0].data();
  size_t n = meshopt_simplify(out.data(), src, part.index_count, pos, full.positions.size(), sizeof(Vec3f),
                              target, 0.2f, 0, nullptr);
  if (n > target + target / 4) {  // seams or borders held it back: fall back to sloppy clustering
    std::vector<uint32_t> sloppy(part.index_count);
    const size_t m = meshopt_simplifySloppy(sloppy.data(), src, part.index_count, pos, full.positions.size(),
                                            sizeof(Vec3f), target, 1.0f, nullptr);
    if (m >= 3 && m < n) {
      out.swap(sloppy);
      n = m;
    }
  }
  if (n == 0) std::copy(src, src + 3, out.begin()), n = 3;  // never let a part vanish
  out.resize(n);
  return out;
}

/// The distinct vertices of quad k (6 indices) of a card part, in index order of appearance.
size_t quad_vertices(const Mesh& full, const MeshPart& part, size_t k, uint32_t (&verts)[4]) {
  const uint32_t* q = full.indices.data() + part.first_index + 6 * k;
  size_t nv = 0;
  for (int i = 0; i < 6; ++i)
    if (std::find(verts, verts + nv, q[i]) == verts + nv && nv < 4) verts[nv++] = q[i];
  return nv;
}

/// Cards of a card part: runs of consecutive quads sharing vertices (a bent strip is one card),
/// as [first quad, end quad) ranges.
std::vector<std::pair<size_t, size_t>> card_runs(const Mesh& full, const MeshPart& part) {
  std::vector<std::pair<size_t, size_t>> runs;
  uint32_t prev[4] = {}, cur[4] = {};
  size_t prev_n = 0;
  for (size_t k = 0; k < part.index_count / 6; ++k) {
    const size_t n = quad_vertices(full, part, k, cur);
    const bool joined = std::any_of(cur, cur + n, [&](uint32_t v) { return std::find(prev, prev + prev_n, v) != prev + prev_n; });
    if (joined) runs.back().second = k + 1;
    else runs.emplace_back(k, k + 1);
    std::copy(cur, cur + n, prev);
    prev_n = n;
  }
  return runs;
}

/// Keeps about `ratio` of a card part's cards (evenly spread) and scales each kept card by
/// sqrt(1/ratio) (at most 2x) so the silhouette keeps its coverage: a single quad about its
/// centre, a strip about the middle of its base edge (its first two vertices).
std::vector<uint32_t> thin_cards(const Mesh& full, const MeshPart& part, float ratio, std::vector<Vec3f>& positions) {
  const auto runs = card_runs(full, part);
  const size_t cards = runs.size();
  const size_t keep = std::clamp<size_t>(size_t(std::lround(float(cards) * ratio)), 1, cards);
  const float scale = std::min(2.0f, std::sqrt(float(cards) / float(keep)));
  std::vector<uint32_t> out;
  for (size_t k = 0; k < cards; ++k) {
    if ((k + 1) * keep / cards == k * keep / cards) continue;
    const uint32_t* q = full.indices.data() + part.first_index + 6 * runs[k].first;
    const size_t count = 6 * (runs[k].second - runs[k].first);
    std::vector<uint32_t> verts(q, q + count);
    std::sort(verts.begin(), verts.end());
    verts.erase(std::unique(verts.begin(), verts.end()), verts.end());
    Vec3f c = Vec3f::Zero();
    if (verts.size() <= 4) {
      for (uint32_t v : verts) c += full.positions[v] / float(verts.size());
    } else {
      c = 0.5f * (full.positions[verts[0]] + full.positions[verts[1]]);
    }
    for (uint32_t v : verts) positions[v] = c + scale * (full.positions[v] - c);
    out.insert(out.end(), q, q + count);
  }
  return out;
}

}  // namespace

Mesh reduce_mesh(const Mesh& full, float ratio) {
  std::vector<Vec3f> positions = full.positions;
  std::vector<std::vector<uint32_t>> part_indices;
  for (const MeshPart& part : full.parts)
    part_indices.push_back(part.mask && part.index_count % 6 == 0 ? thin_cards(full, part, ratio, positions) : simplify_part(full, part, ratio));
  return compact_mesh(full, positions, part_indices);
}

std::vector<Mesh> build_lods(const Mesh& full, std::span<const float> ratios) {
  std::vector<Mesh> lods = {full};
  for (float ratio : ratios) {
    bool reduced = false;
    for (int attempt = 0; attempt < 5 && !reduced; ++attempt, ratio *= 0.5f) {
      Mesh m = reduce_mesh(full, ratio);
      if (m.triangle_count() < lods.back().triangle_count()) {
        lods.push_back(std::move(m));
        reduced = true;
      }
    }
    if (!reduced) break;
  }
  return lods;
}

}  // namespace silva::assets
