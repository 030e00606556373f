#include "bench/harness/bench_programs.hpp"

#include <cstdio>
#include <sstream>
#include <string>

#include "bench/harness/bench_charts.hpp"
#include "core/stopwatch.hpp"

namespace silva::bench {

namespace fs = std::filesystem;

namespace {

/// "not built: install <packages> and rebuild" from a program's "built without ... (Debian: <packages>)".
std::string not_built_note(const std::string& error) {
  const std::string marker = "(Debian: ";
  const size_t at = error.find(marker);
  if (at == std::string::npos) return "not built: " + error;
  const size_t end = error.find(')', at);
  const size_t from = at + marker.size();
  const std::string packages = error.substr(from, end == std::string::npos ? end : end - from);
  std::string why = error.substr(0, at);
  while (!why.empty() && (why.back() == ' ' || why.back() == ':')) why.pop_back();
  return "not built: install " + packages + " and rebuild (" + why + ")";
}

/// A program's entries with program_outcome added; times of entries that did not run become null.
nlohmann::json annotate(const nlohmann::json& benchmarks) {
  nlohmann::json out = nlohmann::json::array();
  for (nlohmann::json b : benchmarks) {
    const ProgramOutcome o = program_outcome(b);
    b["status"] = o.status;
    b["note"] = o.note;
    if (o.status != "ran") b["real_time"] = b["cpu_time"] = nullptr;
    out.push_back(std::move(b));
  }
  return out;
}

/// Keys Google Benchmark writes into an entry itself; every other numeric key is a user counter.
bool is_benchmark_field(const std::string& key) {
  static const char* const kFields[] = {"name", "run_name", "run_type", "repetitions", "repetition_index", "threads",
                                        "iterations", "real_time", "cpu_time", "time_unit", "family_index",
                                        "per_family_instance_index", "aggregate_name", "aggregate_unit"};
  for (const char* f : kFields)
    if (key == f) return true;
  return false;
}

/// "name=value, ..." of an entry's user counters (frames_per_s, rays, ...), 4 significant digits.
std::string user_counters(const nlohmann::json& b) {
  std::string out;
  for (const auto& [key, value] : b.items()) {
    if (is_benchmark_field(key) || !value.is_number()) continue;
    char text[64];
    std::snprintf(text, sizeof text, "%s=%.4g", key.c_str(), value.get<double>());
    out += (out.empty() ? "" : ", ") + std::string(text);
  }
  return out;
}

}  // namespace

ProgramOutcome program_outcome(const nlohmann::json& b) {
  if (b.contains("status") && b.contains("note")) return {b["status"], b["note"]};  // already annotated
  const std::string error = b.value("error_message", std::string());
  const bool failed = b.value("error_occurred", false) || !error.empty() || b.value("skipped", false);
  if (failed && error.rfind("built without", 0) == 0) return {"not built", not_built_note(error)};
  if (failed) return {"did not run", "did not run: " + (error.empty() ? std::string("skipped") : error)};
  const auto& t = b.contains("real_time") ? b["real_time"] : nlohmann::json();
  if (!t.is_number() || t.get<double>() <= 0) return {"did not run", "did not run: no time reported"};
  return {"ran", ""};
}

std::string program_markdown(const std::string& title, const nlohmann::json& run) {
  std::ostringstream md;
  md << "\n## " << title << "\n\n";
  if (!run.value("ran", false)) {
    md << run.value("note", std::string("not run")) << "\n";
    return md.str();
  }
  md << "`" << run.value("program", std::string()) << " --benchmark_format=json";
  if (!run.value("filter", std::string()).empty()) md << " --benchmark_filter='" << run["filter"].get<std::string>() << "'";
  md << "`:\n\n| benchmark | real time | unit | counters |\n|---|---|---|---|\n";
  for (const auto& b : run.value("benchmarks", nlohmann::json::array())) {
    const ProgramOutcome o = program_outcome(b);
    md << "| " << b.value("name", std::string()) << " | ";
    if (o.status != "ran") {
      md << o.note << " | — | |\n";
      continue;
    }
    char time[32];
    std::snprintf(time, sizeof time, "%.3f", b["real_time"].get<double>());
    md << time << " | " << b.value("time_unit", std::string()) << " | " << user_counters(b) << " |\n";
  }
  return md.str();
}

fs::path bench_program_path(const std::string& name) {
  std::error_code ec;
  const fs::path self = fs::read_symlink("/proc/self/exe", ec);
  return ec ? fs::path() : self.parent_path() / "bench" / name;
}

nlohmann::json run_bench_program(const fs::path& program, const std::string& filter) {
  std::error_code ec;
  if (program.empty() || !fs::exists(program, ec))
    return {{"ran", false}, {"note", program.filename().string() + " not built (looked for " + program.string() + "); skipped"}};
  const auto t0 = SteadyClock::now();
  std::string out;
  std::string cmd = shell_quote(program.string()) + " --benchmark_format=json";
  if (!filter.empty()) cmd += " --benchmark_filter=" + shell_quote(filter);
  cmd += " 2>/dev/null";
  int status = -1;
  if (FILE* p = popen(cmd.c_str(), "r")) {
    char buf[4096];
    for (size_t n; (n = std::fread(buf, 1, sizeof buf, p)) > 0;) out.append(buf, n);
    status = pclose(p);
  }
  const nlohmann::json doc = nlohmann::json::parse(out, nullptr, /*allow_exceptions=*/false);
  if (status != 0 || !doc.is_object() || !doc.contains("benchmarks"))
    return {{"ran", false}, {"note", program.string() + " failed (exit status " + std::to_string(status) + ")"}};
  return {{"ran", true},
          {"program", program.string()},
          {"filter", filter},
          {"wall_s", seconds_since(t0)},
          {"benchmarks", annotate(doc["benchmarks"])}};
}

}  // namespace silva::bench
