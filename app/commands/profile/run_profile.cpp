// `silva profile placement`: sweep density (and elevation, trail) over seeds; JSON, CSV, heatmaps, charts.
#include <chrono>
#include <cstdio>

#include "app/cli/output_check.hpp"
#include "app/commands/profile/profile_command.hpp"
#include "pipeline/config/run_setup.hpp"
#include "bench/harness/bench_charts.hpp"
#include "bench/harness/bench_suite.hpp"
#include "bench/harness/profile_output.hpp"
#include "io/atomic_file.hpp"
#include "world/chunk_regions.hpp"
#include "app/cli/pipeline_names.hpp"

namespace silva::app {

using namespace silva::bench;  // NOLINT(google-build-using-namespace): this command is the harness's front end

namespace fs = std::filesystem;

namespace {

/// The text summary: per setting, what one gets (objects/ha, canopy, dropped) and what it costs.
std::string summary_text(const nlohmann::json& means, const fs::path& dir) {
  std::string text = "density  elev  trail  things/ha  trees/ha  canopy%  dropped%  ms/chunk gen+place+resolve  build s\n";
  char line[256];
  for (const auto& m : means) {
    double things = 0, trees = 0, cand = 0, dropped = 0;
    for (const auto& [name, c] : m["classes"].items()) {
      if (name != "ground_vegetation") things += c["per_ha"].get<double>();
      if (name == "tree_trunk") trees = c["per_ha"];
      cand += c["candidates"].get<double>();
      dropped += c["dropped"].get<double>();
    }
    const auto& w = m["world"];
    std::snprintf(line, sizeof line, "%7g  %4g  %5s  %9.1f  %8.1f  %7.1f  %8.2f  %6.2f + %5.2f + %6.2f = %6.2f  %7.2f\n",
                  m["density"].get<double>(), m["max_elevation"].get<double>(), m["trail"].get<bool>() ? "on" : "off",
                  things, trees, w["canopy_cover_pct"].get<double>(), cand > 0 ? 100 * dropped / cand : 0.0,
                  w["generate_ms_per_chunk"].get<double>(), w["place_ms_per_chunk"].get<double>(),
                  w["resolve_ms_per_chunk"].get<double>(),
                  w["generate_ms_per_chunk"].get<double>() + w["place_ms_per_chunk"].get<double>() +
                      w["resolve_ms_per_chunk"].get<double>(),
                  w["build_s"].get<double>());
    text += line;
  }
  return text + "files in " + dir.string();
}

}  // namespace

int run_profile_placement(const ProfilePlacementRequest& request, const Reporter& reporter) {
  check_writable_dir(request.out_dir);
  const RunSetup setup = make_run_setup(request.config);
  const Config& base = request.config.config;
  const std::vector<ChunkCoord> coords = request.radius
                                             ? world::chunks_in_disc(0, 0, *request.radius, base.terrain.chunk_size)
                                             : world::default_world_chunks(base);
  std::vector<ProfileSample> samples;
  for (double elevation : request.elevations)
    for (bool trail : request.trails)
      for (double density : request.densities)
        for (int k = 0; k < request.seeds; ++k) {
          Config cfg = base;
          cfg.vegetation.density = density;
          cfg.terrain.max_elevation = elevation;
          cfg.trail.enabled = trail;
          cfg.seed = base.seed + k;
          const world::WorldContext ctx = world::make_world_context(cfg, *setup.library);
          samples.push_back({density, elevation, trail, cfg.seed, profile_world(ctx, coords, request.threads)});
          char line[160];
          std::snprintf(line, sizeof line, "density %g, elevation %g m, trail %s, seed %lld: %llu objects in %.2f s",
                        density, elevation, trail ? "on" : "off", static_cast<long long>(cfg.seed),
                        static_cast<unsigned long long>(samples.back().world.objects), samples.back().world.build_s);
          reporter.note(line);
        }

  const fs::path& dir = request.out_dir;
  std::error_code ec;
  fs::create_directories(dir, ec);
  // One heatmap per density: the first world of that density, on one colour scale for all.
  double max_per_ha = 0;
  for (const ProfileSample& s : samples)
    for (size_t c = 0; c < s.world.heat.size(); ++c)
      max_per_ha = std::max(max_per_ha, s.world.heat[c] / (kHeatCell * kHeatCell / 1e4));
  nlohmann::json heatmaps = nlohmann::json::array();
  for (double density : request.densities) {
    for (const ProfileSample& s : samples) {
      if (s.density != density) continue;
      char name[64];
      std::snprintf(name, sizeof name, "heatmap-density-%g.png", density);
      io::write_file_atomic(dir / name, heatmap_png(s.world, max_per_ha, 3));
      heatmaps.push_back({{"file", name}, {"density", density}, {"seed", s.seed}, {"max_elevation", s.max_elevation},
                          {"trail", s.trail}});
      break;
    }
  }
  nlohmann::json doc = {{"harness", "silva-profile-placement"},
                        {"created_utc", utc_now()},
                        {"threads", request.threads},
                        {"region", request.radius ? "disc of radius " + std::to_string(*request.radius) + " m around the origin"
                                                  : std::string("the default world")},
                        {"chunks", coords.size()},
                        {"heatmap", {{"cell_m", kHeatCell}, {"scale_max_things_per_ha", max_per_ha}, {"files", heatmaps}}},
                        {"cover_cell_m", kCoverCell},
                        {"means", sweep_means(samples, setup.ontology)},
                        {"samples", nlohmann::json::array()}};
  for (const ProfileSample& s : samples) doc["samples"].push_back(sample_json(s, setup.ontology));
  io::write_file_atomic(dir / "placement.json", doc.dump(2) + "\n");
  io::write_file_atomic(dir / "placement.csv", samples_csv(samples, setup.ontology));
  const ChartRun charts = draw_charts(dir / "placement.json");
  reporter.note(charts.note);
  nlohmann::json summary = doc;
  summary.erase("samples");
  summary["ok"] = true;
  summary["out_dir"] = dir.string();
  summary["charts_drawn"] = charts.drawn;
  reporter.result(summary, summary_text(doc["means"], dir));
  return 0;
}

}  // namespace silva::app
