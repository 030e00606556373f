#include "assets/lod.hpp"

#include <algorithm>
#include <cmath>

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

/// Keeps about `ratio` of a card part's quads (6 indices each, evenly spread) and scales each
/// kept card about its centre by sqrt(1/ratio) (at most 2x) so the silhouette keeps its coverage.
std::vector<uint32_t> thin_cards(const Mesh& full, const MeshPart& part, float ratio, std::vector<Vec3f>& positions) {
  const size_t cards = part.index_count / 6;
  const size_t keep = std::clamp<size_t>(size_t(std::lround(float(cards) * ratio)), 1, cards);
  const float scale = std::min(2.0f, std::sqrt(float(cards) / float(keep)));
  std::vector<uint32_t> out;
  for (size_t k = 0; k < cards; ++k) {
    if ((k + 1) * keep / cards == k * keep / cards) continue;
    const uint32_t* q = full.indices.data() + part.first_index + 6 * k;
    uint32_t verts[4];
    size_t nv = 0;
    for (int i = 0; i < 6; ++i)
      if (std::find(verts, verts + nv, q[i]) == verts + nv && nv < 4) verts[nv++] = q[i];
    Vec3f c = Vec3f::Zero();
    for (size_t i = 0; i < nv; ++i) c += full.positions[verts[i]];
    c /= float(nv);
    for (size_t i = 0; i < nv; ++i) positions[verts[i]] = c + scale * (full.positions[verts[i]] - c);
    out.insert(out.end(), q, q + 6);
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
