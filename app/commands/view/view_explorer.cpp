#include "app/commands/view/view_explorer.hpp"

#include <utility>

#include "core/error.hpp"
#include "pipeline/config/cost_estimate.hpp"

namespace silva::app {

namespace {

/// Config keys the page may not set: the view writes only where the command says.
constexpr const char* kCommandOnlyKeys[] = {"output.dir", "captures.poses_file"};

}  // namespace

LoadedConfig load_view_config(const ConfigSources& sources, const ViewEdits& edits) {
  ConfigSources all = sources;
  for (const std::string& o : edits.overrides) {
    const std::string key = o.substr(0, o.find('='));
    for (const char* k : kCommandOnlyKeys)
      if (key == k) throw InputError(std::string(k) + " is set by the command line (--config / --set), not the page");
    all.overrides.push_back(o);
  }
  if (edits.seed) all.seed = edits.seed;
  LoadedConfig loaded = load_config(all);
  resolve_seed(loaded);
  // The guard of generate (a frame's chunks and placement work) and of world (the class map covers the world).
  check_cost(estimate_generate_cost(loaded.config), false, "view", /*can_force=*/false);
  check_cost(estimate_world_cost(loaded.config, std::nullopt), false, "view", /*can_force=*/false);
  return loaded;
}

ViewExplorer::ViewExplorer(ConfigSources sources) : sources_(std::move(sources)) {
  LoadedConfig loaded = load_view_config(sources_, {});
  // Later edits keep the seed on screen unless they change it.
  edits_.seed = std::to_string(loaded.config.seed);
  world_ = std::make_shared<ViewWorld>(std::move(loaded));
  builder_ = std::thread([this] { build_loop(); });
}

ViewExplorer::~ViewExplorer() {
  {
    const std::lock_guard lock(mutex_);
    stopping_ = true;
  }
  wake_.notify_all();
  builder_.join();
}

std::shared_ptr<ViewWorld> ViewExplorer::world() const {
  const std::lock_guard lock(mutex_);
  return world_;
}

void ViewExplorer::edit(const ViewEdits& edits) {
  ViewEdits next = edits;
  if (!next.seed) next.seed = edits_.seed;
  LoadedConfig loaded = load_view_config(sources_, next);
  {
    const std::lock_guard lock(mutex_);
    pending_ = std::move(loaded);
    edits_ = std::move(next);
    error_.clear();
  }
  wake_.notify_all();
}

void ViewExplorer::build_loop() {
  std::unique_lock lock(mutex_);
  for (;;) {
    wake_.wait(lock, [&] { return stopping_ || pending_; });
    if (stopping_) return;
    LoadedConfig loaded = std::move(*pending_);
    pending_.reset();
    const std::optional<ViewPose> warm_at = last_pose_;
    building_ = true;
    lock.unlock();
    std::shared_ptr<ViewWorld> built;
    std::string error;
    try {
      built = std::make_shared<ViewWorld>(std::move(loaded));
      // The first frame generates the chunks around the start, before the world is shown.
      built->render(warm_at.value_or(built->start_pose()), ViewMode::Semantic, 64, 36);
    } catch (const std::exception& e) {
      error = std::string("silva: error: ") + e.what();
    }
    lock.lock();
    building_ = false;
    if (built) {
      world_ = std::move(built);
      ++generation_;
    } else {
      error_ = error;
    }
  }
}

}  // namespace silva::app
