#pragma once
/// @file The RGB pass: G-buffer + camera + lighting preset (+ sun shadow map) -> 8-bit sRGB image.
#include <cstdint>
#include <optional>
#include <string_view>
#include <vector>

#include "core/camera.hpp"
#include "core/camera_model.hpp"
#include "core/trail_surface.hpp"
#include "render/canopy_map.hpp"
#include "render/gbuffer.hpp"
#include "render/linear_frame.hpp"
#include "render/lighting.hpp"
#include "render/materials.hpp"

namespace silva::render {

/// Everything shade_rgb reads. `shadow` may be null (no sun shadows).
/// Whole-frame buffers shading keeps from one call to the next (sized on use), so a run's frames reuse their memory.
struct ShadeScratch {
  LinearFrame frame;     ///< Shaded rows, when the coverage blend or the camera's optics need whole frames.
  LinearFrame finished;  ///< Blended rows, when both do.
  std::vector<float> ao; ///< Half-resolution ambient occlusion samples.
};

struct ShadeInputs {
  const GBuffer& gbuffer;         ///< The view's resolved surfaces (depth 0 = sky).
  const Camera& camera;           ///< The view's camera (same size as the G-buffer).
  const LightingPreset& preset;   ///< Sun, sky, fog, clouds, exposure.
  const ShadowMap* shadow;        ///< Sun shadow map, or nullptr.
  uint64_t seed;                  ///< World seed (sensor noise stream).
  std::string_view sequence;      ///< Sequence name (sensor noise key).
  uint64_t frame;                 ///< Frame number within the sequence (sensor noise key).
  CameraModel model;              ///< Sensor noise and optics applied to the RGB.
  bool auto_exposure = false;     ///< Expose by the frame's metered luminance (render/auto_exposure.hpp), not preset.ev100.
  float exposure_compensation_ev = 0.0f;  ///< EV added to the image's brightness (the EV100 used is lowered by it).
  Vec3f white_balance = Vec3f::Ones();    ///< Per-channel gains of the camera's white balance (render/frame_lighting.hpp).
  FloorLook floor{};                      ///< What lies on the forest floor (season's leaves, kind of litter).
  /// Expose with this EV100 (compensation included), neither metered nor the preset's: a stereo pair's right
  /// camera takes its left's, as a rig with synchronised exposure does.
  std::optional<float> ev100 = std::nullopt;
  const CanopyMap* canopy = nullptr;  ///< The canopy over the view (sky light under trees), or none.
  TrailSurface trail_surface = TrailSurface::PackedEarth;  ///< How the trail looks (trail.surface).
  bool mask_coverage = true;  ///< Blend pixels of minified alpha masks to their coverage (render/foliage_aa.hpp).
  ShadeScratch* scratch = nullptr;  ///< Buffers to reuse across calls, or none (this call allocates its own).
};

/// What shading saw, for the run's statistics.
struct ShadeCounts {
  uint64_t bare_soil_pixels = 0;  ///< Forest-floor pixels whose bare-soil weight is at least 0.5.
  float ev100 = 0.0f;             ///< The EV100 the frame was exposed with (after metering and compensation).
};

/// Shades every pixel with the preset's weather applied (with_weather): procedural material albedo
/// (wet or snowy as the weather says) lit by the sun (shadow-mapped, back-lit foliage translucency)
/// and the sky's spherical-harmonics ambient light (screen-space AO at half resolution, reused only
/// across pixels of similar depth; under the canopy map's trees partly replaced by their green scattered light), through exponential height fog; sky pixels get the Preetham /
/// overcast sky; with mask_coverage, pixels of minified leaf masks blended to their coverage (MaskBlendRows);
/// falling rain or snow over the radiance (thinner under the canopy over the camera). Then the camera model: motion blur, depth
/// of field and chromatic aberration on the whole linear frame (only when one is on), the EV100
/// exposure (the preset's, or metered from the whole linear frame with auto_exposure; minus the
/// compensation) with the white balance and vignetting, shot + read sensor noise, ACES tone mapping, sRGB.
/// Writes width*height*3 bytes, R, G, B, row-major. Rows run in parallel on the caller's TBB
/// arena; every pixel is a pure function of the inputs, so the bytes never depend on threads.
/// Returns the counts of what it shaded.
ShadeCounts shade_rgb(const ShadeInputs& in, std::vector<uint8_t>& rgb_out);

}  // namespace silva::render
