#pragma once
/// @file Single leaves, needles, twigs and cones lying on the forest floor near the camera: procedural
/// sprites on a jittered grid, composited over the floor's colour and relief with antialiased edges
/// (each sprite's coverage of the pixel's box footprint) and a thin contact shadow around each.
/// Faded out where one pixel covers more than a couple of centimetres, where ground_albedo_row's
/// leaf-sized blotches take over. The scalar definition; render/floor_litter-inl.h evaluates it on
/// SIMD lanes with the same operations in the same order.
#include <cstdint>

#include "core/types.hpp"
#include "render/noise_salts.hpp"

namespace silva::render {

/// Grid cell of the sprites (metres): at most one sprite per cell and layer, its centre inside the
/// cell, so a point sees every sprite that can reach it among its own cell and the eight around it.
inline constexpr float kLitterCell = 0.06f;
/// Layers of sprites, each over the one before (about 60 % of a broadleaf floor covered).
inline constexpr int kLitterLayers = 2;
/// Share of cells that hold a sprite in each layer.
inline constexpr float kLitterDensity = 0.95f;
/// Share of sprites that are twigs (the rest grass blades, needles or leaves, by the floor's grass
/// cover and needle share).
inline constexpr float kLitterTwigShare = 0.05f;
/// Share of sprites that are cones under an all-conifer stand (in proportion to the needle share).
inline constexpr float kLitterConeShare = 0.02f;
/// Width (metres) of the contact shadow around each sprite, and how much it darkens the floor.
inline constexpr float kLitterShadowWidth = 0.004f;
/// How far beyond a sprite's half length and half width its shadow and a pixel's filter can reach it
/// (metres): the shadow's width and a margin far above rounding, so skipping the sprites beyond is exact.
inline constexpr float kLitterReach = kLitterShadowWidth + 1e-4f;
inline constexpr float kLitterShadow = 0.25f;  ///< Darkening at the sprite's edge.
/// How far a midrib darkens its leaf, and its half width (metres).
inline constexpr float kLitterRib = 0.3f;
inline constexpr float kLitterRibHalfWidth = 0.0005f;
/// Largest slope (metres per metre) a sprite lies at along its length: leaves rest on each other.
inline constexpr float kLitterTilt = 0.35f;
/// Slope of each half of a leaf away from its midrib: leaves curl, one half towards the light.
inline constexpr float kLitterCurl = 0.3f;
/// Footprints (metres per pixel) over which the sprites fade out: a leaf 5 … 2 pixels long.
inline constexpr float kLitterFadeNear = 0.012f;
inline constexpr float kLitterFadeFar = 0.03f;
/// The widest antialiasing filter (metres): a filtered sprite still stays inside its cell's neighbours.
inline constexpr float kLitterWidestFilter = 0.02f;
/// Leaf (half length = kLitterLeafHalf[0] + kLitterLeafHalf[1] size, half width kLitterLeafWidth[0] +
/// kLitterLeafWidth[1] w of the half length at the middle, narrowing to the tips), needle and twig
/// shapes (metres).
inline constexpr float kLitterLeafHalf[2] = {0.025f, 0.015f};
inline constexpr float kLitterLeafWidth[2] = {0.4f, 0.3f};        ///< Leaf half width / half length.
inline constexpr float kLitterNeedleHalf[2] = {0.008f, 0.017f};  ///< Needles 1.6 – 5 cm long.
inline constexpr float kLitterNeedleHalfWidth = 0.0006f;        ///< Needles 1.2 mm wide.
inline constexpr float kLitterTwigHalf[2] = {0.028f, 0.014f};    ///< Twigs 5.6 – 8.4 cm long.
inline constexpr float kLitterBladeHalf[2] = {0.015f, 0.025f};   ///< Grass blades 3 – 8 cm long, lying or bent over,
inline constexpr float kLitterBladeHalfWidth[2] = {0.0008f, 0.0008f};  ///< 1.6 – 3.2 mm wide, pointed.
inline constexpr float kLitterTwigHalfWidth[2] = {0.0012f, 0.0018f};  ///< Twigs 2.4 – 6 mm thick.
inline constexpr float kLitterConeHalf[2] = {0.02f, 0.015f};  ///< Cones 4 – 7 cm long (pine and larch; young spruce),
inline constexpr float kLitterConeWidth = 0.45f;             ///< their half width / half length at the middle.
/// Slope of a cone's flank at its outline (its round body lit on one side, as a curled leaf's halves).
inline constexpr float kLitterConeRound = 0.8f;
/// Spacing (metres) of the two sets of diagonal seams between a cone's scales, their half width, and
/// how much they darken it.
inline constexpr float kLitterConePitch = 0.007f;
inline constexpr float kLitterConeSeamHalfWidth = 0.0007f;
inline constexpr float kLitterConeSeam = 0.5f;
/// Linear-RGB colours, dark and light end of each kind (a sprite's hue mixes them).
inline constexpr float kLitterLeafDark[3] = {0.055f, 0.037f, 0.024f};
inline constexpr float kLitterLeafLight[3] = {0.165f, 0.113f, 0.066f};
inline constexpr float kLitterNeedleDark[3] = {0.07f, 0.04f, 0.022f};
inline constexpr float kLitterNeedleLight[3] = {0.17f, 0.1f, 0.05f};
inline constexpr float kLitterBladeDark[3] = {0.03f, 0.048f, 0.012f};
inline constexpr float kLitterBladeLight[3] = {0.11f, 0.13f, 0.04f};
inline constexpr float kLitterTwigDark[3] = {0.04f, 0.033f, 0.027f};
inline constexpr float kLitterTwigLight[3] = {0.12f, 0.1f, 0.085f};
inline constexpr float kLitterConeDark[3] = {0.05f, 0.03f, 0.018f};
inline constexpr float kLitterConeLight[3] = {0.19f, 0.11f, 0.055f};

/// Spruce cones (Picea abies: 10–16 cm long, 3–4 cm thick, hanging and fallen whole) lie on a grid of their
/// own, at most one per cell, its centre inside the cell, so a point sees every cone that can reach it among
/// its own cell and the eight around it (kSpruceConeCell exceeds a cone's reach with the widest filter).
inline constexpr float kSpruceConeCell = 0.25f;
/// Share of cells holding a cone where the litter is all spruce needles (about 5 cones per m²).
inline constexpr float kSpruceConeShare = 0.3f;
inline constexpr float kSpruceConeHalf[2] = {0.05f, 0.03f};  ///< Half length: cones 10 – 16 cm long,
inline constexpr float kSpruceConeWidth = 0.3f;              ///< their half width / half length at the middle,
inline constexpr float kSpruceConePitch = 0.011f;            ///< and the spacing of the seams between their scales.
/// Footprints (metres per pixel) over which the cones fade out: a cone 5 … 2.5 pixels long.
inline constexpr float kSpruceConeFadeNear = 0.026f;
inline constexpr float kSpruceConeFadeFar = 0.052f;
/// The widest antialiasing filter for cones (metres).
inline constexpr float kSpruceConeWidestFilter = 0.052f;
inline constexpr float kSpruceConeDark[3] = {0.055f, 0.03f, 0.016f};  ///< Weathered dark brown,
inline constexpr float kSpruceConeLight[3] = {0.2f, 0.095f, 0.04f};    ///< freshly fallen red-brown.
/// Width (metres) of the shadow around a cone, 3-4 cm thick where it lies, and how far its shadow and the
/// widest filter can reach past its outline (as kLitterReach).
inline constexpr float kSpruceConeShadowWidth = 0.012f;
inline constexpr float kSpruceConeReach = kSpruceConeShadowWidth + 1e-4f;

/// How much the sprites show where one pixel covers `footprint` metres: 1 up to kLitterFadeNear,
/// 0 from kLitterFadeFar.
float litter_fade(float footprint);

/// What the sprites at a floor point are made of.
struct LitterMix {
  float grass = 0.0f;    ///< The floor's grass cover: this share of the sprites are grass blades.
  float needles = 0.0f;  ///< The stand's needle share (0 broadleaf … 1 conifer) of the rest; cones follow it.
  float fresh = 0.0f;    ///< Share of the leaves that are freshly fallen (autumn colours).
};

/// Composites the litter sprites over the floor colour `c` and relief gradient `slope` (metres per
/// metre) at world point (x, y), seen with a pixel footprint of `footprint` metres; `weight` is how
/// much litter lies here (0 on moss and bare soil; litter_fade included). Sprites lie over each other
/// in the order (layer, cell y, cell x), so overlaps agree between neighbouring points.
void litter_sprites(float x, float y, float footprint, const LitterMix& litter, float weight, Vec3f& c, Vec2f& slope);

/// How much the spruce cones show where one pixel covers `footprint` metres: 1 up to kSpruceConeFadeNear,
/// 0 from kSpruceConeFadeFar.
float spruce_cone_fade(float footprint);

/// Composites the spruce cones over `c` and `slope` at world point (x, y) as litter_sprites does its sprites:
/// a cell holds a cone with probability kSpruceConeShare x `density` (the share of spruce needles in the
/// litter), laid with `weight` (0 on moss and bare soil; spruce_cone_fade included), in the order (cell y, cell x).
void spruce_cones(float x, float y, float footprint, float density, float weight, Vec3f& c, Vec2f& slope);

}  // namespace silva::render
