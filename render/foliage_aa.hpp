#pragma once
/// @file Coverage of minified alpha masks in RGB: a pixel sees one sample, so a leaf mask with several
/// texels across the pixel (needles of a spruce a few metres away, a far crown) comes out as a speckle of
/// leaf and background where a camera integrates their mix. This blends each such pixel with the pixels
/// around it on its own layer and behind it (and those with the leaves in front of them), by how minified
/// the mask is. RGB only: labels, depth and the G-buffer keep the exact per-pixel sample.
#include <array>
#include <cstdint>
#include <vector>

#include "render/gbuffer.hpp"
#include "render/linear_frame.hpp"

namespace silva::render {

/// Mask texels across a pixel (GBuffer::mask_texels) below which a masked pixel is left as it is.
inline constexpr float kMinifiedStart = 1.0f;
/// Mask texels across a pixel from which a masked pixel is blended fully.
inline constexpr float kMinifiedFull = 3.0f;
/// Relative depth within which two pixels count as one layer.
inline constexpr float kLayerTolerance = 0.02f;

/// Blending weight in [0, 1] of a pixel whose mask has `mask_texels` texels across it (0: not masked).
float minified_weight(float mask_texels);

/// True when some pixel of `g` has a minified mask (minified_weight > 0): the frame needs MaskBlendRows.
bool has_minified_masks(const GBuffer& g);

/// The coverage blend of a frame, one row at a time, for a renderer that shades rows in bands: pixel p becomes
/// the mean of its 3x3 neighbours q under the tent weights 4 / 2 / 1 (centre / side / corner), q != p taking
/// part with its tent weight times max(w(p) if q is a surface on p's layer or behind it, w(q) if q lies on p's
/// layer or in front of it), w = minified_weight, where "behind" and "in front" compare depths (no hit =
/// infinitely far) with kLayerTolerance: the sky through a gap never brightens the leaves, but the gap takes
/// their colour. Every pixel's weight is also divided by 1 + its luminance x `exposure` (the exposed luminance,
/// 1 about white), so the blend acts as if on the image's tones: a bright pixel softens the leaves around it
/// instead of lighting them up (one sample per pixel holds too few gaps for a linear mean). The frame is read,
/// never written, so rows may be blended in any order by any number of these (one per thread); the result of
/// a row never depends on which.
class MaskBlendRows {
 public:
  /// Blends rows of `frame` (radiance of g's pixels) at `exposure`; both must outlive this.
  MaskBlendRows(const GBuffer& g, float exposure, const LinearFrame& frame);

  /// Writes row v's blended radiance into out (g.width values). Rows v - 1 … v + 1 of the frame (those
  /// inside it) must hold their final radiance.
  void blend(int v, Vec3f* out);

 private:
  /// Blend inputs of one row: layer depth, minified weight, tone weight, and whether a minified mask lies
  /// within one pixel along the row.
  struct RowPlanes {
    int row = -1;  ///< Row these hold (-1: none).
    std::vector<float> layer, weight, tone;
    std::vector<uint8_t> near;
  };

  /// The planes of row v (v inside the frame), computed unless this holds them from a previous call.
  const RowPlanes& planes(int v);

  const GBuffer& g_;
  const LinearFrame& frame_;
  float exposure_;
  std::array<RowPlanes, 3> ring_;  ///< Planes of the last rows seen, row v in slot v % 3.
};

}  // namespace silva::render
