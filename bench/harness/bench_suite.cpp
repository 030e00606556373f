#include "bench/harness/bench_suite.hpp"

#include <ctime>

#include "pipeline/console/interrupt.hpp"
#include "bench/harness/bench_capture.hpp"
#include "bench/harness/bench_generation.hpp"
#include "bench/harness/bench_machine.hpp"
#include "core/stopwatch.hpp"
#include "bench/harness/pipeline_names.hpp"

namespace silva::bench {

std::string utc_now() {
  const std::time_t now = std::time(nullptr);
  std::tm tm{};
  gmtime_r(&now, &tm);
  char buf[32];
  std::strftime(buf, sizeof buf, "%Y-%m-%dT%H:%M:%SZ", &tm);
  return buf;
}

nlohmann::json run_bench_suite(const BenchContext& ctx, double setup_s) {
  const auto t0 = SteadyClock::now();
  nlohmann::json doc = {{"harness", "silva-bench"}, {"kind", ctx.plan.kind}, {"created_utc", utc_now()}};
  doc["machine"] = machine_description();
  doc["cpu_slug"] = cpu_slug(doc["machine"]["cpu"]);
  doc["thesis_machine"] = ctx.thesis.machine();
  doc["seed"] = kBenchSeed;
  doc["plan"] = {{"overrides", ctx.plan.overrides},       {"generation_repeats", ctx.plan.generation_repeats},
                 {"frames_per_point", ctx.plan.frames_per_point}, {"captures_max", ctx.plan.captures_max},
                 {"autopilot_frames", ctx.plan.autopilot_frames}, {"scaling_frames", ctx.plan.scaling_frames},
                 {"threads", ctx.plan.threads}};
  doc["setup_s"] = setup_s;
  std::vector<Figure> figures;
  bool interrupted = false;
  try {
    for (auto* part : {&bench_generation, &bench_capture, &bench_generation_threads, &bench_autopilot_and_scaling})
      (*part)(ctx, figures);
  } catch (const Interrupted&) {
    interrupted = true;
  }
  doc["interrupted"] = interrupted;
  doc["tables"] = nlohmann::json::object();
  doc["figures"] = nlohmann::json::array();
  for (const Figure& f : figures) {
    if (!ctx.thesis.title(f.table).empty()) doc["tables"][f.table] = ctx.thesis.title(f.table);
    doc["figures"].push_back(figure_json(f));
  }
  doc["wall_s"] = seconds_since(t0) + setup_s;
  doc["load_average_end"] = load_average();
  return doc;
}

}  // namespace silva::bench
