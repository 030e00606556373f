#pragma once
/// @file Options and work counters of one rasteriser pass.
#include <cstdint>

namespace silva::render {

/// What the rasteriser may skip or simplify.
struct RenderOptions {
  bool lod = true;            ///< false: always draw MeshLods::lods[0] (reference renders).
  bool backface_cull = true;  ///< false: draw back faces of single-sided parts too.
  int tile_size = 128;        ///< Screen tile side in pixels: a multiple of 8 in [8, 256].
  double min_radius = 0;      ///< Instances with a smaller bounding sphere (metres) are not drawn.
};

/// Work counts of one pass (sums over threads; the last three may vary with thread count
/// because early depth rejection depends on the order tiles see triangles).
struct RenderStats {
  uint64_t instances_submitted = 0;   ///< Instances in the scene.
  uint64_t instances_culled = 0;      ///< Instances rejected by their bounds (outside the view).
  uint64_t triangles_submitted = 0;   ///< Triangles of the chosen LODs of the instances drawn.
  uint64_t triangles_after_cull = 0;  ///< Triangles left after frustum and back-face culling.
  uint64_t triangles_clipped = 0;     ///< Triangles that crossed the near plane or guard band.
  uint64_t triangles_rasterised = 0;  ///< Screen triangles binned (after clipping and small-triangle rejection).
  uint64_t tile_bin_entries = 0;      ///< (triangle, tile) pairs binned.
  uint64_t fragments_covered = 0;     ///< Sample centres found inside a triangle (after block rejection).
  uint64_t pixels_shaded_or_written = 0;  ///< Visibility-buffer writes, overdraw included.
  uint64_t pixels_covered = 0;        ///< Pixels that saw a surface at the end.
};

}  // namespace silva::render
