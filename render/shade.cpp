#include "render/shade.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <utility>
#include <vector>

#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include "core/base_color.hpp"
#include "core/error.hpp"
#include "render/auto_exposure.hpp"
#include "render/bark_materials.hpp"
#include "render/camera_encode.hpp"
#include "render/camera_optics.hpp"
#include "render/foliage_aa.hpp"
#include "render/linear_frame.hpp"
#include "render/materials.hpp"
#include "render/post.hpp"
#include "render/shade_ao.hpp"
#include "render/shadow_lookup.hpp"
#include "render/sky.hpp"
#include "render/sky_glare.hpp"
#include "render/sky_fog.hpp"
#include "render/surface_light.hpp"
#include "render/trail_material.hpp"
#include "render/view_directions.hpp"
#include "render/weather_look.hpp"
#include "render/weather_overlay.hpp"

namespace silva::render {

namespace {

/// Relative depth difference above which a half-resolution AO sample is not reused for a pixel.
constexpr float kAoReuseDepth = 0.05f;

/// Screen-space AO evaluated at the even pixels (2x, 2y) only (-1 where that pixel saw the sky).
struct HalfResAo {
  int width = 0, height = 0;  ///< Half-resolution size (rounded up).
  std::vector<float>& ao;     ///< Row-major, width * height.

  /// Evaluates the samples in parallel rows into `storage` (kept by the caller for later frames).
  HalfResAo(const GBuffer& g, const Camera& camera, std::vector<float>& storage)
      : width((g.width + 1) / 2), height((g.height + 1) / 2), ao(storage) {
    ao.resize(size_t(width) * size_t(height));
    tbb::parallel_for(tbb::blocked_range<int>(0, height), [&](const tbb::blocked_range<int>& rows) {
      for (int y = rows.begin(); y < rows.end(); ++y) {
        float* row = &ao[size_t(y) * size_t(width)];
        screen_space_ao_row(g, camera, 2 * y, 0, 2, width, row);
        for (int x = 0; x < width; ++x)
          if (g.depth[size_t(2 * y) * size_t(g.width) + size_t(2 * x)] == 0.0f) row[x] = -1.0f;
      }
    });
  }

  /// The sample of the nearest of the (up to 4) even pixels around full-resolution pixel (u, v)
  /// whose depth is within kAoReuseDepth of the pixel's, or -1 when none is.
  float reuse(const GBuffer& g, int u, int v) const {
    const float depth = g.depth[size_t(v) * size_t(g.width) + size_t(u)];
    const int hx = u / 2, hy = v / 2;
    const int nx = std::min(hx + (u & 1), width - 1), ny = std::min(hy + (v & 1), height - 1);
    const float limit = kAoReuseDepth * depth;
    float best = -1.0f, best_diff = 0.0f;
    for (const auto& [x, y] : {std::pair{hx, hy}, std::pair{nx, hy}, std::pair{hx, ny}, std::pair{nx, ny}}) {
      const float a = ao[size_t(y) * size_t(width) + size_t(x)];
      if (a < 0.0f) continue;
      const float diff = std::abs(g.depth[size_t(2 * y) * size_t(g.width) + size_t(2 * x)] - depth);
      if (diff <= limit && (best < 0.0f || diff < best_diff)) best = a, best_diff = diff;
    }
    return best;
  }

