#pragma once
/// @file How a visible surface pixel is lit: sun (GGX highlight, back-lit foliage), the sky's
/// spherical-harmonics ambient light, the mirrored sky and height fog, from the pixel's material
/// inputs. One pixel at a time (light_surface), or many at once on SIMD lanes (light_rough_surfaces).
#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/types.hpp"
#include "render/lighting.hpp"
#include "render/sky.hpp"
#include "render/sky_fog.hpp"

namespace silva::render {

/// Roughness below which the mirrored sky is looked up along the reflection rather than taken from
/// the smooth ambient fit (water films of the wet look).
inline constexpr float kSharpReflection = 0.3f;

/// Colour of the light a back-lit leaf lets through, per unit of its albedo: chlorophyll passes
/// yellow-green and absorbs blue.
inline const Vec3f kTransmissionTint(1.3f, 1.15f, 0.55f);

/// Light under a closed canopy per unit of the open ground's irradiance (sun and sky): what the leaves
/// scatter and let through (3 % of the luminance, as measured under broadleaf and spruce canopies), green
/// but not saturated: the sky seen through the small gaps of a closed crown adds its blue, and a grey bark
/// in this light reads grey-green (sRGB green / red about 1.15), not lime.
inline const Vec3f kCanopyScatter(0.024f, 0.033f, 0.018f);

/// The sky and ground light a rough surface mirrors, by the mirrored direction's z only: the
/// ambient fit's irradiance / π straight up, level and straight down, blended linearly in z and
/// times forest_sky_view (per frame; a few multiplies per pixel instead of the full fit).
struct MirroredSky {
  Vec3f up, level, down;  ///< Radiance mirrored from z = 1, 0, -1 (kcd/m²).

  /// Samples `sky`'s ambient fit.
  explicit MirroredSky(const Sky& sky);

  /// The radiance mirrored along unit direction `dir`.
  Vec3f along(const Vec3f& dir) const;
};

/// What lights every surface pixel of one frame.
struct SurfaceLighting {
  const Sky& sky;              ///< Sun, ambient fit and sky of the weather-adjusted preset.
  const HeightFog& fog;        ///< The camera's height fog.
  MirroredSky mirror;          ///< The sky rough surfaces mirror.
  float ao_strength;           ///< How much screen-space AO darkens the ambient light (LightingPreset).
  float foliage_translucency;  ///< How much sun back-lit foliage lets through (LightingPreset).
  Vec3f canopy_light;          ///< Irradiance the canopy scatters down in place of the sky light it takes.

  /// The lighting of `sky` and `fog` with the occlusion and translucency strengths of `preset`.
  SurfaceLighting(const Sky& sky, const HeightFog& fog, const LightingPreset& preset);
};

/// The material inputs of one visible surface pixel.
struct SurfaceSample {
  Vec3f albedo;           ///< Albedo after the weather's look.
  Vec3f normal;           ///< Unit shading normal (the material's relief included).
  Vec3f card_normal;      ///< Unit geometric normal, turned to face the camera (back-light test).
  Vec3f view_dir;         ///< Unit direction from the camera through the pixel.
  float roughness = 1;    ///< Perceptual GGX roughness (after the weather's look).
  float f0 = 0.04f;       ///< Specular reflectance at normal incidence.
  float translucency = 0; ///< Fraction of back light the material lets through.
  float ao = 1;           ///< Screen-space ambient visibility in [0, 1].
  float sun_visible = 1;  ///< Shadow-map visibility of the sun in [0, 1].
  float fog = 0;          ///< Height-fog amount along the view (HeightFog::amounts).
  float canopy = 0;       ///< Share of the sky light the canopy above takes (canopy_share_row).
};

/// Linear radiance (kcd/m²) leaving a surface pixel towards the camera, fog included: the albedo x
/// (sun x n·l + (ambient SH irradiance x (1 - canopy) + canopy light x canopy) x occlusion) / π, a GGX highlight of the sun, the sky mirrored
/// by the surface's Fresnel weight x (1 - canopy) (looked up along the reflection below kSharpReflection), and the
/// sun shining through back-lit thin foliage; then the height fog, its light x (1 - kFogCanopyShade x canopy).
Vec3f light_surface(const SurfaceLighting& lighting, const SurfaceSample& s);

/// Surface samples stored field by field (structure of arrays) for light_rough_surfaces; each
/// field's array is padded to whole SIMD vectors.
class SurfaceBatch {
 public:
  /// The stored fields, in storage order.
  enum Field : size_t {
    kAlbedoR, kAlbedoG, kAlbedoB, kNormalX, kNormalY, kNormalZ, kCardX, kCardY, kCardZ,
    kViewX, kViewY, kViewZ, kRoughness, kF0, kTranslucency, kAo, kSunVisible, kFog, kCanopy, kFieldCount
  };
  static_assert(kFieldCount == 19, "push's unroll pragma names the field count");
  /// Samples per padding unit: the float lanes of the widest SIMD vector (AVX-512).
  static constexpr size_t kPadding = 16;
  /// Empties the batch and makes room for up to `capacity` samples (memory is kept across calls).
  void start(size_t capacity);
  /// Appends one sample (at most the capacity given to start()).
  void push(const SurfaceSample& s) {
    const float values[kFieldCount] = {s.albedo.x(),      s.albedo.y(),      s.albedo.z(),      s.normal.x(),
                                       s.normal.y(),      s.normal.z(),      s.card_normal.x(), s.card_normal.y(),
                                       s.card_normal.z(), s.view_dir.x(),    s.view_dir.y(),    s.view_dir.z(),
                                       s.roughness,       s.f0,              s.translucency,    s.ao,
                                       s.sun_visible,     s.fog,             s.canopy};
#pragma GCC unroll 19  // kFieldCount: one store per field, no loop (this runs for most pixels of a frame)
    for (size_t f = 0; f < kFieldCount; ++f) data_[f][size_] = values[f];
    ++size_;
  }
  /// Number of samples.
  size_t size() const { return size_; }
  /// The values of field f; readable up to padded_size().
  const float* field(Field f) const { return fields_[f].data(); }
  /// size() rounded up to whole vectors of the widest SIMD target; the padding holds zeros.
  size_t padded_size() const;
  /// Zeroes the padding of every field (call after the last push, before reading).
  void pad();

 private:
  std::array<std::vector<float>, kFieldCount> fields_;
  std::array<float*, kFieldCount> data_{};  ///< fields_[f].data(), as of start().
  size_t size_ = 0;
};

/// light_surface of every sample of `batch`, whose roughness must be at least kSharpReflection,
/// on SIMD lanes with the same operations in the same order (bit for bit, on every Highway target).
/// Writes batch.padded_size() values to `out` (the padding's values are meaningless).
void light_rough_surfaces(const SurfaceLighting& lighting, const SurfaceBatch& batch, Vec3f* out);

/// The Highway target light_rough_surfaces dispatches to now.
int64_t surface_light_simd_target();

}  // namespace silva::render
