// `silva bench`: measure, compare with the previous results, write JSON + markdown + charts.
#include <unistd.h>

#include <fstream>
#include <thread>

#include "pipeline/console/interrupt.hpp"
#include "app/cli/output_check.hpp"
#include "app/commands/bench/bench_command.hpp"
#include "pipeline/config/data_path.hpp"
#include "bench/harness/bench_charts.hpp"
#include "bench/harness/bench_compare.hpp"
#include "bench/harness/bench_programs.hpp"
#include "bench/harness/bench_process.hpp"
#include "bench/harness/bench_report.hpp"
#include "bench/harness/bench_suite.hpp"
#include "core/error.hpp"
#include "core/stopwatch.hpp"
#include "io/atomic_file.hpp"
#include "app/cli/pipeline_names.hpp"

namespace silva::app {

using namespace silva::bench;  // NOLINT(google-build-using-namespace): this command is the harness's front end

namespace fs = std::filesystem;

namespace {

/// Removes a folder when it goes out of scope.
struct ScratchFolder {
  fs::path path;
  ~ScratchFolder() {
    std::error_code ec;
    fs::remove_all(path, ec);
  }
};

/// Reads a JSON file (null when unreadable).
nlohmann::json read_json(const fs::path& path) {
  std::ifstream in(path);
  return nlohmann::json::parse(in, nullptr, /*allow_exceptions=*/false);
}

/// Silva/thesis of a figure, or null.
nlohmann::json ratio_of(const nlohmann::json& results, const std::string& table, const std::string& x) {
  for (const auto& f : results["figures"])
    if (f["table"] == table && (x.empty() || f["x"] == x)) return f["ratio"];
  return nullptr;
}

/// A Google Benchmark program run by `silva bench` (bench_programs.hpp) and where its results go.
struct BenchProgram {
  const char* key;           ///< Key of its results in the JSON (and its markdown section).
  const char* name;          ///< Program in <build>/bench/.
  const char* filter;        ///< --benchmark_filter ("" = every benchmark).
  const char* quick_filter;  ///< --benchmark_filter of `silva bench --quick` (null: `filter`).
};

/// The rasteriser peers (2 threads only under --quick); `silva view`'s frames on 2 threads (moving
/// at 960x540 and 480x270, RGB and semantic) and its first frame; the LiDAR sweep and chunk update
/// on 2 threads.
constexpr BenchProgram kBenchPrograms[] = {
    {"peers", "peers_bench", "", "threads:2"},
    {"view", "view_bench", "BM_ViewFrameMoving/threads:2|BM_ViewFirstFrame", nullptr},
    {"lidar", "lidar_bench", "Lidar.*/2/", nullptr},
};

}  // namespace

int run_bench(const BenchRequest& request, const Reporter& reporter) {
  const int cores = int(std::max(1u, std::thread::hardware_concurrency()));
  const BenchPlan plan = request.quick ? quick_plan(cores) : full_plan(cores);
  const fs::path dir = request.out_dir.empty() ? data_path("bench/results") : request.out_dir;
  check_writable_dir(dir);
  ThesisTables thesis = ThesisTables::load(data_path("bench/thesis-tables.json"));
  const ScratchFolder scratch{fs::temp_directory_path() / ("silva-bench-" + std::to_string(getpid()))};

  install_interrupt_handler();
  begin_writing();  // an interrupted bench still writes what it measured
  reporter.note("silva bench (" + plan.kind + "): results go to " + dir.string() +
                " (Ctrl-C stops early and writes the figures measured so far, marked partial)");
  const auto t0 = SteadyClock::now();
  const BenchContext ctx = make_bench_context(plan, std::move(thesis), scratch.path, reporter, cores);
  nlohmann::json results = run_bench_suite(ctx, seconds_since(t0));
  const bool interrupted = results["interrupted"];
  reporter.note("timing `silva world` of the default world as a whole process (median of " +
                std::to_string(kProcessRuns) + " runs)");
  results["generation_process"] = generation_and_process(
      results, interrupted ? nlohmann::json{{"ran", false}, {"note", "not run: the harness was interrupted"}}
                           : time_whole_process(silva_binary_path(), plan, cores));
  for (const BenchProgram& program : kBenchPrograms) {
    results[program.key] = interrupted ? nlohmann::json{{"ran", false}, {"note", "not run: the harness was interrupted"}}
                                       : run_bench_program(bench_program_path(program.name),
                                                           request.quick && program.quick_filter ? program.quick_filter
                                                                                           : program.filter);
    reporter.note(results[program.key].value("ran", false) ? std::string(program.name) + " ran"
                                                           : results[program.key]["note"].get<std::string>());
  }

  const std::string stem = results["created_utc"].get<std::string>().substr(0, 10) + "-" +
                           results["cpu_slug"].get<std::string>() + "-bench" + (plan.kind == "full" ? "" : "-" + plan.kind) +
                           (interrupted ? "-partial" : "");
  if (interrupted) results["kind"] = plan.kind + "-partial";  // never the baseline of a complete run
  const auto previous = previous_results(dir, results["kind"], results["cpu_slug"]);
  const std::vector<Regression> regressions = previous ? compare_results(read_json(*previous), results)
                                                       : std::vector<Regression>{};
  results["compared_with"] = previous ? previous->filename().string() : "";
  results["regressions"] = nlohmann::json::array();
  for (const Regression& r : regressions)
    results["regressions"].push_back(
        {{"table", r.table}, {"x", r.x}, {"before_s", r.before_s}, {"after_s", r.after_s}, {"change", r.change}});

  std::error_code ec;
  fs::create_directories(dir, ec);
  const fs::path json_path = dir / (stem + ".json"), md_path = dir / (stem + ".md");
  io::write_file_atomic(json_path, results.dump(2) + "\n");
  const ChartRun charts = draw_charts(json_path);
  reporter.note(charts.note);
  io::write_file_atomic(md_path, bench_markdown(results, results["compared_with"], regressions, dir, stem));

  const nlohmann::json summary = {{"ok", true},
                                  {"kind", plan.kind},
                                  {"results_json", json_path.string()},
                                  {"report_md", md_path.string()},
                                  {"charts_drawn", charts.drawn},
                                  {"wall_s", seconds_since(t0)},
                                  {"figures", results["figures"].size()},
                                  {"compared_with", results["compared_with"]},
                                  {"regressions", results["regressions"]},
                                  {"headline_ratios",
                                   {{"generation_default_world", ratio_of(results, "5.1", "5")},
                                    {"capture_set_1920x1080", ratio_of(results, "5.6", "1920x1080")},
                                    {"autopilot", ratio_of(results, "autopilot", "")}}}};
  std::string text = "wrote " + json_path.string() + " and " + md_path.string() + " (" +
                     std::to_string(regressions.size()) + " figure(s) 10 % or more slower than " +
                     (previous ? previous->filename().string() : std::string("nothing: no earlier results")) + ")";
  if (interrupted) throw Interrupted("bench interrupted; the figures measured so far are in " + json_path.string());
  reporter.result(summary, text);
  return 0;
}

}  // namespace silva::app
