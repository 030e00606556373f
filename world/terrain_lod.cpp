#include "world/terrain_lod.hpp"

#include <algorithm>

#include <meshoptimizer.h>

#include "world/trail_path.hpp"

namespace silva::world {

Mesh build_terrain_lod(const Mesh& full) {
  if (full.indices.empty() || full.parts.size() != 1) return {};
  // The trail's band stays as it is; the rest is simplified, its edge along the band locked as border.
  std::vector<uint32_t> band, rest;
  const bool overlay = full.parts[0].overlay.has_value();
  for (size_t k = 0; k < full.indices.size(); k += 3) {
    const uint32_t* t = &full.indices[k];
    const bool near = overlay && std::min({full.uvs[t[0]].x(), full.uvs[t[1]].x(), full.uvs[t[2]].x()}) <
                                     float(kTrailShoulder);
    (near ? band : rest).insert((near ? band : rest).end(), t, t + 3);
  }
  if (rest.empty()) return {};
  const float* positions = full.positions[0].data();
  const float scale = meshopt_simplifyScale(positions, full.positions.size(), sizeof(Vec3f));
  std::vector<uint32_t> indices(rest.size());
  // Target one triangle: the error bound and the locked border decide where it stops.
  indices.resize(meshopt_simplify(indices.data(), rest.data(), rest.size(), positions, full.positions.size(),
                                  sizeof(Vec3f), 3, kTerrainLodError / scale, meshopt_SimplifyLockBorder, nullptr));
  indices.insert(indices.end(), band.begin(), band.end());
  if (indices.empty() || indices.size() >= full.indices.size()) return {};
  return compact_mesh(full, full.positions, {indices});
}

}  // namespace silva::world
