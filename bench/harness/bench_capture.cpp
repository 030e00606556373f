#include "bench/harness/bench_capture.hpp"

#include <tbb/task_arena.h>

#include <chrono>
#include <filesystem>

#include "pipeline/console/interrupt.hpp"
#include "pipeline/schedule/world_schedule.hpp"
#include "world/chunk_cache.hpp"
#include "world/plan_captures.hpp"
#include "bench/harness/pipeline_names.hpp"

namespace silva::bench {

namespace fs = std::filesystem;

namespace {

/// A measured capture run.
struct CaptureRun {
  systems::CaptureStats stats;
  std::vector<double> done_at_s;  ///< Seconds from the start to each completed frame.
  int width = 0, height = 0;
};

/// Captures `frames` of `w` with `types` on `threads` threads into a scratch folder, then deletes it.
CaptureRun capture(const BenchContext& ctx, WarmWorld& w, std::vector<world::PlannedFrame> frames,
                   const std::vector<std::string>& types, int threads) {
  stop_if_interrupted();
  static int run_number = 0;
  const systems::CaptureSettings settings{ctx.setup.lighting, ctx.setup.ontology, io::OutputSelection::from_names(types),
                                          ctx.scratch / ("run-" + std::to_string(++run_number)), {}};
  CaptureRun run;
  run.width = frames.empty() ? 0 : frames.front().camera.width;  // frames may be planned at another size
  run.height = frames.empty() ? 0 : frames.front().camera.height;
  const SteadyClock::time_point t0 = SteadyClock::now();
  tbb::task_arena arena(threads);
  arena.execute([&] {
    run.stats = w.schedule->capture(
        frames, settings, [&](int, int) { run.done_at_s.push_back(seconds_since(t0)); },
        [] { return interrupt_requested(); });
  });
  std::error_code ec;
  fs::remove_all(settings.run_dir, ec);
  if (run.stats.stopped) throw Interrupted("bench interrupted");
  return run;
}

/// `count` random frames planned at `width` x `height` in `w` (planning is not timed).
std::vector<world::PlannedFrame> random_frames(WarmWorld& w, int count, int width, int height) {
  world::WorldContext sized = w.world;
  sized.config.captures.random_count = count;
  sized.config.output.width = width;
  sized.config.output.height = height;
  return world::plan_random(sized, w.schedule->ecs().resource<world::ChunkCache>());
}

/// About `count` autopilot frames: whole points (every yaw of each, as the autopilot captures them, sharing
/// their sun maps) spread evenly over the trail, at least one (all of them when count is 0 or not smaller);
/// and the number of frames of the whole autopilot.
std::pair<std::vector<world::PlannedFrame>, size_t> autopilot_frames(const WarmWorld& w, int count) {
  std::vector<world::PlannedFrame> all = world::plan_autopilot(w.world);
  const size_t n = all.size();
  if (count <= 0 || size_t(count) >= n) return {std::move(all), n};
  const size_t yaws = std::max<size_t>(1, w.world.config.captures.autopilot_yaws.size());
  const size_t points = n / yaws, chosen = std::max<size_t>(1, size_t(count) / yaws);
  std::vector<world::PlannedFrame> subset;
  subset.reserve(chosen * yaws);
  for (size_t k = 0; k < chosen; ++k)
    for (size_t y = 0; y < yaws; ++y) subset.push_back(all[(k * points / chosen) * yaws + y]);
  return {std::move(subset), n};
}

/// A figure of `run`: seconds per set (or the whole run when `per_set` is false), work counts, phases.
Figure capture_figure(const BenchContext& ctx, const std::string& table, const std::string& x, const CaptureRun& run,
                      bool per_set, const WarmWorld& w) {
  const double frames = std::max(1, run.stats.frames_written);
  const double scale = per_set ? 1.0 / frames : 1.0;
  Figure f;
  f.table = table;
  f.x = x;
  f.silva_s = run.stats.wall_s * scale;
  f.thesis_s = ctx.thesis.seconds(table, x);
  f.work.objects = w.objects;
  f.work.chunks = w.schedule->ecs().resource<world::ChunkCache>().size();
  f.work.triangles = run.stats.triangles_submitted;
  f.work.frames = uint64_t(run.stats.frames_written);
  f.work.pixels = f.work.frames * uint64_t(run.width) * uint64_t(run.height);
  f.work.bytes = run.stats.bytes_written;
  const systems::CaptureStats& s = run.stats;
  f.breakdown = {{"per_set", per_set},          {"wall_s", s.wall_s},       {"stream_s", s.stream_s},
                 {"prepare_s", s.prepare_s},    {"render_s", s.render_s},   {"shadow_s", s.shadow_s},
                 {"shade_s", s.shade_s},        {"encode_s", s.encode_s},   {"write_s", s.write_s},
                 {"chunks_generated", s.chunks_generated}, {"triangles_rasterised", s.triangles_rasterised},
                 {"world_build_s", w.build_s}};
  return f;
}

/// Parses "WxH".
std::pair<int, int> resolution(const std::string& x) {
  const size_t cut = x.find('x');
  return {std::stoi(x.substr(0, cut)), std::stoi(x.substr(cut + 1))};
}

/// Notes a figure on stderr.
void note(const BenchContext& ctx, const Figure& f) {
  ctx.reporter->note("capture " + f.table + " x=" + f.x + ": " + std::to_string(f.silva_s) + " s" +
                     (f.extrapolated ? " (extrapolated)" : ""));
}

/// Table 5.5: seconds per thesis set at each density.
void capture_vs_density(const BenchContext& ctx, WarmWorld& base, std::vector<Figure>& out) {
  const Config& c = base.world.config;
  for (const std::string& x : ctx.thesis.xs("5.5")) {
    std::unique_ptr<WarmWorld> owned;
    WarmWorld* w = &base;
    if (std::stod(x) != c.vegetation.density) {
      owned = warm_world(ctx, bench_variant(ctx, {"vegetation.density=" + x}));
      w = owned.get();
    }
    const CaptureRun run = capture(ctx, *w, random_frames(*w, ctx.plan.frames_per_point, c.output.width, c.output.height),
                                   kThesisSet, ctx.cores);
    out.push_back(capture_figure(ctx, "5.5", x, run, true, *w));
    note(ctx, out.back());
  }
}

/// Table 5.6: seconds per thesis set at each resolution.
void capture_vs_resolution(const BenchContext& ctx, WarmWorld& w, std::vector<Figure>& out) {
  for (const std::string& x : ctx.thesis.xs("5.6")) {
    const auto [width, height] = resolution(x);
    const CaptureRun run =
        capture(ctx, w, random_frames(w, ctx.plan.frames_per_point, width, height), kThesisSet, ctx.cores);
    out.push_back(capture_figure(ctx, "5.6", x, run, true, w));
    note(ctx, out.back());
  }
}

/// Table 5.7: time to the n-th completed set of one run of plan.captures_max random sets; larger n
/// are scaled from the whole run (marked extrapolated).
void capture_vs_count(const BenchContext& ctx, WarmWorld& w, std::vector<Figure>& out) {
  const Config& c = w.world.config;
  const CaptureRun run = capture(ctx, w, random_frames(w, ctx.plan.captures_max, c.output.width, c.output.height),
                                 kThesisSet, ctx.cores);
  const int measured = run.stats.frames_written;
  for (const std::string& x : ctx.thesis.xs("5.7")) {
    const int n = std::stoi(x);
    Figure f = capture_figure(ctx, "5.7", x, run, false, w);
    if (n <= measured) {
      f.silva_s = run.done_at_s[size_t(n - 1)];
      f.note = "time to the " + x + "th completed set of a " + std::to_string(measured) +
               "-set run (triangles: the whole run)";
      f.work.frames = uint64_t(n);
      f.work.pixels = f.work.frames * uint64_t(run.width) * uint64_t(run.height);
    } else {
      f.silva_s = run.stats.wall_s * n / measured;
      f.extrapolated = true;
      f.note = "scaled from a " + std::to_string(measured) + "-set run (" + std::to_string(run.stats.wall_s) + " s)";
    }
    out.push_back(f);
    note(ctx, out.back());
  }
}

/// Tables 5.8 and 5.9: one output type per run, then the marginal cost of the second type of a pair.
void capture_per_type(const BenchContext& ctx, WarmWorld& w, std::vector<Figure>& out) {
  const Config& c = w.world.config;
  const std::vector<world::PlannedFrame> frames = random_frames(w, ctx.plan.frames_per_point, c.output.width, c.output.height);
  std::map<std::string, Figure> alone;
  for (const std::string& x : ctx.thesis.xs("5.8")) {
    alone[x] = capture_figure(ctx, "5.8", x, capture(ctx, w, frames, {x}, ctx.cores), true, w);
    out.push_back(alone[x]);
    note(ctx, out.back());
  }
  for (const std::string& x : ctx.thesis.xs("5.9")) {
    const size_t cut = x.find("_to_");
    const std::string from = x.substr(0, cut), to = x.substr(cut + 4);
    const std::string a = from == "rgb" ? to : from;  // the pair is {rgb, a}
    Figure f = capture_figure(ctx, "5.9", x, capture(ctx, w, frames, {"rgb", a}, ctx.cores), true, w);
    const double pair_s = f.silva_s;
    f.silva_s = pair_s - alone.at(from).silva_s;
    f.breakdown["pair_per_set_s"] = pair_s;
    f.breakdown["first_alone_per_set_s"] = alone.at(from).silva_s;
    f.note = "no switch in Silva (one pass renders every type): per-set cost of adding " + to + " to " + from +
             " (negative = within noise)";
    out.push_back(f);
    note(ctx, out.back());
  }
}

}  // namespace

void bench_capture(const BenchContext& ctx, std::vector<Figure>& out) {
  std::unique_ptr<WarmWorld> w = warm_world(ctx, ctx.base.config);
  ctx.reporter->note("capture world generated in " + std::to_string(w->build_s) + " s (not part of capture figures)");
  capture_vs_density(ctx, *w, out);
  capture_vs_resolution(ctx, *w, out);
  capture_vs_count(ctx, *w, out);
  capture_per_type(ctx, *w, out);
}

void bench_autopilot_and_scaling(const BenchContext& ctx, std::vector<Figure>& out) {
  std::unique_ptr<WarmWorld> w = warm_world(ctx, ctx.base.config);
  const auto [subset, total] = autopilot_frames(*w, ctx.plan.scaling_frames);
  CaptureRun widest;
  for (int t : ctx.plan.threads) {
    widest = capture(ctx, *w, subset, kThesisSet, t);
    out.push_back(capture_figure(ctx, "threads-capture", std::to_string(t), widest, false, *w));
    out.back().note = std::to_string(subset.size()) + " autopilot sets";
    note(ctx, out.back());
  }
  Figure ap;
  const std::string x = std::to_string(total);
  if (ctx.plan.autopilot_frames > 0 && size_t(ctx.plan.autopilot_frames) < total) {
    // The subset of the widest scaling run stands for the whole autopilot, scaled by frame count.
    ap = capture_figure(ctx, "autopilot", x, widest, false, *w);
    ap.silva_s = widest.stats.wall_s * double(total) / std::max(1, widest.stats.frames_written);
    ap.extrapolated = true;
    ap.note = "scaled from " + std::to_string(widest.stats.frames_written) + " of " + x + " sets (" +
              std::to_string(widest.stats.wall_s) + " s)";
  } else {
    ap = capture_figure(ctx, "autopilot", x, capture(ctx, *w, autopilot_frames(*w, 0).first, kThesisSet, ctx.cores),
                        false, *w);
    ap.note = "every autopilot set captured";
  }
  ap.thesis_s = ctx.thesis.autopilot_estimate_s();
  out.push_back(ap);
  note(ctx, out.back());
}

}  // namespace silva::bench
