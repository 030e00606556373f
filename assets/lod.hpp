#pragma once
/// @file Levels of detail: solid parts are simplified with meshoptimizer, alpha-tested card parts
/// (which simplification cannot reduce) are thinned, the kept cards enlarged to keep coverage.
#include <span>
#include <vector>

#include "core/mesh.hpp"

namespace silva::assets {

/// Default triangle ratios of LODs 1, 2, 3 relative to the full-detail mesh.
inline constexpr float kLodRatios[] = {0.5f, 0.25f, 0.1f};

/// Projected-size thresholds (fraction of image height) for LODs 1..3, descending
/// (render::MeshLods::lod_screen_sizes).
inline constexpr float kLodScreenSizes[] = {0.25f, 0.1f, 0.04f};

/// One reduced mesh: every part reduced to about `ratio` of its triangles (at least one
/// triangle or card each). Parts keep their order, roles, materials and masks.
Mesh reduce_mesh(const Mesh& full, float ratio);

/// lods[0] = full, then one level per ratio; a level that does not have strictly fewer
/// triangles than the previous one is retried at half the ratio (up to 4 times), else the
/// chain stops there.
std::vector<Mesh> build_lods(const Mesh& full, std::span<const float> ratios = kLodRatios);

}  // namespace silva::assets