  /// AO of every surface pixel of row v into out: reused samples, and the pixels without one
  /// evaluated together, a SIMD lane each (`missing` and `evaluated` are scratch).
  void row(const GBuffer& g, const Camera& camera, int v, std::vector<int32_t>& missing, std::vector<float>& evaluated,
           std::vector<float>& out) const {
    const size_t first = size_t(v) * size_t(g.width);
    missing.clear();
    for (int u = 0; u < g.width; ++u) {
      if (g.depth[first + size_t(u)] == 0.0f) continue;
      out[size_t(u)] = reuse(g, u, v);
      if (out[size_t(u)] < 0.0f) missing.push_back(u);
    }
    evaluated.resize(missing.size());
    screen_space_ao_columns(g, camera, v, missing.data(), int(missing.size()), evaluated.data());
    for (size_t k = 0; k < missing.size(); ++k) out[size_t(missing[k])] = evaluated[k];
  }
};

/// What shade_rgb evaluates for a whole row before the per-pixel loop (SIMD lanes).
struct RowTerms {
  std::vector<float> fog_amount;    ///< HeightFog amount per pixel.
  std::vector<float> ao;            ///< Ambient visibility per surface pixel (HalfResAo::row).
  std::vector<int32_t> ao_missing;  ///< Scratch: pixels without a reusable AO sample.
  std::vector<float> ao_evaluated;  ///< Scratch: their AO.
  std::vector<float> sun_visible;   ///< Shadow-map visibility per pixel (1 without shadows).
  std::vector<float> canopy;        ///< Share of the sky light the canopy takes per pixel (0 without a map).
  std::vector<Vec3f> ground;        ///< Ground albedo per pixel (only procedural Ground pixels set).
  std::vector<Vec2f> ground_slope;  ///< Ground relief gradient per pixel (the same pixels).
  std::vector<Vec3f> trail_floor;   ///< Forest-floor albedo under each procedural Trail pixel (only those set).
  std::vector<uint32_t> ground_at;  ///< Pixels of the row with procedural Ground or Trail (the trail's floor).
  std::vector<Vec3f> gather_p, gather_n, gather_out;  ///< Compacted ground inputs and results.
  std::vector<float> gather_footprint, gather_soil;  ///< Metres per pixel there; bare-soil weights.
  std::vector<Vec2f> gather_slope;  ///< Compacted relief gradients.
  float metres_per_depth = 0.0f;    ///< Width of one pixel per metre of depth (1 / fx).
  SurfaceBatch rough;               ///< The row's surface pixels lit on SIMD lanes (roughness >= kSharpReflection).
  std::vector<uint32_t> rough_at;   ///< Their columns.
  std::vector<Vec3f> rough_out;     ///< Their radiance.
  std::vector<Vec3f> view_dir;      ///< Unit view direction per pixel (view_directions_row).
  std::vector<Vec3f> foliage;       ///< Plain-foliage albedo per pixel (only those pixels set).
  std::vector<uint32_t> foliage_at; ///< Pixels of the row with plain foliage.
  std::vector<Vec3f> foliage_p;     ///< Their positions,
  std::vector<uint32_t> foliage_variation;  ///< instance variations,
  std::vector<float> foliage_leaf;  ///< leaf shades,
  std::vector<Vec3f> foliage_base;  ///< base colours
  std::vector<Vec3f> foliage_out;   ///< and albedos.
  uint64_t bare_soil = 0;           ///< Ground pixels with a bare-soil weight >= 0.5 (all rows evaluated).

  /// Sized for rows of `width` pixels.
  explicit RowTerms(int width)
      : fog_amount(size_t(width)), ao(size_t(width)), sun_visible(size_t(width), 1.0f), canopy(size_t(width), 0.0f),
        ground(size_t(width)),
        ground_slope(size_t(width)), trail_floor(size_t(width)), view_dir(size_t(width)), foliage(size_t(width)) {}

