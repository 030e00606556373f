#include "bench/harness/bench_compare.hpp"

#include <fstream>
#include <map>

namespace silva::bench {

namespace fs = std::filesystem;

std::vector<Regression> compare_results(const nlohmann::json& previous, const nlohmann::json& current,
                                        double threshold) {
  std::map<std::pair<std::string, std::string>, double> before;
  for (const auto& f : previous.value("figures", nlohmann::json::array()))
    before[{f.value("table", ""), f.value("x", "")}] = f.value("silva_s", 0.0);
  std::vector<Regression> out;
  for (const auto& f : current.value("figures", nlohmann::json::array())) {
    const auto it = before.find({f.value("table", ""), f.value("x", "")});
    if (it == before.end() || it->second <= 0) continue;
    const double after = f.value("silva_s", 0.0);
    const double change = after / it->second - 1.0;
    if (change >= threshold - 1e-9) out.push_back({it->first.first, it->first.second, it->second, after, change});
  }
  return out;
}

std::optional<fs::path> previous_results(const fs::path& dir, const std::string& kind, const std::string& cpu) {
  std::optional<fs::path> best;
  std::string best_time;
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(dir, ec)) {
    if (entry.path().extension() != ".json") continue;
    std::ifstream in(entry.path());
    const nlohmann::json doc = nlohmann::json::parse(in, nullptr, /*allow_exceptions=*/false);
    if (!doc.is_object() || doc.value("harness", "") != "silva-bench" || doc.value("kind", "") != kind ||
        doc.value("cpu_slug", "") != cpu)
      continue;
    const std::string created = doc.value("created_utc", "");
    if (!best || created > best_time) {
      best = entry.path();
      best_time = created;
    }
  }
  return best;
}

}  // namespace silva::bench
