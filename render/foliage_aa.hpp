#pragma once
/// @file Coverage of minified alpha masks in RGB: a pixel sees one sample, so a leaf mask with several
/// texels across the pixel (needles of a spruce a few metres away, a far crown) comes out as a speckle of
/// leaf and background where a camera integrates their mix. This blends each such pixel with the pixels
/// around it on its own layer and behind it (and those with the leaves in front of them), by how minified
/// the mask is. RGB only: labels, depth and the G-buffer keep the exact per-pixel sample.
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

/// True when some pixel of `g` has a minified mask (minified_weight > 0): the frame needs blend_minified_masks.
bool has_minified_masks(const GBuffer& g);

/// Replaces `frame` (radiance of g's pixels) by its coverage blend: pixel p becomes the mean of its 3x3
/// neighbours q under the tent weights 4 / 2 / 1 (centre / side / corner), q != p taking part with its tent
/// weight times max(w(p) if q is a surface on p's layer or behind it, w(q) if q lies on p's layer or in
/// front of it), w = minified_weight, where "behind" and "in front" compare depths (no hit = infinitely far)
/// with kLayerTolerance: the sky through a gap never brightens the leaves, but the gap takes their colour.
/// Every pixel's weight is also divided by 1 + its luminance x `exposure` (the exposed luminance, 1 about
/// white), so the blend acts as if on the image's tones: a bright pixel softens the leaves around it instead
/// of lighting them up (one sample per pixel holds too few gaps for a linear mean). `scratch` is overwritten. Rows run in parallel; the result never depends on threads.
void blend_minified_masks(const GBuffer& g, float exposure, LinearFrame& frame, LinearFrame& scratch);

}  // namespace silva::render
