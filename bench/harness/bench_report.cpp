#include "bench/harness/bench_report.hpp"

#include <cstdio>
#include <map>
#include <sstream>

#include "bench/harness/bench_programs.hpp"
#include "bench/harness/bench_process.hpp"

namespace silva::bench {

namespace {

/// printf-style formatting into a string.
template <class... A>
std::string fmt(const char* f, A... a) {
  char buf[256];
  std::snprintf(buf, sizeof buf, f, a...);
  return buf;
}

/// A time in seconds with 3 significant-ish digits.
std::string secs(double s) { return s >= 100 ? fmt("%.0f", s) : s >= 1 ? fmt("%.2f", s) : fmt("%.3f", s); }

/// A count with thin grouping: 1234567 -> "1 234 567".
std::string count(uint64_t n) {
  std::string digits = std::to_string(n), out;
  for (size_t k = 0; k < digits.size(); ++k) {
    if (k && (digits.size() - k) % 3 == 0) out += ' ';
    out += digits[k];
  }
  return out;
}

/// The figures of `table`, in results order.
std::vector<nlohmann::json> figures_of(const nlohmann::json& results, const std::string& table) {
  std::vector<nlohmann::json> out;
  for (const auto& f : results["figures"])
    if (f["table"] == table) out.push_back(f);
  return out;
}

/// One headline line: "what: Silva s vs thesis s (N x faster)".
std::string headline(const nlohmann::json& results, const std::string& table, const std::string& x,
                     const std::string& what) {
  for (const auto& f : results["figures"]) {
    if (f["table"] != table || f["x"] != x || f["ratio"].is_null()) continue;
    const double silva = f["silva_s"], thesis = f["thesis_s"];
    return "- " + what + ": **" + secs(silva) + " s** vs thesis " + secs(thesis) + " s — " +
           fmt("%.1f", thesis / silva) + "x faster" + (f["extrapolated"].get<bool>() ? " (extrapolated)" : "") + "\n";
  }
  return "";
}

/// The markdown table of a thesis table's figures.
void thesis_table(std::ostringstream& md, const nlohmann::json& results, const std::string& table,
                  const std::string& title) {
  const auto figures = figures_of(results, table);
  if (figures.empty()) return;
  md << "\n## Table " << table << " — " << title << "\n\n";
  md << "| x | Silva s | thesis s | Silva/thesis | speed-up | objects | chunks | triangles | frames | pixels | note |\n";
  md << "|---|---|---|---|---|---|---|---|---|---|---|\n";
  for (const auto& f : figures) {
    const auto& w = f["work"];
    const bool has_ratio = !f["ratio"].is_null();
    const double ratio = has_ratio ? f["ratio"].get<double>() : 0.0;
    md << "| " << f["x"].get<std::string>() << " | " << secs(f["silva_s"]) << (f["extrapolated"].get<bool>() ? "*" : "")
       << " | " << (f["thesis_s"].is_null() ? "—" : secs(f["thesis_s"])) << " | "
       << (has_ratio ? fmt("%.3f", ratio) : "—") << " | " << (has_ratio && ratio > 0 ? fmt("%.1fx", 1 / ratio) : "—")
       << " | " << count(w["objects"]) << " | " << count(w["chunks"]) << " | " << count(w["triangles"]) << " | "
       << count(w["frames"]) << " | " << count(w["pixels"]) << " | " << f["note"].get<std::string>() << " |\n";
  }
}

/// The thread-scaling table (generation and capture seconds and speed-up against 1 thread).
void scaling_table(std::ostringstream& md, const nlohmann::json& results) {
  const auto gen = figures_of(results, "threads-generation"), cap = figures_of(results, "threads-capture");
  if (gen.empty() && cap.empty()) return;
  md << "\n## Thread scaling (tbb::task_arena)\n\n";
  md << "Generation: the default world. Capture: " << (cap.empty() ? "" : cap[0]["note"].get<std::string>())
     << " (RGB + semantic + depth, warm world).\n\n";
  md << "| threads | generation s | speed-up | capture s | speed-up | capture s/set |\n|---|---|---|---|---|---|\n";
  for (size_t k = 0; k < std::max(gen.size(), cap.size()); ++k) {
    md << "| " << (k < gen.size() ? gen[k]["x"] : cap[k]["x"]).get<std::string>() << " | ";
    if (k < gen.size()) md << secs(gen[k]["silva_s"]) << " | " << fmt("%.2fx", gen[0]["silva_s"].get<double>() / gen[k]["silva_s"].get<double>());
    else md << "— | —";
    md << " | ";
    if (k < cap.size())
      md << secs(cap[k]["silva_s"]) << " | " << fmt("%.2fx", cap[0]["silva_s"].get<double>() / cap[k]["silva_s"].get<double>())
         << " | " << secs(cap[k]["silva_s"].get<double>() / std::max<double>(1, cap[k]["work"]["frames"].get<double>()));
    else md << "— | — | —";
    md << " |\n";
  }
}

}  // namespace

std::string chart_suffix(const std::string& table) {
  static const std::map<std::string, std::string> charts = {
      {"5.1", "generation-density"}, {"5.2", "generation-elevation"}, {"5.5", "capture-density"},
      {"5.6", "capture-resolution"}, {"5.7", "capture-count"},       {"threads", "threads"}};
  const auto it = charts.find(table);
  return it == charts.end() ? "" : it->second;
}

std::string bench_markdown(const nlohmann::json& results, const std::string& previous_name,
                           const std::vector<Regression>& regressions, const std::filesystem::path& dir,
                           const std::string& stem) {
  const auto chart = [&](std::ostringstream& md, const std::string& table) {
    const std::string suffix = chart_suffix(table);
    const std::string file = stem + "-" + suffix + ".png";
    if (!suffix.empty() && std::filesystem::exists(dir / file)) md << "\n![" << suffix << "](" << file << ")\n";
  };
  const auto& m = results["machine"];
  std::ostringstream md;
  md << "# `silva bench` (" << results["kind"].get<std::string>() << ") — " << results["created_utc"].get<std::string>()
     << "\n\n";
  md << "- Machine: " << m["cpu"].get<std::string>() << ", " << m["cores"] << " cores, "
     << fmt("%.1f", m["memory_gib"].get<double>()) << " GiB, " << m["os"].get<std::string>() << " ("
     << m["kernel"].get<std::string>() << "), " << m["compiler"].get<std::string>() << "\n";
  md << "- Git revision " << m["git_revision"].get<std::string>() << "; load average "
     << fmt("%.2f", m["load_average_start"].get<double>()) << " at the start, "
     << fmt("%.2f", results.value("load_average_end", -1.0)) << " at the end; harness wall time "
     << secs(results["wall_s"]) << " s\n";
  md << "- Thesis machine: " << results["thesis_machine"].get<std::string>() << "\n";
  md << "- Silva/thesis below 1 means Silva is faster; speed-up = thesis / Silva. * = extrapolated from a "
        "smaller measured run. Capture figures are warm (the world is generated first; generation is "
        "Tables 5.1-5.4) and include encoding and writing to a scratch folder; the set is RGB + semantic + "
        "depth as in the thesis.\n";
  md << "\n## Headline\n\n";
  md << headline(results, "5.1", "5", "Default world generation (density 5 %)");
  md << headline(results, "5.6", "1920x1080", "One capture set at 1920x1080");
  for (const auto& f : figures_of(results, "autopilot"))
    md << headline(results, "autopilot", f["x"], "Full autopilot (" + f["x"].get<std::string>() + " sets)");
  md << "\n## Against the previous results\n\n";
  if (previous_name.empty()) {
    md << "No earlier results of this kind on this CPU.\n";
  } else if (regressions.empty()) {
    md << "No figure is 10 % or more slower than in `" << previous_name << "`.\n";
  } else {
    md << regressions.size() << " figure(s) 10 % or more slower than in `" << previous_name
       << "`:\n\n| table | x | before s | now s | change |\n|---|---|---|---|---|\n";
    for (const Regression& r : regressions)
      md << "| " << r.table << " | " << r.x << " | " << secs(r.before_s) << " | " << secs(r.after_s) << " | +"
         << fmt("%.1f", 100 * r.change) << " % |\n";
  }
  for (const auto& [table, title] : results["tables"].items()) {
    thesis_table(md, results, table, title.get<std::string>());
    chart(md, table);
  }
  scaling_table(md, results);
  chart(md, "threads");
  if (results.contains("generation_process")) md << generation_process_markdown(results["generation_process"]);
  md << program_markdown("Rasteriser peers", results.value("peers", nlohmann::json::object()));
  if (results.contains("view")) md << program_markdown("`silva view` frames", results["view"]);
  if (results.contains("lidar")) md << program_markdown("LiDAR", results["lidar"]);
  return md.str();
}

}  // namespace silva::bench
