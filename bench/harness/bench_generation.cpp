#include "bench/harness/bench_generation.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>

#include "pipeline/schedule/world_schedule.hpp"
#include "bench/harness/pipeline_names.hpp"

namespace silva::bench {

namespace {

/// One generation point: a table, its x, and the --set assignments that produce it.
struct GenerationPoint {
  std::string table;
  std::string x;
  std::vector<std::string> sets;
};

/// Every thesis generation point, in the thesis's order.
std::vector<GenerationPoint> generation_points(const ThesisTables& thesis) {
  std::vector<GenerationPoint> points;
  for (const std::string& x : thesis.xs("5.1")) points.push_back({"5.1", x, {"vegetation.density=" + x}});
  for (const std::string& x : thesis.xs("5.2")) {
    char metres[32];
    std::snprintf(metres, sizeof metres, "%.2f", std::stod(x) / 100.0);  // the thesis gives centimetres
    points.push_back({"5.2", x, {std::string("terrain.max_elevation=") + metres}});
  }
  for (const std::string& x : thesis.xs("5.3")) points.push_back({"5.3", x, {"lighting.time_of_day=" + x}});
  for (const std::string& x : thesis.xs("5.4")) points.push_back({"5.4", x, {"trail.enabled=" + x}});
  for (const std::string& x : thesis.xs("5.4b")) points.push_back({"5.4b", x, {"vegetation.ground=" + x}});
  return points;
}

/// A timed build of the default world of `cfg` on `threads` threads (context included).
struct TimedBuild {
  double seconds = 0;
  double context_s = 0;
  world::WorldTotals totals;
  uint64_t hash = 0;
};

TimedBuild timed_build(const BenchContext& ctx, const Config& cfg, int threads) {
  const SteadyClock::time_point t0 = SteadyClock::now();
  const world::WorldContext wc = world::make_world_context(cfg, *ctx.setup.library);
  const double context_s = seconds_since(t0);
  const world::BuiltWorld w = build_default_world(wc, threads);
  return {seconds_since(t0), context_s, w.totals, w.hash};
}

/// The median-time build of `repeats` builds (all builds are identical in content).
Figure measure_point(const BenchContext& ctx, const std::string& table, const std::string& x, const Config& cfg,
                     int threads) {
  std::vector<TimedBuild> builds;
  for (int r = 0; r < std::max(1, ctx.plan.generation_repeats); ++r) builds.push_back(timed_build(ctx, cfg, threads));
  std::sort(builds.begin(), builds.end(), [](const TimedBuild& a, const TimedBuild& b) { return a.seconds < b.seconds; });
  const TimedBuild& b = builds[builds.size() / 2];
  Figure f;
  f.table = table;
  f.x = x;
  f.silva_s = b.seconds;
  f.thesis_s = ctx.thesis.seconds(table, x);
  f.work.objects = b.totals.objects;
  f.work.chunks = b.totals.chunks;
  f.work.triangles = b.totals.triangles;
  char hash[17];
  std::snprintf(hash, sizeof hash, "%016llx", static_cast<unsigned long long>(b.hash));
  f.breakdown = {{"context_s", b.context_s},   {"place_s", b.totals.place_s},
                 {"chunks_s", b.totals.chunks_s}, {"threads", threads},
                 {"repeats", builds.size()},    {"min_s", builds.front().seconds},
                 {"max_s", builds.back().seconds}, {"world_hash", hash}};
  return f;
}

}  // namespace

void bench_generation(const BenchContext& ctx, std::vector<Figure>& out) {
  for (const GenerationPoint& p : generation_points(ctx.thesis)) {
    stop_if_interrupted();
    out.push_back(measure_point(ctx, p.table, p.x, bench_variant(ctx, p.sets), ctx.cores));
    if (p.table == "5.3") out.back().note = "the world does not depend on the time of day (lighting is applied at capture)";
    ctx.reporter->note("generation " + p.table + " x=" + p.x + ": " + std::to_string(out.back().silva_s) + " s");
  }
}

void bench_generation_threads(const BenchContext& ctx, std::vector<Figure>& out) {
  for (int t : ctx.plan.threads) {
    stop_if_interrupted();
    out.push_back(measure_point(ctx, "threads-generation", std::to_string(t), ctx.base.config, t));
    ctx.reporter->note("generation on " + std::to_string(t) + " threads: " + std::to_string(out.back().silva_s) + " s");
  }
}

}  // namespace silva::bench
