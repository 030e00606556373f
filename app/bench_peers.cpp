#include "app/bench_peers.hpp"

#include <chrono>
#include <cstdio>
#include <string>

#include "app/bench_charts.hpp"
#include "app/bench_context.hpp"

namespace silva::app {

namespace fs = std::filesystem;

fs::path peers_bench_path() {
  std::error_code ec;
  const fs::path self = fs::read_symlink("/proc/self/exe", ec);
  return ec ? fs::path() : self.parent_path() / "bench" / "peers_bench";
}

nlohmann::json run_peers_bench(const fs::path& program) {
  std::error_code ec;
  if (program.empty() || !fs::exists(program, ec))
    return {{"ran", false}, {"note", "peers_bench not built (looked for " + program.string() + "); peers skipped"}};
  const auto t0 = std::chrono::steady_clock::now();
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
  return {{"ran", true}, {"program", program.string()}, {"wall_s", seconds_since(t0)}, {"benchmarks", doc["benchmarks"]}};
}

}  // namespace silva::app
