#pragma once
/// @file Procedural, seeded surface colours for every core/material.hpp Material.
#include <array>
#include <cstddef>
#include <cstdint>

#include "core/material.hpp"
#include "core/season.hpp"
#include "core/trail_surface.hpp"
#include "core/types.hpp"
#include "render/noise_salts.hpp"

namespace silva::render {

/// What lies on a world's whole forest floor: the season's fresh leaves and the kind of litter.
struct FloorLook {
  float fallen_leaves = 0.0f;   ///< The season's fresh leaf litter (fallen_leaf_cover).
  /// Share of needles in the litter everywhere, 0 … 1 (a forest type of one kind of tree); negative:
  /// stands of needle and of leaf litter from noise (a mixed forest).
  float needle_share = -1.0f;
  float spruce_cones = 0.0f;  ///< Share of the needle litter that falls from spruce and lays its cones, 0 … 1.
};

/// What a material function needs to know about one visible surface point.
struct SurfacePoint {
  Vec3f position;      ///< World position (metres, Z up).
  Vec3f normal;        ///< Unit world normal facing the camera.
  Vec2f uv;            ///< Mesh texture coordinates (trail: render/trail_material.hpp).
  Material material;   ///< Which procedural material.
  uint32_t variation;  ///< Per-instance variation seed.
  FloorLook floor{};           ///< What lies on the forest floor (Ground and Trail points).
  float leaf_shade = 1.0f;     ///< The brightness of the leaf under the point (leaf_brightness).
  TrailSurface trail = TrailSurface::PackedEarth;  ///< The trail's surface family (Material::Trail points).
  float footprint = 0.0f;  ///< Metres one pixel covers there (Trail points' floor detail fades with it; 0: full detail).
};

/// Brightness of one leaf of a foliage mask against its tree's from the alpha of its texel:
/// 0.75 … 1.25 for alpha 128 … 254 (a leaf's own value), 1 for anything else (255: no per-leaf value).
/// Inline: the shading asks it of most pixels of every frame.
inline float leaf_brightness(uint8_t alpha) {
  return alpha >= 128 && alpha < 255 ? 0.75f + 0.5f * float(alpha - 128) / 126.0f : 1.0f;
}

/// Linear-RGB diffuse albedo of a surface point: a pure function of the point (no state).
Vec3f material_albedo(const SurfacePoint& s);

/// Frequency (1/m) and salt of the value noise that mottles foliage.
inline constexpr float kFoliageMottleScale = 6.0f;
inline constexpr uint32_t kFoliageMottleSalt = kFoliage + 1;  ///< The mottle's salt.

/// True when material m's albedo is plain foliage: `base` (set) tinted per instance and mottled,
/// foliage_albedo(base, variation, value_noise3(kFoliageMottleScale p, kFoliageMottleSalt), leaf_shade).
bool plain_foliage_base(Material m, Vec3f& base);

/// Albedo of plain foliage of colour `base` on the instance of `variation` where its mottle noise is
/// `mottle`, on a leaf of brightness `leaf_shade`.
Vec3f foliage_albedo(const Vec3f& base, uint32_t variation, float mottle, float leaf_shade);

/// Plain-foliage albedo of `count` points (positions, instance variations, base colours, leaf shades) into
/// out[i]: material_albedo's value for a point of a plain-foliage material of that base, one point
/// per SIMD lane with the scalar operations in their order (the same bits on every Highway target).
void foliage_albedo_row(const Vec3f* points, const uint32_t* variations, const Vec3f* bases, const float* leaf_shades,
                        size_t count, Vec3f* out);

/// Forest floor (Material::Ground): leaf and needle litter with grassy and mossy patches and a
/// little bare soil, blended by noise and slope; leaf-sized detail fades out where one pixel
/// covers more than a few centimetres. Linear-RGB colours of the layers:
inline constexpr float kGroundLeafLitter[3] = {0.095f, 0.066f, 0.042f};   ///< Brown leaf litter.
inline constexpr float kGroundDryLeaves[3] = {0.16f, 0.115f, 0.07f};      ///< Dry, lit leaves on top.
inline constexpr float kGroundNeedleLitter[3] = {0.095f, 0.062f, 0.04f};   ///< Spruce/pine needle litter.
inline constexpr float kGroundGrass[3] = {0.075f, 0.092f, 0.032f};          ///< Short grass cover.
inline constexpr float kGroundMoss[3] = {0.06f, 0.085f, 0.022f};          ///< Moss carpets.
inline constexpr float kGroundSoil[3] = {0.075f, 0.055f, 0.038f};         ///< Bare soil.
inline constexpr float kGroundFallenOrange[3] = {0.15f, 0.065f, 0.028f};   ///< Freshly fallen leaves, russet brown.
inline constexpr float kGroundFallenYellow[3] = {0.25f, 0.14f, 0.03f};     ///< Freshly fallen leaves, orange-yellow.
/// The fBm layers (scale in 1/m, octaves; salts in render/noise_salts.hpp): stand 0.02 x2 (leaf
/// vs needle litter), grass 0.06 x2, moss 0.15 x3, soil 0.5 x3, fine grain 4 x2; leaf detail value
/// noise at 9 and 23.

/// Ground albedo of `count` points (world positions, normals, and the metres one pixel covers
/// there) into out[i], one point per SIMD lane; `soil` (may be null) receives each point's
/// bare-soil weight in [0, 1]. With smoothstep(e0, e1, x) and fbm2(x, y, octaves, salt):
///   flat = smoothstep(0.6, 0.9, n.z); fine_detail = 1 - smoothstep(0.01, 0.05, footprint)
///   sprites = litter_fade(footprint) (render/floor_litter.hpp); blotches = fine_detail (1 - sprites)
///   needles = smoothstep(0.42, 0.58, fbm2(0.02 p, 2, stand)), or floor.needle_share where that is set
///   leaf = value_noise2(9 p, leaf); c = mix(leaf_litter, needle_litter, needles)
///   c = mix(c, dry_leaves, smoothstep(0.6, 0.8, leaf) (1 - needles) blotches)
///   c = mix(c, grass, 0.8 smoothstep(0.62, 0.78, fbm2(0.06 p, 2, grass)) flat)
///   c = mix(c, moss colour (kMossDetailNear), 0.85 smoothstep(0.6, 0.72, fbm2(0.15 p, 3, moss)) flat)
///   with floor.fallen_leaves f > 0 (autumn): fallen = f smoothstep(0.25, 0.55, fbm2(0.4 p, 2, fallen)) (1 - 0.7 needles),
///   hue = mix(fbm2(1.5 p, 2, fallen + 8), smoothstep(0.3, 0.7, leaf), fine_detail),
///   c = mix(c, mix(fallen_orange, fallen_yellow, hue), fallen): fresh leaves over grass and moss
///   soil = max(1 - flat, smoothstep(0.7, 0.84, fbm2(0.5 p, 3, soil))); c = mix(c, soil_colour, soil)
///   out = c (1 + (0.6 fbm2(4 p, 2, fine) - 0.3) (1 - smoothstep(0.1, 0.4, footprint)))
///         (1 + (0.8 value_noise2(23 p, leaf + 1) - 0.4) fine_detail)
///   then litter_sprites over out with LitterMix{grass / 0.8, needles, fallen} and weight
///   sprites (1 - 0.7 moss) (1 - soil): single leaves, needles, twigs and grass blades near the camera
///   then, where floor.spruce_cones > 0, spruce_cones with density needles spruce_cones and weight
///   spruce_cone_fade(footprint) (1 - 0.7 moss) (1 - soil)
/// with shading_noise.hpp's noise evaluated lane by lane in its operation order (every target agrees).
/// `slope` (may be null) receives the gradient (d/dx, d/dy, metres per metre) of the floor's relief
///   height = (kGroundLeafRelief leaf (1 - sprites) + kGroundSpeckleRelief speckle) fine_detail
///            + moss cushions (kMossCushionRelief), then each sprite's tilt where it lies
/// (analytic derivatives of the value noises; the fades taken as constant).
void ground_albedo_row(const Vec3f* positions, const Vec3f* normals, const float* footprints, size_t count,
                       Vec3f* out, float* soil = nullptr, Vec2f* slope = nullptr, const FloorLook& floor = {});

/// How much fresh leaf litter a season lays on the forest floor (FloorLook::fallen_leaves):
/// autumn 0.8, else 0 (winter's litter lies under the snow or has browned into the old litter).
float fallen_leaf_cover(Season season);

/// Moss texture near the camera: cushions (value noise at 40/m) and their tips (110/m) brighten and
/// darken kGroundMoss by up to 45 % and bump the relief, faded out from kMossDetailNear to
/// kMossDetailFar metres per pixel:
///   shown = (1 - smoothstep(near, far, footprint)) moss
///   moss colour = kGroundMoss (1 + ((0.7 cushion + 0.3 tips) - 0.5) 0.9 shown)
inline constexpr float kMossDetailNear = 0.004f;
inline constexpr float kMossDetailFar = 0.02f;  ///< See kMossDetailNear.
inline constexpr float kMossCushionRelief = 0.006f;  ///< Relief height per unit of the cushion noise (metres).
inline constexpr float kMossTipRelief = 0.002f;      ///< Relief height per unit of the tip noise (metres).

/// Relief height of the forest floor per unit of its leaf-sized noise (metres): leaves lying on each other.
inline constexpr float kGroundLeafRelief = 0.012f;
/// Relief height per unit of the floor's speckle noise (metres): twigs, needles, grit.
inline constexpr float kGroundSpeckleRelief = 0.004f;

/// The Highway target ground_albedo_row dispatches to now.
int64_t ground_simd_target();

/// How a material reflects and transmits light beyond its diffuse albedo.
struct MaterialResponse {
  float roughness;     ///< Perceptual GGX roughness in (0, 1] (the GGX alpha is its square).
  float f0;            ///< Specular reflectance at normal incidence (0.04: most dielectrics).
  float translucency;  ///< Fraction of the light a back-lit thin card lets through (0: opaque).
};

/// Every material's response, in core/material.hpp order (waxy leaves are smoother than bark,
/// bark than litter; thin foliage lets light through).
inline constexpr std::array<MaterialResponse, size_t(Material::Count)> kMaterialResponses = {{
    {0.85f, 0.04f, 0.0f},  // Ground
    {0.9f, 0.04f, 0.0f},  // Trail
    {0.85f, 0.04f, 0.0f},  // BarkConifer
    {0.85f, 0.04f, 0.0f},  // BarkBroadleaf
    {0.85f, 0.04f, 0.0f},  // BarkDead
    {0.5f, 0.04f, 0.6f},  // Needles
    {0.55f, 0.04f, 1.0f},  // Leaves
    {0.55f, 0.04f, 0.8f},  // Grass
    {0.5f, 0.04f, 1.0f},  // Fern
    {0.55f, 0.04f, 1.0f},  // ShrubLeaves
    {0.7f, 0.045f, 0.0f},  // Rock
    {0.75f, 0.04f, 0.0f},  // Wood
    {0.85f, 0.04f, 0.0f},  // LogBark
    {0.8f, 0.04f, 0.0f},  // BrokenWood
    {0.95f, 0.03f, 0.0f},  // Moss
    {0.8f, 0.04f, 0.0f},  // LeafLitter
    {0.85f, 0.04f, 0.0f},  // BarkSpruce
    {0.85f, 0.04f, 0.0f},  // BarkPine
    {0.85f, 0.04f, 0.0f},  // BarkLarch
    {0.6f, 0.04f, 0.0f},  // BarkBeech
    {0.6f, 0.04f, 0.0f},  // BarkBirch
    {0.85f, 0.04f, 0.0f},  // BarkOak
    {0.5f, 0.04f, 0.6f},  // NeedlesSpruce
    {0.5f, 0.04f, 0.6f},  // NeedlesPine
    {0.55f, 0.04f, 0.8f},  // NeedlesLarch
    {0.55f, 0.04f, 1.0f},  // LeavesBeech
    {0.55f, 0.04f, 1.0f},  // LeavesBirch
    {0.55f, 0.04f, 1.0f},  // LeavesOak
    {0.55f, 0.04f, 0.9f},  // AutumnLeaves
    {0.55f, 0.04f, 0.8f},  // AutumnNeedles
    {0.8f, 0.04f, 0.0f},  // BareTwigs
    {0.65f, 0.04f, 0.6f},  // AutumnGrass
    {0.75f, 0.04f, 0.4f},  // WinterGrass
    {0.75f, 0.04f, 0.3f},  // DeadBracken
    {0.9f, 0.04f, 0.0f},  // Soil
    {0.5f, 0.04f, 1.0f},  // Herb
    {0.55f, 0.04f, 1.0f},  // SpringLeaves
    {0.6f, 0.04f, 0.7f},  // Petals
    {0.8f, 0.04f, 0.2f},  // MattedBracken
}};

/// The response of material `m`.
inline MaterialResponse material_response(Material m) { return kMaterialResponses[size_t(m)]; }

/// The shading normal of a surface point with the relief of its material: bark, rock and wood are
/// bumped by the gradient of the same value noise that grains their albedo, faded out where one
/// pixel (`footprint` metres) covers more than about a third of the noise's period, plus
/// `relief_slope` (a height gradient the caller has: a species bark's fissures, SpeciesBark::slope).
/// Other materials return s.normal. Labels and the `normals` output keep the geometric normal.
Vec3f material_shading_normal(const SurfacePoint& s, float footprint, const Vec3f& relief_slope = Vec3f::Zero());

/// `n` tilted by a height field's gradient `slope` (metres per metre) and renormalised: the
/// gradient's part along n is dropped, the rest subtracted.
Vec3f bumped_normal(const Vec3f& n, const Vec3f& slope);

}  // namespace silva::render
