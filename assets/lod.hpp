#pragma once
/// @file Levels of detail: solid parts are simplified with meshoptimizer within an error that stays
/// below a pixel where the level is drawn; alpha-tested card parts are kept whole in the camera's
/// levels, because thinning cards changes which pixels they cover and so the labels (LOD changes
/// triangles, never classes). Only the shadow caster thins them (shadows are RGB only).
#include <span>
#include <vector>

#include "core/mesh.hpp"

namespace silva::assets {

/// Default triangle ratios of LODs 1, 2, 3 relative to the full-detail mesh.
inline constexpr float kLodRatios[] = {0.5f, 0.25f, 0.1f};

/// Share of the cards the shadow caster keeps (AssetGeometry::shadow_caster).
inline constexpr float kShadowCardRatio = 0.3f;

/// Projected-size thresholds (fraction of image height) for LODs 1..3, descending
/// (render::MeshLods::lod_screen_sizes).
inline constexpr float kLodScreenSizes[] = {0.25f, 0.1f, 0.04f};

/// Largest simplification error of a level, in pixels of a kLodReferenceHeight-line image when
/// the asset is drawn at the level's threshold size (and less the farther it is).
inline constexpr float kLodMaxErrorPixels = 1.0f;
/// Image height (pixels) the error bound refers to.
inline constexpr float kLodReferenceHeight = 1080.0f;

/// Largest simplification error, relative to the mesh's extent, of a level drawn below `screen_size`.
float lod_error_bound(float screen_size);

/// One reduced mesh: every solid part simplified towards `ratio` of its triangles (at least one
/// triangle each) with an error of at most `max_error` relative to the mesh's extent; card parts
/// (alpha-masked quads) unchanged. Parts keep their order, roles, materials and masks.
Mesh reduce_mesh(const Mesh& full, float ratio, float max_error);

/// Levels of detail with the screen-size thresholds they are drawn below.
struct LodChain {
  std::vector<Mesh> lods;            ///< lods[0] = full detail.
  std::vector<float> screen_sizes;   ///< Threshold of lods[k + 1], descending.
};

/// lods[0] = full, then for threshold k (at most 3) a level at ratio kLodRatios[k] within
/// lod_error_bound(screen_sizes[k]); a level that does not have strictly fewer triangles than the
/// previous one is retried at half the ratio (up to 4 times), else that threshold is left out
/// (a later, coarser threshold allows a larger error and may still reduce).
LodChain build_lods(const Mesh& full, std::span<const float> screen_sizes = kLodScreenSizes);

}  // namespace silva::assets
