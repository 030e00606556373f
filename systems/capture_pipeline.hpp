#pragma once
/// @file The pass-batched capture pipeline: per frame Stream -> Prepare -> Render (one visibility
/// pass + sun shadow map) -> Shade -> Encode -> Write, with the next frame's render overlapping
/// the previous frame's shading, encoding and writing (bounded in-flight frames).
#include <filesystem>
#include <functional>
#include <vector>

#include "core/ontology.hpp"
#include "io/output_types.hpp"
#include "render/gbuffer.hpp"
#include "render/lighting.hpp"
#include "systems/chunk_cache.hpp"
#include "systems/plan_captures.hpp"
#include "systems/scene_builder.hpp"
#include "systems/shadow_plan.hpp"

namespace silva::world {

/// Frames in flight at once (rendering, shading/encoding, writing).
inline constexpr size_t kFramesInFlight = 3;

/// What one capture run renders and where it writes.
struct CaptureJob {
  const WorldContext* world = nullptr;           ///< World inputs (config, assets, terrain, trail).
  render::LightingPreset preset;                  ///< Selected lighting preset.
  Ontology ontology;                              ///< Class ids and colours.
  io::OutputSelection outputs;                    ///< Output types to write.
  std::filesystem::path run_dir;                  ///< <output.dir>/<seed>/.
  std::vector<PlannedFrame> frames;               ///< Frames to render, in global order.
  std::function<bool()> stop;                     ///< Polled between frames; true = stop cleanly.
};

/// Counts and per-phase wall times of a capture run (seconds summed over frames).
struct CaptureStats {
  int frames_written = 0;     ///< Frames completed.
  bool stopped = false;       ///< True when the run ended early because `stop` was set.
  uint64_t bytes_written = 0; ///< Bytes of every file written.
  uint64_t triangles_submitted = 0;   ///< Sum over frames (camera passes).
  uint64_t triangles_rasterised = 0;  ///< Sum over frames (camera passes).
  uint64_t chunks_generated = 0;      ///< Chunk cache misses.
  double stream_s = 0;   ///< Chunk streaming (generation on misses included).
  double prepare_s = 0;  ///< Scene building.
  double render_s = 0;   ///< Visibility pass + resolve.
  double shadow_s = 0;   ///< Sun shadow map pass.
  double shade_s = 0;    ///< RGB shading.
  double encode_s = 0;   ///< Encoding all outputs.
  double write_s = 0;    ///< Writing files.
  double wall_s = 0;     ///< Whole run, wall clock.
};

/// Called after each frame is written with (frames done, frames total).
using ProgressFn = std::function<void(int done, int total)>;

/// Renders and writes every frame of `job` (skipping none: resume filtering is the caller's).
/// Files are written atomically; each frame's camera JSON is written last, so its presence means
/// the frame is complete. Throws IoError on write failures.
CaptureStats run_capture(const CaptureJob& job, ChunkCache& cache, const ProgressFn& progress);

/// Sequence-relative path of a frame's camera file, whose presence marks the frame complete.
std::filesystem::path camera_file(const PlannedFrame& frame);

/// Renders one frame's G-buffer and RGB (no files): the pipeline's per-frame work for tests and benches.
struct RenderedFrame {
  render::GBuffer gbuffer;        ///< Labels, depth, normals.
  std::vector<uint8_t> rgb;       ///< Shaded RGB (empty when rgb is not needed).
};
/// Renders `frame` of `job` using `cache` (no files written).
RenderedFrame render_frame(const CaptureJob& job, ChunkCache& cache, const PlannedFrame& frame);

}  // namespace silva::world
