#pragma once
/// @file Render phase: the active camera's visibility pass and sun maps into a frame slot (system "render_views"),
/// the frame slots that carry a frame on to the Write phase, and the cache that lets a view fan share its sun maps.
#include <array>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <span>
#include <vector>

#include "components/sensor.hpp"
#include "core/lidar_point.hpp"
#include "core/ontology.hpp"
#include "ecs/world.hpp"
#include "io/capture_set.hpp"
#include "io/dataset_card.hpp"
#include "io/output_types.hpp"
#include "raycast/lidar.hpp"
#include "render/gbuffer.hpp"
#include "render/frame_lighting.hpp"
#include "core/aabb.hpp"
#include "core/recycling_pool.hpp"
#include "render/canopy_map.hpp"
#include "render/renderer.hpp"
#include "render/shade.hpp"
#include "systems/prepare_scene.hpp"
#include "world/plan_captures.hpp"

namespace silva::systems {

/// A view is blocked (the camera inside foliage or against bark) when at least kBlockedViewShare of its pixels see a
/// surface nearer than kBlockedViewDepth metres.
inline constexpr float kBlockedViewDepth = 0.5f;
/// Share of a blocked view's pixels nearer than kBlockedViewDepth.
inline constexpr double kBlockedViewShare = 0.3;

/// Resource: what a capture run renders and where it writes.
struct CaptureSettings {
  render::RunLighting lighting;      ///< Selected lighting preset, exposure and per-frame randomisation.
  Ontology ontology;                 ///< Class ids and colours.
  io::OutputSelection outputs;       ///< Output types to write.
  std::filesystem::path run_dir;     ///< <output.dir>/<seed>/.
  raycast::LidarPreset lidar;        ///< The LiDAR model of output type lidar.
  double stereo_baseline_m = 0;      ///< Baseline of the stereo pair's right camera, metres (0: one camera).
};

/// A view's sun passes.
struct SunMaps {
  render::ShadowMap shadow;  ///< The sun shadow map.
  render::CanopyMap canopy;  ///< The canopy over the view (sky light under trees).
};

/// What a set of sun maps was drawn from: the same key, the same maps bit for bit.
struct SunKey {
  std::shared_ptr<const FrameScene> scene;  ///< The fan's scene (held, so its address names it alone).
  AABB region;                              ///< The shadow map's region (the canopy map's follows from it).
  int resolution = 0;                       ///< Its texels per side.
  Vec3d to_sun = Vec3d::Zero();             ///< Direction towards the sun.
  /// True when every field is equal (the scene by address).
  bool operator==(const SunKey& o) const;
};

/// Recycled sun maps, and the last view fan's maps with their key. Used by one thread at a time (the Render
/// phase); frames holding maps may drop them on any thread.
class SunCache {
 public:
  /// The last kept maps when `key` is theirs; else null, and the kept maps are let go (another view's maps
  /// are drawn next, and the set returns to the pool once no frame holds it).
  std::shared_ptr<const SunMaps> find(const SunKey& key);
  /// Maps no frame holds, to draw into: a recycled set when one is free, else a new one.
  std::shared_ptr<SunMaps> take();
  /// Keeps `maps`, drawn from `key`, for find().
  void keep(SunKey key, std::shared_ptr<const SunMaps> maps);
  /// The region drawn straight down that a canopy map is made from: one scratch for every set, since the
  /// Render phase draws one set at a time and the canopy map keeps what it needs.
  render::ShadowMap& canopy_source() { return canopy_source_; }

