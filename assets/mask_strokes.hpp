#pragma once
/// @file Drawing binary alpha masks of any size from strokes (stems, blades, leaves) in
/// aspect-correct mask units: x in [0, 1] across the width, y in [0, height / width] down.
#include <memory>
#include <vector>

#include "core/mesh.hpp"

namespace silva::assets {

/// A stroke from a to b (mask units) whose half-width goes from w0 to w1; a pointed stroke has
/// half-width w0 sin(pi t)^0.7 (a leaf), a round one w0 sin(pi t)^0.35 (a broad leaf).
struct Stroke {
  Vec2f a, b;             ///< End points.
  float w0, w1;           ///< Half-widths at a and b (pointed/round: w0 is the widest).
  enum class Shape : uint8_t { Tapered, Pointed, Round } shape = Shape::Tapered;  ///< Width profile.
  uint8_t alpha = 255;    ///< Alpha of the texels it covers, >= 128 (where strokes overlap, the first one's).
};

/// True when point p lies inside the stroke.
bool stroke_covers(const Stroke& s, const Vec2f& p);

/// A width x height mask, opaque where any stroke covers the texel centre (with the alpha of the
/// first stroke that does), 0 elsewhere.
std::shared_ptr<AlphaMask> rasterise_strokes(const std::vector<Stroke>& strokes, int width, int height);

/// A point at angle `deg` (0 = up the mask, positive = right) and distance `len` from `from`.
Vec2f stroke_towards(const Vec2f& from, float deg, float len);

/// A leaf of length `len` and half-width `half` from `base` at angle `deg`, with `teeth` small
/// pointed lobes per side (0: smooth edge).
void add_leaf_strokes(std::vector<Stroke>& s, const Vec2f& base, float deg, float len, float half, int teeth);

}  // namespace silva::assets
