#include "bench/harness/bench_process.hpp"

#include <fcntl.h>
#include <spawn.h>
#include <sys/resource.h>
#include <sys/wait.h>

#include <algorithm>
#include <cstdio>
#include <variant>

#include "bench/harness/bench_charts.hpp"
#include "bench/harness/bench_context.hpp"
#include "core/stopwatch.hpp"

extern char** environ;

namespace silva::bench {

namespace fs = std::filesystem;

namespace {

/// One finished run of the whole process.
struct ProcessRun {
  double wall_s = 0;       ///< Spawn to exit, seconds.
  double cpu_s = 0;        ///< User + system CPU seconds of the child.
};

/// Seconds of a timeval.
double seconds_of(const timeval& t) { return double(t.tv_sec) + 1e-6 * double(t.tv_usec); }

/// Runs `argv` with stdout and stderr on /dev/null; its times, or an error text when it failed.
std::variant<ProcessRun, std::string> run_once(const std::vector<std::string>& argv) {
  std::vector<char*> args;
  args.reserve(argv.size() + 1);
  for (const std::string& a : argv) args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 1, "/dev/null", O_WRONLY, 0);
  posix_spawn_file_actions_addopen(&actions, 2, "/dev/null", O_WRONLY, 0);
  const Stopwatch clock;
  pid_t pid = -1;
  const int err = posix_spawn(&pid, args[0], &actions, nullptr, args.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (err != 0) return "cannot start " + argv[0] + " (errno " + std::to_string(err) + ")";
  int status = 0;
  rusage usage{};
  if (wait4(pid, &status, 0, &usage) != pid) return "lost the child process of " + argv[0];
  // No peak memory: ru_maxrss of a spawned child includes the harness's own peak, kept across exec.
  ProcessRun run{clock.seconds(), seconds_of(usage.ru_utime) + seconds_of(usage.ru_stime)};
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0)
    return argv[0] + " world failed (wait status " + std::to_string(status) + ")";
  return run;
}

/// `v` seconds with two decimals, or "—" when null.
std::string secs_or_dash(const nlohmann::json& v) {
  if (!v.is_number()) return "—";
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.2f", v.get<double>());
  return buf;
}

/// The figure of `table` at `x`, or null.
const nlohmann::json* find_figure(const nlohmann::json& results, const std::string& table, const std::string& x) {
  if (!results.is_object() || !results.contains("figures")) return nullptr;
  for (const auto& f : results["figures"])
    if (f.value("table", "") == table && f.value("x", "") == x) return &f;
  return nullptr;
}

}  // namespace

fs::path silva_binary_path() {
  std::error_code ec;
  const fs::path self = fs::read_symlink("/proc/self/exe", ec);
  return !ec && self.filename() == "silva" ? self : fs::path();
}

std::vector<std::string> whole_process_args(const BenchPlan& plan, int threads) {
  std::vector<std::string> args = {"world", "--seed", std::to_string(kBenchSeed), "--threads", std::to_string(threads),
                                   "--json", "--quiet"};
  for (const std::string& o : plan.overrides) args.insert(args.end(), {"--set", o});
  return args;
}

nlohmann::json time_whole_process(const fs::path& silva, const BenchPlan& plan, int threads, int runs) {
  if (silva.empty()) return {{"ran", false}, {"note", "not run: the harness is not running as the silva binary"}};
  std::vector<std::string> argv = {silva.string()};
  for (const std::string& a : whole_process_args(plan, threads)) argv.push_back(a);
  std::string command;
  for (const std::string& a : argv) {
    if (!command.empty()) command += ' ';
    command += shell_quote(a);
  }
  std::vector<ProcessRun> done;
  for (int r = 0; r < std::max(1, runs); ++r) {
    auto run = run_once(argv);
    if (auto* error = std::get_if<std::string>(&run)) return {{"ran", false}, {"command", command}, {"note", *error}};
    done.push_back(std::get<ProcessRun>(run));
  }
  std::sort(done.begin(), done.end(), [](const ProcessRun& a, const ProcessRun& b) { return a.wall_s < b.wall_s; });
  const ProcessRun& median = done[done.size() / 2];
  return {{"ran", true},          {"command", command},          {"runs", done.size()},
          {"wall_s", median.wall_s}, {"min_s", done.front().wall_s}, {"max_s", done.back().wall_s},
          {"cpu_s", median.cpu_s}};
}

nlohmann::json generation_and_process(const nlohmann::json& results, const nlohmann::json& process) {
  const nlohmann::json* build = find_figure(results, "5.1", "5");
  const bool ran = process.value("ran", false);
  nlohmann::json out = {{"build_s", build ? (*build)["silva_s"] : nlohmann::json(nullptr)},
                        {"process_wall_s", ran ? process["wall_s"] : nlohmann::json(nullptr)},
                        {"difference_s", nullptr},
                        {"process", process}};
  if (build && ran) out["difference_s"] = process["wall_s"].get<double>() - (*build)["silva_s"].get<double>();
  out["explanation"] =
      "build_s is the harness's default-world figure (Table 5.1 at 5 %): world context and build, the asset "
      "library already loaded; process_wall_s is `silva world` of the same world as a child process (median "
      "of its runs), and adds process start, config, ontology and asset library loading, and exit.";
  return out;
}

std::string generation_process_markdown(const nlohmann::json& g) {
  if (!g.is_object() || !g.contains("build_s") || !g.contains("difference_s")) return "";
  const nlohmann::json process = g.value("process", nlohmann::json::object());
  std::string md = "\n## Generation: the build and the whole process\n\n";
  md += "| default world | seconds |\n|---|---|\n";
  md += "| build in the harness (Table 5.1 at 5 %: world context + build) | " + secs_or_dash(g["build_s"]) + " |\n";
  md += "| `silva world` as a whole process (median of " + std::to_string(process.value("runs", 0)) + ") | ";
  md += process.value("ran", false) ? secs_or_dash(g.value("process_wall_s", nlohmann::json())) + " |\n"
                                     : process.value("note", std::string("not run")) + " |\n";
  md += "\n";
  const std::string around = "process start, loading the config, ontology and asset library, and exit (freeing "
                             "the world); both include the world context and the build.";
  if (!g["difference_s"].is_number()) {
    md += "Only one of the two figures was measured, so there is no difference to report.\n";
    return md;
  }
  const double diff = g["difference_s"].get<double>();
  if (diff >= 0) {
    md += "The whole process takes " + secs_or_dash(diff) + " s more than the build: " + around;
  } else {
    md += "The whole process took " + secs_or_dash(-diff) +
          " s less than the build figure: the two were measured at different moments on a busy machine (see the "
          "load average), so rerun on an idle one. What the process adds is " + around;
  }
  const std::string cpu = secs_or_dash(process.value("cpu_s", nlohmann::json()));
  md += " Command: `" + process.value("command", std::string()) + "` (" + cpu +
        " CPU-s in the median run).\n";
  return md;
}

}  // namespace silva::bench
