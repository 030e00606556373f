#include "bench/harness/bench_peers.hpp"

#include <cstdio>
#include <sstream>
#include <string>

#include "bench/harness/bench_charts.hpp"
#include "core/stopwatch.hpp"

namespace silva::app {

namespace fs = std::filesystem;

namespace {

/// "not built: install <packages> and rebuild" from peers_bench's "built without ... (Debian: <packages>)".
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

/// peers_bench's entries with peer_outcome added; times of entries that did not run become null.
nlohmann::json annotate(const nlohmann::json& benchmarks) {
  nlohmann::json out = nlohmann::json::array();
  for (nlohmann::json b : benchmarks) {
    const PeerOutcome o = peer_outcome(b);
    b["status"] = o.status;
    b["note"] = o.note;
    if (o.status != "ran") b["real_time"] = b["cpu_time"] = nullptr;
    out.push_back(std::move(b));
  }
  return out;
}

}  // namespace

PeerOutcome peer_outcome(const nlohmann::json& b) {
  if (b.contains("status") && b.contains("note")) return {b["status"], b["note"]};  // already annotated
  const std::string error = b.value("error_message", std::string());
  const bool failed = b.value("error_occurred", false) || !error.empty() || b.value("skipped", false);
  if (failed && error.rfind("built without", 0) == 0) return {"not built", not_built_note(error)};
  if (failed) return {"did not run", "did not run: " + (error.empty() ? std::string("skipped") : error)};
  const auto& t = b.contains("real_time") ? b["real_time"] : nlohmann::json();
  if (!t.is_number() || t.get<double>() <= 0) return {"did not run", "did not run: no time reported"};
  return {"ran", ""};
}

std::string peers_markdown(const nlohmann::json& peers) {
  std::ostringstream md;
  md << "\n## Rasteriser peers\n\n";
  if (!peers.value("ran", false)) {
    md << peers.value("note", std::string("not run")) << "\n";
    return md.str();
  }
  md << "`" << peers.value("program", std::string())
     << " --benchmark_format=json`:\n\n| benchmark | real time | unit |\n|---|---|---|\n";
  for (const auto& b : peers.value("benchmarks", nlohmann::json::array())) {
    const PeerOutcome o = peer_outcome(b);
    md << "| " << b.value("name", std::string()) << " | ";
    if (o.status == "ran") {
      char time[32];
      std::snprintf(time, sizeof time, "%.3f", b["real_time"].get<double>());
      md << time << " | " << b.value("time_unit", std::string()) << " |\n";
    } else {
      md << o.note << " | — |\n";
    }
  }
  return md.str();
}

fs::path peers_bench_path() {
  std::error_code ec;
  const fs::path self = fs::read_symlink("/proc/self/exe", ec);
  return ec ? fs::path() : self.parent_path() / "bench" / "peers_bench";
}

nlohmann::json run_peers_bench(const fs::path& program) {
  std::error_code ec;
  if (program.empty() || !fs::exists(program, ec))
    return {{"ran", false}, {"note", "peers_bench not built (looked for " + program.string() + "); peers skipped"}};
  const auto t0 = SteadyClock::now();
  std::string out;
  const std::string cmd = shell_quote(program.string()) + " --benchmark_format=json 2>/dev/null";
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
          {"wall_s", seconds_since(t0)},
          {"benchmarks", annotate(doc["benchmarks"])}};
}

}  // namespace silva::app
