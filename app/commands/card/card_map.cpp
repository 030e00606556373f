#include "app/commands/card/card_map.hpp"

#include <algorithm>
#include <cmath>

#include "pipeline/config/config_checks.hpp"
#include "pipeline/config/run_setup.hpp"
#include "pipeline/schedule/world_schedule.hpp"
#include "core/error.hpp"
#include "io/run_folder.hpp"
#include "app/cli/pipeline_names.hpp"

namespace silva::app {

namespace {

/// The chunks within kMapMargin of the cameras' bounding box, (i, j) order.
std::vector<ChunkCoord> chunks_under_cameras(const io::CardCounts& c, double chunk_size) {
  double x0 = 1e300, x1 = -1e300, y0 = 1e300, y1 = -1e300;
  for (const Vec3d& p : c.positions)
    x0 = std::min(x0, p.x()), x1 = std::max(x1, p.x()), y0 = std::min(y0, p.y()), y1 = std::max(y1, p.y());
  std::vector<ChunkCoord> coords;
  for (int i = int(std::floor((x0 - kMapMargin) / chunk_size)); i < int(std::ceil((x1 + kMapMargin) / chunk_size)); ++i)
    for (int j = int(std::floor((y0 - kMapMargin) / chunk_size)); j < int(std::ceil((y1 + kMapMargin) / chunk_size));
         ++j)
      coords.push_back({i, j});
  return coords;
}

/// The class map of `schedule`'s world over the chunks under the cameras.
world::ClassMap render_map(WorldSchedule& schedule, const RunSetup& setup, const io::Dataset& d,
                           const io::CardCounts& c) {
  const double chunk = setup.world.config.terrain.chunk_size;
  std::vector<ChunkCoord> coords = chunks_under_cameras(c, chunk);
  const double span = chunk * std::max(coords.back().i - coords.front().i + 1, coords.back().j - coords.front().j + 1);
  const world::BuiltWorld built = schedule.build(std::move(coords));
  return world::render_class_map(built, chunk, *setup.library, d.ontology, std::max(0.25, span / (kMapSize - 40)));
}

}  // namespace

CameraMap camera_map(const io::Dataset& d, const io::CardCounts& c, const CardInputs& in) {
  if (c.positions.empty()) return {std::nullopt, "the dataset has no frames"};
  if (in.schedule && in.setup) return {render_map(*in.schedule, *in.setup, d, c), ""};
  const std::optional<io::RunMarker> marker = io::read_run_marker(d.dir);
  if (!marker || marker->config.empty()) return {std::nullopt, "the run marker records no config"};
  try {
    LoadedConfig loaded = parse_config_text(marker->config, (d.dir / ".silva-run.json").string());
    loaded.config.seed = d.seed;
    loaded.config.output.dir = std::filesystem::absolute(d.dir).parent_path().string();  // the marker leaves it out
    loaded.seed_given = true;
    check_config(loaded);
    const RunSetup setup = make_run_setup(loaded);
    if (run_identity_hash(loaded, setup) != marker->config_hash)
      return {std::nullopt, "the asset library or pose file differs from the run's, so its world cannot be rebuilt"};
    WorldSchedule schedule(setup.world, chunks_under_cameras(c, setup.world.config.terrain.chunk_size).size());
    return {render_map(schedule, setup, d, c), ""};
  } catch (const InputError& e) {
    return {std::nullopt, std::string("the world could not be rebuilt (") + e.what() + ")"};
  }
}

}  // namespace silva::app