 private:
  std::vector<std::shared_ptr<SunMaps>> pool_;  ///< Every set made; free when the pool holds its only reference.
  std::optional<SunKey> key_;                   ///< What last_ was drawn from.
  std::shared_ptr<const SunMaps> last_;         ///< The last kept maps.
  render::ShadowMap canopy_source_;             ///< See canopy_source().
};

/// One frame travelling from Render through Write; its buffers are reused across frames.
struct FrameWork {
  world::PlannedFrame frame;         ///< The planned capture.
  render::FrameLighting lighting;    ///< The frame's lighting (drawn per frame when randomised).
  float ev100 = 0;                   ///< The EV100 the RGB was exposed with (0 without rgb).
  render::GBuffer gbuffer;           ///< Labels, depth, normals.
  std::vector<uint8_t> rgb;          ///< Shaded RGB (empty when rgb is not selected).
  std::vector<uint8_t> rgb_scratch;  ///< Edge-filtered RGB before it is swapped into `rgb`.
  /// Shading's whole-frame buffers, lent for each shading: FrameSlots gives its slots one shelf, so a run keeps as
  /// many as frames shade at once, not one per slot.
  RecyclingPool<render::ShadeScratch> shade_scratches;
  std::shared_ptr<const SunMaps> sun;  ///< The view's sun passes (with rgb; shared by the frames of a view fan).
  io::EncodedSet files;              ///< Encoded outputs.
  double render_s = 0, shadow_s = 0, shade_s = 0, encode_s = 0;  ///< Per-step wall times.
  uint64_t triangles_submitted = 0, triangles_rasterised = 0;    ///< Camera pass work counts.
  std::array<uint64_t, kRoleCount> pixels_by_role{};  ///< Pixels of each class (role) in the view.
  io::CardCounts card;               ///< The dataset card's label counts of the frame (from the planes).
  uint64_t bare_soil_pixels = 0;     ///< Forest-floor pixels that look like bare soil (0 without rgb).
  uint64_t near_pixels = 0;          ///< Left camera: pixels whose surface is nearer than kBlockedViewDepth
  std::vector<LidarPoint> lidar;     ///< The frame's LiDAR sweep (empty when lidar is not selected).
  double lidar_s = 0;                ///< Wall time of the sweep (scene update and cast).
  /// The stereo pair's right view (rendered when CaptureSettings::stereo_baseline_m > 0, else left as it was): this
  /// frame's lighting, shaded with this frame's shadow map; its own `right`, `shadow` and `lidar` stay unused.
  std::unique_ptr<FrameWork> right;
};

/// Resource: the renderer, the frame slots (recycled, so each in-flight frame's big buffers are
/// allocated once per run) and the slot rendered this frame.
class FrameSlots {
 public:
  /// A free slot (a new one when none is free); it returns to the pool when its last owner drops it.
  std::shared_ptr<FrameWork> take();
  std::unique_ptr<render::Renderer> renderer = std::make_unique<render::Renderer>();  ///< Camera passes' buffers.
  /// The sun's passes (shadow map, canopy map) while `renderer` draws the cameras, made on first use from
  /// kThreadsForSunBeside threads (null below: `renderer` draws them after the cameras).
  std::unique_ptr<render::Renderer> sun_renderer;
  SunCache sun_maps;                  ///< The frames' sun maps, recycled, and the last view fan's.
  std::shared_ptr<FrameWork> current; ///< The slot the Render phase filled this frame (or null).

 private:
  RecyclingPool<FrameWork> slots_;                      ///< The slots not in flight.
  RecyclingPool<render::ShadeScratch> shade_scratches_; ///< Shading's buffers, which every slot lends from.
};

/// Threads from which the sun's passes run beside the camera passes, on a renderer of their own (its buffers add
/// about 110 MB to a 720p run, which fewer threads do not repay).
inline constexpr int kThreadsForSunBeside = 4;

/// Renders the G-buffer of each of `cameras` (left first) for `work.frame` from scene.frame with `slots.renderer` —
/// the left camera's into `work`, a stereo pair's right camera's into work.right — and, when rgb is selected, the
/// left camera's sun maps (shadow map and canopy map) from scene.sun_scene(): from kThreadsForSunBeside threads at
/// the same time with `slots.sun_renderer`, else afterwards with `slots.renderer`. The frames of a view fan share
/// one set of sun maps, planned over all the fan's views and drawn by the first of them.
void render_frame(const PreparedScene& scene, const world::WorldContext& ctx, const CaptureSettings& settings,
                  std::span<const CameraSensor> cameras, FrameSlots& slots, FrameWork& work);

/// Registers "render_views" (phase Render): when a camera is active, renders the PreparedScene
/// into a fresh FrameSlots slot, left in FrameSlots::current for the Write phase.
void install_render_views(ecs::World& world, CaptureSettings settings);

}  // namespace silva::systems