  /// Evaluates the terms of row v.
  void evaluate(const ShadeInputs& in, const Sky& sky, const HeightFog& fog, const HalfResAo& half_ao, int v) {
    const GBuffer& g = in.gbuffer;
    const size_t row = size_t(v) * size_t(g.width), w = size_t(g.width);
    fog.amounts(&g.position[row], w, fog_amount.data());
    half_ao.row(g, in.camera, v, ao_missing, ao_evaluated, ao);
    if (in.shadow && sky.sun_illuminance.maxCoeff() > 0.0f)
      shadow_visibility_row(*in.shadow, &g.position[row], &g.normal[row], w, sky.to_sun, sun_visible.data());
    if (in.canopy) canopy_share_row(*in.canopy, &g.position[row], w, canopy.data());
    ground_at.clear();
    gather_p.clear();
    gather_n.clear();
    gather_footprint.clear();
    metres_per_depth = float(1.0 / in.camera.fx);
    foliage_at.clear();
    foliage_p.clear();
    foliage_variation.clear();
    foliage_leaf.clear();
    foliage_base.clear();
    Vec3f base;
    for (size_t u = 0; u < w; ++u) {
      if (g.depth[row + u] == 0.0f || g.base_color[row + u] != 0) continue;
      if (g.material[row + u] == Material::Ground || g.material[row + u] == Material::Trail) {
        ground_at.push_back(uint32_t(u));
        gather_p.push_back(g.position[row + u]);
        gather_n.push_back(g.normal[row + u]);
        gather_footprint.push_back(g.depth[row + u] * metres_per_depth);
      } else if (plain_foliage_base(g.material[row + u], base)) {
        foliage_at.push_back(uint32_t(u));
        foliage_p.push_back(g.position[row + u]);
        foliage_variation.push_back(g.variation[row + u]);
        foliage_leaf.push_back(leaf_brightness(g.leaf[row + u]));
        foliage_base.push_back(base);
      }
    }
    foliage_out.resize(foliage_at.size());
    foliage_albedo_row(foliage_p.data(), foliage_variation.data(), foliage_base.data(), foliage_leaf.data(), foliage_at.size(),
                       foliage_out.data());
    for (size_t k = 0; k < foliage_at.size(); ++k) foliage[foliage_at[k]] = foliage_out[k];
    gather_out.resize(ground_at.size());
    gather_soil.resize(ground_at.size());
    gather_slope.resize(ground_at.size());
    ground_albedo_row(gather_p.data(), gather_n.data(), gather_footprint.data(), ground_at.size(), gather_out.data(),
                      gather_soil.data(), gather_slope.data(), in.floor);
    for (size_t k = 0; k < ground_at.size(); ++k) {
      if (g.material[row + ground_at[k]] == Material::Trail) {
        trail_floor[ground_at[k]] = gather_out[k];
        continue;
      }
      ground[ground_at[k]] = gather_out[k];
      ground_slope[ground_at[k]] = gather_slope[k];
      bare_soil += gather_soil[k] >= 0.5f ? 1 : 0;
    }
  }
};

/// The material inputs of the visible surface pixel (u, v): albedo (after the weather's look) and
/// roughness, the shading normal with the material's relief, and the row's AO, sun and fog terms.
SurfaceSample surface_sample(const ShadeInputs& in, const WeatherLook& look, const RowTerms& row, int u, int v,
                             const Vec3f& view_dir) {
  const GBuffer& g = in.gbuffer;
  const size_t i = size_t(v) * size_t(g.width) + size_t(u);
  const SurfacePoint s{g.position[i], g.normal[i], g.uv[i], g.material[i], g.variation[i], in.floor,
                       leaf_brightness(g.leaf[i]), in.trail_surface, g.depth[i] * row.metres_per_depth};
  const bool procedural_ground = g.base_color[i] == 0 && s.material == Material::Ground;
  const bool procedural_trail = g.base_color[i] == 0 && s.material == Material::Trail;
  Vec3f base;
  // A species bark's colour and fissure relief come from one lookup of its plate.
  const bool bark = is_species_bark(s.material);
  const SpeciesBark species = bark ? species_bark(s) : SpeciesBark{Vec3f::Zero(), Vec3f::Zero()};
  Vec3f albedo = g.base_color[i] != 0                  ? unpack_srgb8(g.base_color[i])
                 : procedural_ground                   ? row.ground[size_t(u)]
                 : procedural_trail                    ? trail_albedo_on(s, row.trail_floor[size_t(u)])
                 : bark                                ? species.albedo
                 : plain_foliage_base(s.material, base) ? row.foliage[size_t(u)]
                                                       : material_albedo(s);
  const float puddle = look.active() ? look.puddle(s) : 0.0f;
  if (look.active()) albedo = look.albedo(albedo, s, puddle);
  const MaterialResponse response = material_response(s.material);
  const Vec2f& slope = row.ground_slope[size_t(u)];
  Vec3f n = procedural_ground ? bumped_normal(s.normal, Vec3f(slope.x(), slope.y(), 0.0f))
                              : material_shading_normal(s, s.footprint, species.slope);
  if (puddle > 0.0f) n = (n + (Vec3f::UnitZ() - n) * puddle).normalized();  // still water lies level
  const float roughness = look.active() ? look.roughness(s, response.roughness, n, puddle) : response.roughness;
  return {albedo,       n,           s.normal,         view_dir,
          roughness,    response.f0, response.translucency, row.ao[size_t(u)],
          row.sun_visible[size_t(u)], row.fog_amount[size_t(u)], row.canopy[size_t(u)]};
}

/// Encodes every row of the whole linear `frame` into rgb_out (8-bit RGB) with the exposed camera model.
void encode_frame(const ShadeInputs& in, const CameraModel& model, float exposure, uint64_t key, const LinearFrame& frame,
                  std::vector<uint8_t>& rgb_out) {
  tbb::parallel_for(tbb::blocked_range<int>(0, frame.height), [&](const tbb::blocked_range<int>& rows) {
    RowEncoder encoder(in.camera, model, exposure, in.seed, key, in.white_balance);
    for (int v = rows.begin(); v < rows.end(); ++v) {
      const size_t row = size_t(v) * size_t(frame.width);
      encoder.encode(v, frame.rgb[row].data(), &rgb_out[row * 3]);
    }
  });
}

/// What shading one row reads besides its inputs: the frame's sky, fog, weather look, lighting and AO.
struct RowShading {
  const ShadeInputs& in;
  const Sky& sky;
  const HeightFog& fog;
  const WeatherLook& look;
  const SurfaceLighting& lighting;
  const HalfResAo& half_ao;
};

/// Shades row v of the G-buffer into radiance (g.width values) with `terms` as the row's scratch.
void shade_row(const RowShading& s, RowTerms& terms, int v, Vec3f* radiance) {
  const GBuffer& g = s.in.gbuffer;
  const size_t row = size_t(v) * size_t(g.width);
  terms.evaluate(s.in, s.sky, s.fog, s.half_ao, v);
  terms.rough.start(size_t(g.width));
  terms.rough_at.clear();
  view_directions_row(s.in.camera, v, terms.view_dir.data());
  for (int u = 0; u < g.width; ++u) {
    const Vec3f& dir = terms.view_dir[size_t(u)];
    if (g.depth[row + size_t(u)] == 0.0f) {
      radiance[u] = s.sky.radiance(dir);
      continue;
    }
    const SurfaceSample sample = surface_sample(s.in, s.look, terms, u, v, dir);
    if (sample.roughness < kSharpReflection) {
      radiance[u] = light_surface(s.lighting, sample);
      continue;
    }
    terms.rough.push(sample);
    terms.rough_at.push_back(uint32_t(u));
  }
  terms.rough.pad();
  terms.rough_out.resize(terms.rough.padded_size());
  light_rough_surfaces(s.lighting, terms.rough, terms.rough_out.data());
  for (size_t k = 0; k < terms.rough_at.size(); ++k) radiance[terms.rough_at[k]] = terms.rough_out[k];
}

/// Rows per band: a band's rows are shaded by one task and, with the coverage blend, all but its first and
/// last finished as soon as the row below them is shaded (those two wait for the neighbouring bands).
constexpr int kBandRows = 16;

/// Runs band(first, end) for every band of kBandRows rows of a frame `height` rows high, in parallel.
template <class Band>
void each_band(int height, Band band) {
  const int bands = (height + kBandRows - 1) / kBandRows;
  tbb::parallel_for(tbb::blocked_range<int>(0, bands), [&](const tbb::blocked_range<int>& range) {
    for (int b = range.begin(); b < range.end(); ++b) band(b * kBandRows, std::min(height, (b + 1) * kBandRows));
  });
}

/// One thread's scratch for shading and finishing rows.
struct RowWorker {
  RowTerms terms;                      ///< The row's terms.
  std::vector<Vec3f> row;              ///< A row's radiance: shaded (without a whole frame) or blended.
  std::optional<RowEncoder> encoder;   ///< Encodes finished rows, unless the whole frame is encoded at the end.
  std::optional<MaskBlendRows> blend;  ///< The coverage blend, when the frame has minified masks.
};

/// Share of the sky light the canopy takes at the camera (0 without a canopy map).
float canopy_at_camera(const ShadeInputs& in) {
  float share = 0.0f;
  if (in.canopy) {
    const Vec3f eye = in.camera.position().cast<float>();
    canopy_share_row(*in.canopy, &eye, 1, &share);
  }
  return share;
}

}  // namespace

ShadeCounts shade_rgb(const ShadeInputs& in, std::vector<uint8_t>& rgb_out) {
  const GBuffer& g = in.gbuffer;
  if (g.width != in.camera.width || g.height != in.camera.height)
    throw InputError("shade_rgb: G-buffer " + std::to_string(g.width) + "x" + std::to_string(g.height) +
                     " does not match the camera's " + std::to_string(in.camera.width) + "x" +
                     std::to_string(in.camera.height));
  rgb_out.resize(g.size() * 3);
  const LightingPreset lit = with_weather(in.preset);
  const Sky sky(lit);
  const HeightFog fog(lit, sky, in.camera.position().cast<float>());
  const WeatherLook look(lit.weather, in.trail_surface);
  const SurfaceLighting lighting(sky, fog, in.preset);
  const bool metered = in.auto_exposure && !in.ev100;
  float ev100 = in.ev100 ? *in.ev100 : lit.ev100 - in.exposure_compensation_ev;
  float exposure = exposure_multiplier(ev100);
  const uint64_t key = noise_key(in.sequence, in.frame);
  CameraModel exposed_model = exposed_camera_model(in.model, ev100);
  const WeatherOverlay overlay(lit.weather, sky, in.seed, key, g.height, canopy_at_camera(in));
  const SkyGlare glare(g, in.camera, sky, float(in.model.bloom));
  ShadeScratch own;  // this call's buffers when the caller keeps none
  ShadeScratch& scratch = in.scratch ? *in.scratch : own;
  const HalfResAo half_ao(g, in.camera, scratch.ao);
  const RowShading shading{in, sky, fog, look, lighting, half_ao};
  const bool soften = in.mask_coverage && has_minified_masks(g);  // the blend reads the rows above and below
  const bool deferred = needs_whole_frame(in.model) || metered;   // metering and optics need every row first
  LinearFrame& frame = scratch.frame;        // shaded rows (when blended or deferred)
  LinearFrame& finished = scratch.finished;  // blended rows (when both)
  const bool whole = soften || deferred;
  if (whole) frame.resize(g.width, g.height);
  if (soften && deferred) finished.resize(g.width, g.height);
  tbb::enumerable_thread_specific<RowWorker> workers([&] {
    RowWorker w{RowTerms(g.width), std::vector<Vec3f>(size_t(g.width)), std::nullopt, std::nullopt};
    if (!deferred) w.encoder.emplace(in.camera, exposed_model, exposure, in.seed, key, in.white_balance);
    if (soften) w.blend.emplace(g, exposure, frame);  // the preset's exposure when metered
    return w;
  });
  const auto shaded_row = [&](RowWorker& w, int v) {
    return whole ? &frame.rgb[size_t(v) * size_t(g.width)] : w.row.data();
  };
  const auto finish = [&](RowWorker& w, int v) {  // blend, weather overlay, glare, then encode or keep for the frame
    const size_t row = size_t(v) * size_t(g.width);
    Vec3f* radiance = soften ? w.row.data() : shaded_row(w, v);
    if (soften) w.blend->blend(v, radiance);
    if (overlay.active()) overlay.apply_row(v, radiance, g.width);
    if (glare.active()) glare.apply_row(v, radiance);
    if (!deferred) w.encoder->encode(v, radiance->data(), &rgb_out[row * 3]);
    else if (soften) std::copy(radiance, radiance + g.width, &finished.rgb[row]);
  };
  each_band(g.height, [&](int first, int end) {
    RowWorker& w = workers.local();
    for (int v = first; v < end; ++v) {
      shade_row(shading, w.terms, v, shaded_row(w, v));
      if (!soften) finish(w, v);
      else if (v - 1 > first) finish(w, v - 1);
    }
  });
  if (soften)
    each_band(g.height, [&](int first, int end) {
      RowWorker& w = workers.local();
      finish(w, first);
      if (end - 1 > first) finish(w, end - 1);
    });
  uint64_t bare_soil = 0;
  for (const RowWorker& w : workers) bare_soil += w.terms.bare_soil;
  if (deferred) {
    if (soften) std::swap(frame, finished);
    if (metered) {
      ev100 = ev100_for_luminance(log_average_luminance(frame)) - in.exposure_compensation_ev;
      exposure = exposure_multiplier(ev100);
      exposed_model = exposed_camera_model(in.model, ev100);
    }
    if (needs_whole_frame(in.model)) apply_optics(frame, finished, g.depth, in.camera, in.model);
    encode_frame(in, exposed_model, exposure, key, frame, rgb_out);
  }
  return {bare_soil, ev100};
}

}  // namespace silva::render
