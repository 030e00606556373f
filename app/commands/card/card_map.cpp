#include "app/commands/card/card_map.hpp"

#include <algorithm>
#include <cmath>
#include <set>

#include "pipeline/config/config_checks.hpp"
#include "pipeline/config/run_setup.hpp"
#include "pipeline/schedule/world_schedule.hpp"
#include "core/error.hpp"
#include "io/run_folder.hpp"
#include "app/cli/pipeline_names.hpp"

namespace silva::app {

namespace {

/// The chunks within kMapMargin of some camera, (i, j) order: a corridor along the cameras, so a long trajectory
/// costs its length, not the area of its bounding box.
std::vector<ChunkCoord> chunks_under_cameras(const io::CardCounts& c, double chunk_size) {
  std::set<ChunkCoord> coords;
  for (const Vec3d& p : c.positions)
    for (int i = int(std::floor((p.x() - kMapMargin) / chunk_size)); i < int(std::ceil((p.x() + kMapMargin) / chunk_size)); ++i)
      for (int j = int(std::floor((p.y() - kMapMargin) / chunk_size)); j < int(std::ceil((p.y() + kMapMargin) / chunk_size));
           ++j)
        coords.insert({i, j});
  return {coords.begin(), coords.end()};
}

/// The class map of `schedule`'s world over the chunks under the cameras (at most kMapSize pixels a side).
world::ClassMap render_map(WorldSchedule& schedule, const RunSetup& setup, const io::Dataset& d,
                           const io::CardCounts& c) {
  const double chunk = setup.world.config.terrain.chunk_size;
  std::vector<ChunkCoord> coords = chunks_under_cameras(c, chunk);
  int i0 = coords.front().i, i1 = i0, j0 = coords.front().j, j1 = j0;
  for (const ChunkCoord& k : coords) i0 = std::min(i0, k.i), i1 = std::max(i1, k.i), j0 = std::min(j0, k.j), j1 = std::max(j1, k.j);
  const double span = chunk * std::max(i1 - i0 + 1, j1 - j0 + 1);
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
