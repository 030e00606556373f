#include "world/terrain_lod.hpp"

#include <meshoptimizer.h>

namespace silva::world {

Mesh build_terrain_lod(const Mesh& full) {
  if (full.indices.empty() || full.parts.size() != 1) return {};
  const float* positions = full.positions[0].data();
  const float scale = meshopt_simplifyScale(positions, full.positions.size(), sizeof(Vec3f));
  std::vector<uint32_t> indices(full.indices.size());
  // Target one triangle: the error bound and the locked border decide where it stops.
  indices.resize(meshopt_simplify(indices.data(), full.indices.data(), full.indices.size(), positions,
                                  full.positions.size(), sizeof(Vec3f), 3, kTerrainLodError / scale,
                                  meshopt_SimplifyLockBorder, nullptr));
  if (indices.empty() || indices.size() >= full.indices.size()) return {};
  return compact_mesh(full, full.positions, {indices});
}

}  // namespace silva::world
