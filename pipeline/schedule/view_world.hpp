#pragma once
/// @file One world of `silva view`: its config, run inputs and schedule, rendered from a free
/// camera through the same schedule `silva generate` runs (Stream .. Render, then the capture's
/// shading), and captured into the output folder exactly as a custom pose of `generate`.
#include <cstdint>
#include <filesystem>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "pipeline/config/run_setup.hpp"
#include "pipeline/schedule/world_schedule.hpp"
#include "world/class_map.hpp"
#include "world/pose_clearance.hpp"

namespace silva::pipeline {

/// What the view shows.
enum class ViewMode { Rgb, Semantic, Instance, Depth, Normal };

/// Parses "rgb", "semantic", "instance", "depth" or "normal"; false when unknown.
bool parse_view_mode(std::string_view name, ViewMode& mode);

/// A free camera pose (CONTRACT.md angles; roll is always 0 in the view).
struct ViewPose {
  Vec3d position = Vec3d::Zero();  ///< World position; z ignored when `walk`.
  bool walk = false;               ///< Camera held the rig's camera height above the terrain (world::plan_custom).
  /// Walking: where the camera comes from; a step from a clear spot into one closer than
  /// captures.clearance to a trunk or other solid is refused (the camera stays there).
  std::optional<Eigen::Vector2d> from;
  double yaw_deg = 0, pitch_deg = 0;  ///< Looking direction.
};

/// One streamed frame.
struct ViewFrame {
  std::vector<uint8_t> jpeg;        ///< The image, JPEG.
  Vec3d position = Vec3d::Zero();   ///< The camera position rendered (walk: z resolved).
  double ground_z = 0;              ///< Terrain height under the camera.
  bool blocked = false;             ///< The step was refused (walking into a solid).
  double render_ms = 0;             ///< Schedule frame + shading + encoding, milliseconds.
  double schedule_ms = 0;           ///< Of which Stream .. Render (chunks, scene, visibility, shadow map).
  double raster_ms = 0;             ///< Of which the visibility pass and the shadow map.
  double shade_ms = 0;              ///< Of which shading (rgb) or label colours.
  double encode_ms = 0;             ///< Of which JPEG encoding.
};

/// JPEG quality of streamed frames.
inline constexpr int kViewJpegQuality = 80;

/// A loaded world of the view. Thread-safe: calls are serialised by an internal mutex (the class
/// map has its own, so building it never stalls frames).
class ViewWorld {
 public:
  /// Loads the run inputs of `loaded` (make_run_setup) and installs the schedule. Throws InputError.
  explicit ViewWorld(LoadedConfig loaded);

  /// Renders `pose` in `mode` at `width` x `height`; keeps the frame for probe().
  ViewFrame render(const ViewPose& pose, ViewMode mode, int width, int height);

  /// Class, instance id and depth at (u, v) in [0, 1)^2 of the last rendered frame ({"hit": false} when none).
  nlohmann::json probe(double u, double v) const;

  /// Writes `pose` as the next frame of the custom sequence into <output.dir>/<seed>/ (the files
  /// `generate` writes for it) and appends it to <output.dir>/<seed>/poses.json. Returns
  /// {"frame", "run_dir", "poses_file", "files"}. Throws InputError / IoError.
  nlohmann::json capture(const ViewPose& pose);

  /// The class map of the capture region (built on one thread on first call, then kept), as PNG, with its
  /// placement {"x0", "y1", "metres_per_pixel", "width", "height"}.
  std::pair<std::vector<uint8_t>, nlohmann::json> class_map();

  /// The trail's centre line every `step` metres as [[x, y, z, yaw_deg], ...] (empty without a trail).
  nlohmann::json trail(double step) const;

  /// Where a first visit starts: the trail's start looking along it, else the origin.
  ViewPose start_pose() const;

  /// The config this world was made from.
  const LoadedConfig& loaded() const { return loaded_; }

 private:
  /// The planned frame of `pose` at `width` x `height` (sequence "view", frame 0).
  world::PlannedFrame view_frame(const ViewPose& pose, int width, int height) const;
  /// True when a ground camera at `eye` is closer than captures.clearance to a solid (the rules of
  /// planned poses, world/pose_clearance.hpp).
  bool blocked(const Vec3d& eye);

  LoadedConfig loaded_;
  RunSetup setup_;
  std::unique_ptr<WorldSchedule> schedule_;
  std::unique_ptr<world::CrownProfiles> crowns_;  ///< For the clearance probe.
  std::shared_ptr<systems::FrameWork> last_;  ///< The last rendered frame (probe).
  mutable std::mutex mutex_;                  ///< Serialises schedule use and last_.
  std::mutex map_mutex_;                      ///< Guards map_.
  std::optional<std::pair<std::vector<uint8_t>, nlohmann::json>> map_;  ///< Built class map.
};

/// The 8-bit RGB image a mode shows for a rendered frame (Rgb: shaded as a capture is).
std::vector<uint8_t> view_image(const world::WorldContext& ctx, const systems::CaptureSettings& settings, ViewMode mode,
                                systems::FrameWork& work);

}  // namespace silva::pipeline
