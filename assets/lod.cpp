#include "assets/lod.hpp"

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include <meshoptimizer.h>

namespace silva::assets {

namespace {

/// Simplifies one solid part's triangles (indices into `full`) towards `ratio` of them, within
/// `max_error` relative to the extent of full's positions.
std::vector<uint32_t> simplify_part(const Mesh& full, const MeshPart& part, float ratio, float max_error) {
  const uint32_t* src = full.indices.data() + part.first_index;
  const size_t triangles = part.index_count / 3;
  const size_t target = std::max<size_t>(3, size_t(std::lround(float(triangles) * ratio)) * 3);
  std::vector<uint32_t> out(part.index_count);
  const float* pos = full.positions[0].data();
  size_t n = meshopt_simplify(out.data(), src, part.index_count, pos, full.positions.size(), sizeof(Vec3f),
                              target, max_error, 0, nullptr);
  if (n > target + target / 4) {  // seams or borders held it back: sloppy clustering, if as accurate
    std::vector<uint32_t> sloppy(part.index_count);
    float error = 0;
    const size_t m = meshopt_simplifySloppy(sloppy.data(), src, part.index_count, pos, full.positions.size(),
                                            sizeof(Vec3f), target, max_error, &error);
    if (m >= 3 && m < n && error <= max_error) {
      out.swap(sloppy);
      n = m;
    }
  }
  if (n == 0) std::copy(src, src + 3, out.begin()), n = 3;  // never let a part vanish
  out.resize(n);
  return out;
}

}  // namespace

float lod_error_bound(float screen_size) { return kLodMaxErrorPixels / (kLodReferenceHeight * screen_size); }

Mesh reduce_mesh(const Mesh& full, float ratio, float max_error) {
  std::vector<std::vector<uint32_t>> part_indices;
  for (const MeshPart& part : full.parts) {
    const auto first = full.indices.begin() + part.first_index;
    part_indices.push_back(part.mask ? std::vector<uint32_t>(first, first + part.index_count)
                                     : simplify_part(full, part, ratio, max_error));
  }
  return compact_mesh(full, full.positions, part_indices);
}

LodChain build_lods(const Mesh& full, std::span<const float> screen_sizes) {
  LodChain chain;
  chain.lods = {full};
  const size_t levels = std::min(screen_sizes.size(), std::size(kLodRatios));
  for (size_t k = 0; k < levels; ++k) {
    const float max_error = lod_error_bound(screen_sizes[k]);
    float ratio = kLodRatios[k];
    for (int attempt = 0; attempt < 5; ++attempt, ratio *= 0.5f) {
      Mesh m = reduce_mesh(full, ratio, max_error);
      if (m.triangle_count() < chain.lods.back().triangle_count()) {
        chain.lods.push_back(std::move(m));
        chain.screen_sizes.push_back(screen_sizes[k]);
        break;
      }
    }
  }
  return chain;
}

}  // namespace silva::assets
