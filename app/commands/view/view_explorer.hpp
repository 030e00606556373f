#pragma once
/// @file The state behind `silva view`'s page: the world on screen, the config edits of the page
/// (checked by the same loader and messages as the CLI), and the world regenerated in the
/// background while the old one keeps answering; its routes on a web::ViewServer.
#include <condition_variable>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "pipeline/schedule/view_world.hpp"
#include "pipeline/config/config_loader.hpp"
#include "web/view_server.hpp"
#include "app/cli/pipeline_names.hpp"

namespace silva::app {

/// The config the page asks for: the command's sources plus the page's seed and `key=value` edits.
struct ViewEdits {
  std::optional<std::string> seed;     ///< Seed typed or drawn on the page (else the command's).
  std::vector<std::string> overrides;  ///< `key=value` in the page's order, after the command's --set.
};

/// The explorer behind the page: one world on screen, at most one being built.
class ViewExplorer {
 public:
  /// Builds the first world from `sources` (seed drawn from the clock when none is given).
  /// Throws InputError like the CLI.
  explicit ViewExplorer(ConfigSources sources);
  ~ViewExplorer();
  ViewExplorer(const ViewExplorer&) = delete;
  ViewExplorer& operator=(const ViewExplorer&) = delete;

  /// Registers the page's routes: GET /frame, /probe, /state, /trail, /map, /config.toml;
  /// POST /config, /capture.
  void install(web::ViewServer& server);

  /// The world on screen.
  std::shared_ptr<ViewWorld> world() const;

  /// Checks `edits` (InputError with the CLI's message) and starts building their world in the
  /// background; the newest edits win over ones not started yet.
  void edit(const ViewEdits& edits);

 private:
  /// The background builder: takes the newest pending edits, builds, swaps, repeats.
  void build_loop();
  /// GET /frame: x, y, z, yaw, pitch, walk (0/1), view, w, h -> JPEG; the pose rendered in X-Silva-Pose.
  web::Reply frame(const web::Request& r);
  /// GET /state: seed, generation, build status and error, edits, start pose, camera keys.
  web::Reply state() const;
  /// POST /config {"seed", "overrides"}: 200, or 400 with the CLI's message.
  web::Reply config(const web::Request& r);
  /// POST /capture {"x", "y", "z", "yaw", "pitch", "walk"}: the frame written, or the error.
  web::Reply capture(const web::Request& r);

  ConfigSources sources_;                 ///< The command's config sources.
  mutable std::mutex mutex_;              ///< Guards everything below.
  std::condition_variable wake_;          ///< Wakes the builder.
  std::shared_ptr<ViewWorld> world_;      ///< On screen.
  std::optional<LoadedConfig> pending_;   ///< Checked config waiting to be built.
  ViewEdits edits_;                       ///< The edits of the world on screen or being built.
  bool building_ = false;                 ///< True while a world is being built.
  std::string error_;                     ///< Why the last build failed ("" = it did not).
  int generation_ = 0;                    ///< Bumped at each swap.
  bool stopping_ = false;                 ///< Ends the builder.
  std::optional<ViewPose> last_pose_;     ///< The latest pose a frame was asked for (a new world warms there).
  std::thread builder_;                   ///< Runs build_loop.
};

/// The config `sources` + `edits` give, checked (CLI messages); the page may not move output.dir
/// or captures.poses_file. A missing seed is drawn from the clock.
LoadedConfig load_view_config(const ConfigSources& sources, const ViewEdits& edits);

}  // namespace silva::app
