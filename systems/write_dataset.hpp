#pragma once
/// @file Write phase: a rendered frame's shading, encoding and files, overlapping the next frame's
/// render (system "write_dataset").
#include <array>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "ecs/ordered_stage.hpp"
#include "ecs/world.hpp"
#include "io/dataset_card.hpp"
#include "io/label_planes.hpp"
#include "io/output_types.hpp"
#include "render/gbuffer.hpp"
#include "systems/render_views.hpp"
#include "world/plan_captures.hpp"

namespace silva::systems {

/// Frames alive at once on two threads: the one rendering and the one shading, encoding and writing (a third
/// holds another frame's buffers for no speed there: bench/results/2026-12-02-amd-epyc-2core-frames-in-flight.md).
inline constexpr size_t kFramesInFlight = 2;
/// Frames alive at once on three to five threads: the one rendering plus those shading, encoding and writing.
inline constexpr size_t kFramesInFlightFromThree = 3;
/// Most frames alive at once: one more per kThreadsPerFrameInFlight threads beyond the first two.
inline constexpr size_t kMaxFramesInFlight = 5;
/// Threads that keep one more frame in flight busy: each frame's PNGs are encoded one per thread.
inline constexpr size_t kThreadsPerFrameInFlight = 4;

/// Frames alive at once on `threads` threads (1 on one thread: each frame written before the next renders; 2 on two).
size_t frames_in_flight(size_t threads);

/// Counts and per-step wall times of a capture run (seconds summed over frames).
struct CaptureStats {
  int frames_written = 0;             ///< Frames completed.
  bool stopped = false;               ///< True when the run ended early because it was asked to stop.
  uint64_t bytes_written = 0;         ///< Bytes of every file written.
  uint64_t triangles_submitted = 0;   ///< Sum over frames (camera passes).
  uint64_t triangles_rasterised = 0;  ///< Sum over frames (camera passes).
  uint64_t chunks_generated = 0;      ///< Chunks generated (cache misses).
  std::array<uint64_t, kRoleCount> pixels_by_role{};  ///< Pixels of each class over the frames written.
  uint64_t bare_soil_pixels = 0;      ///< Forest-floor pixels that look like bare soil (rgb frames).
  int blocked_views = 0;              ///< Frames whose left camera's view is blocked (kBlockedViewShare).
  std::string first_blocked;          ///< "<sequence> frame <n>" of the first blocked view ("" when none).
  double stream_s = 0;   ///< Stream .. Resolve phases (chunk generation on misses included).
  double prepare_s = 0;  ///< Scene building.
  double render_s = 0;   ///< Visibility pass + resolve.
  double shadow_s = 0;   ///< Sun shadow map pass.
  double shade_s = 0;    ///< RGB shading.
  double encode_s = 0;   ///< Encoding all outputs.
  double write_s = 0;    ///< Writing files.
  double lidar_s = 0;    ///< LiDAR scene updates and sweeps.
  uint64_t lidar_points = 0;  ///< LiDAR returns written.
  io::KnownCounts card;       ///< The dataset card's label counts of the frames written (the card reads no PNG of them).
  double wall_s = 0;     ///< Whole run, wall clock.
  std::vector<std::pair<std::string, double>> system_s;  ///< Each ECS system's wall time over the run, schedule order.
};

/// Called after each frame is written with (frames done, frames total).
using ProgressFn = std::function<void(int done, int total)>;

/// Resource: the ordered stage that shades, encodes and writes frames, and what it has done.
struct DatasetWriter {
  ecs::OrderedStage stage{kFramesInFlight - 1};  ///< Parallel shade + encode, then in-order writes.
  CaptureStats stats;                        ///< Updated by the in-order part of each frame.
  ProgressFn progress;                       ///< Told after each frame (may be empty).
  int total = 0;                             ///< Frames the run captures (for progress).
};

/// Shades `work`'s RGB from its G-buffer under its lighting (work.lighting) with the shadow map and canopy of
/// `sun` (work itself, or a stereo pair's left view) as a capture does (the frame's camera model, edge
/// antialiasing when camera.antialias; exposed with `ev100` when given), into work.rgb; sets shade_s,
/// bare_soil_pixels and ev100.
void shade_frame(const world::WorldContext& ctx, FrameWork& work, const FrameWork& sun, std::optional<float> ev100);

/// The planes the label encoders read, viewing `g`.
io::LabelPlanes label_planes(const render::GBuffer& g);

/// Sequence-relative path of a frame's camera file, whose presence marks the frame complete.
std::filesystem::path camera_file(const world::PlannedFrame& frame);

/// Creates the output folders of `frames`' sequences under `run_dir` for the selected outputs (with `stereo`, the
/// right camera's and disparity/ too); InputError when
/// a sequence folder or one of its output folders is a symbolic link.
void create_output_folders(const std::filesystem::path& run_dir, const std::vector<world::PlannedFrame>& frames,
                           const io::OutputSelection& outputs, bool stereo);

/// Registers "write_dataset" (phase Write) and its std::unique_ptr<DatasetWriter> resource (set its
/// progress and total before the frames run): hands FrameSlots::current to the writer's stage:
/// RGB shading and encoding in parallel, then the frame's files written atomically in frame order,
/// its camera JSON last (its presence marks the frame complete). Waits for the oldest frame when
/// the stage's limit (frames_in_flight(threads) - 1) is reached, so at most that many frames hold buffers.
void install_write_dataset(ecs::World& world);

}  // namespace silva::systems
