#pragma once
/// @file Overlays painted into a mesh part (core/mesh.hpp PartOverlay, the trail in the terrain):
/// the part's uv.x is a signed distance in metres to the overlay's edge (negative inside); a
/// ragged noise moves the edge, and one weight decides both the look and the label. The resolve
/// gives a pixel the overlay's role where overlay_weight >= 0.5 and the overlay's material where
/// the edge coordinate is below kOverlayMargin; that material blends by the same weight, so the
/// label edge is the 50 % line of the visual blend.
#include "core/types.hpp"

namespace silva {

/// How far the ragged edge wanders either way from uv.x = 0 (metres).
inline constexpr float kOverlayRagged = 0.12f;
/// Half width of the soft blend across the edge line (metres).
inline constexpr float kOverlaySoftness = 0.04f;
/// Edge coordinate below which the overlay's material shades a pixel: the blend and a worn margin
/// outside the edge (metres; must stay below the largest uv.x the part carries, 1 m for the trail).
inline constexpr float kOverlayMargin = 0.6f;

/// Edge coordinate of a surface point: uv.x moved by the ragged edge noise at its world position
/// (metres, negative inside the overlay).
float overlay_edge(float uv_x, const Vec3f& position);

/// Overlay weight of an edge coordinate: 1 inside, 0 outside, exactly 0.5 on the edge line (a
/// smoothstep over +-kOverlaySoftness).
float overlay_weight(float edge);

}  // namespace silva
