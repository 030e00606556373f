// `silva world` after the CLI checks.

#include "app/commands/world/world_command.hpp"
#include "pipeline/config/run_setup.hpp"
#include "core/stopwatch.hpp"
#include "io/atomic_file.hpp"
#include "io/gltf_writer.hpp"
#include "io/png_writer.hpp"
#include "io/ontology_file.hpp"
#include "world/chunk_regions.hpp"
#include "world/class_map.hpp"
#include "app/commands/world/world_export.hpp"
#include "pipeline/schedule/world_schedule.hpp"
#include "app/cli/pipeline_names.hpp"

namespace silva::app {

namespace {
/// Ground sample distance of `--map`, metres per pixel.
constexpr double kMapMetresPerPixel = 0.5;

/// The world's totals as the JSON `--stats` and `--json` print (CONTRACT.md / README).
nlohmann::json totals_json(const world::BuiltWorld& w, const Ontology& ontology) {
  const world::WorldTotals& t = w.totals;
  nlohmann::json per_class = nlohmann::json::object();
  for (int r = 0; r < kRoleCount; ++r)
    if (t.objects_by_role[r]) per_class[ontology.classes[r].name] = t.objects_by_role[r];
  char hash[17];
  std::snprintf(hash, sizeof hash, "%016llx", static_cast<unsigned long long>(w.hash));
  return {{"chunks", t.chunks},
          {"triangles", t.triangles},
          {"objects", t.objects},
          {"objects_per_class", per_class},
          {"distinct_assets", t.distinct_assets},
          {"candidates", t.candidates},
          {"trail_rejected", t.trail_rejected},
          {"adjusted", t.adjusted},
          {"dropped", t.dropped},
          {"ground_dropped", t.ground_dropped},
          {"fcl_broad_queries", t.broad_queries},
          {"fcl_narrow_queries", t.narrow_queries},
          {"world_hash", hash},
          {"timings_s", {{"place", t.place_s}, {"chunks", t.chunks_s}, {"total", t.total_s}}}};
}
}  // namespace

int run_world(const WorldRequest& request, const Reporter& reporter) {
  const RunSetup setup = make_run_setup(request.config);
  const Config& cfg = request.config.config;
  const std::vector<ChunkCoord> coords =
      request.region ? world::chunks_in_disc(request.region->x, request.region->y, request.region->radius,
                                             cfg.terrain.chunk_size)
                     : world::default_world_chunks(cfg);
  reporter.note("building " + std::to_string(coords.size()) + " chunks (seed " + std::to_string(cfg.seed) + ")");
  const world::BuiltWorld w = build_world(setup.world, coords, request.threads);
  nlohmann::json summary = totals_json(w, setup.ontology);
  summary["seed"] = cfg.seed;
  summary["threads"] = request.threads;
  if (!request.export_path.empty()) {
    const Stopwatch clock;
    io::write_glb(world_document(w, *setup.library, setup.ontology, request.instancing), request.export_path);
    summary["export"] = {{"file", request.export_path.string()},
                         {"seconds", clock.seconds()}};
  }
  if (!request.map_path.empty()) {
    const world::ClassMap map =
        world::render_class_map(w, cfg.terrain.chunk_size, *setup.library, setup.ontology, kMapMetresPerPixel);
    io::write_file_atomic(request.map_path, io::encode_png_rgb8(map.rgb, map.width, map.height));
    summary["map"] = {{"file", request.map_path.string()},
                      {"width", map.width},
                      {"height", map.height},
                      {"metres_per_pixel", kMapMetresPerPixel}};
  }
  std::string text = "built " + std::to_string(w.totals.chunks) + " chunks, " + std::to_string(w.totals.objects) +
                     " objects in " + std::to_string(w.totals.total_s) + " s";
  if (request.stats) text = summary.dump(2);
  if (!request.export_path.empty()) text += "\nexported " + request.export_path.string();
  if (!request.map_path.empty()) text += "\nwrote class map " + request.map_path.string();
  reporter.result(summary, text);
  return 0;
}

}  // namespace silva::app
