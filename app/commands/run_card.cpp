// `silva card DIR`: counts the dataset's own files (io/dataset_card.hpp) and writes CARD.md, card.json and
// the charts in card/. Every number is recounted from the label, depth and camera files, so the card is the
// same for a single run, a resumed run and merged shards.
#include <cstdio>
#include <map>

#include "app/commands/commands.hpp"
#include "app/config/config_print.hpp"
#include "core/error.hpp"
#include "io/atomic_file.hpp"
#include "io/dataset_card.hpp"
#include "io/json_read.hpp"
#include "io/png_writer.hpp"
#include "io/run_folder.hpp"

namespace silva::app {

namespace fs = std::filesystem;

namespace {

/// Every leaf of a JSON object as "a.b.c" -> value.
void flatten(const nlohmann::json& j, const std::string& prefix, std::map<std::string, nlohmann::json>& out) {
  if (j.is_object() && !(prefix.ends_with("presets"))) {
    for (const auto& [k, v] : j.items()) flatten(v, prefix.empty() ? k : prefix + "." + k, out);
  } else {
    out[prefix] = j;
  }
}

/// Keys whose value differs from the defaults (seed and output.dir left out): key -> {default, value}.
nlohmann::json config_differences(const nlohmann::json& config) {
  std::map<std::string, nlohmann::json> defaults, used;
  flatten(config_to_json(LoadedConfig{}), "", defaults);
  flatten(config, "", used);
  nlohmann::json diff = nlohmann::json::object();
  for (const auto& [key, value] : used) {
    if (key == "seed" || key == "output.dir") continue;
    const auto it = defaults.find(key);
    if (it == defaults.end() || it->second != value)
      diff[key] = {{"default", it == defaults.end() ? nlohmann::json() : it->second}, {"value", value}};
  }
  return diff;
}

std::string seconds(double s) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3f s", s);
  return buf;
}

std::string percent(double share) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.2f %%", 100.0 * share);
  return buf;
}

/// The class table: one row per class id that a role uses, in id order.
nlohmann::json class_rows(const io::Dataset& d, const io::CardCounts& c) {
  nlohmann::json rows = nlohmann::json::array();
  for (int id = 0; id < 256; ++id) {
    std::string roles, name, rugd, rellis;
    std::array<uint8_t, 3> color{};
    for (int r = 0; r < kRoleCount; ++r) {
      const OntologyClass& oc = d.ontology.classes[size_t(r)];
      if (oc.id != id) continue;
      roles += (roles.empty() ? "" : ",") + oc.role;
      if (name.empty()) name = oc.name, rugd = oc.rugd, rellis = oc.rellis, color = oc.color;
    }
    if (roles.empty()) continue;
    rows.push_back({{"id", id}, {"name", name}, {"roles", roles}, {"color", color}, {"rugd", rugd}, {"rellis", rellis},
                    {"pixels", c.class_pixels[size_t(id)]},
                    {"fraction", c.pixels ? double(c.class_pixels[size_t(id)]) / double(c.pixels) : 0.0},
                    {"instances", c.class_instances[size_t(id)]}});
  }
  return rows;
}

void write_chart(const fs::path& path, const std::vector<uint8_t>& rgb, int w, int h) {
  io::write_file_atomic(path, io::encode_png_rgb8(rgb, w, h));
}

/// Colours (and their names in CARD.md) of the sequences on the pose map, in first-seen order.
const std::vector<std::array<uint8_t, 3>> kSequenceColors = {{200, 60, 40}, {40, 120, 200}, {40, 160, 60}};
constexpr const char* kSequenceColorNames[] = {"red", "blue", "green"};

/// card.json's object: counts, conditions, config differences and the run's timings.
nlohmann::json card_json(const io::Dataset& d, const io::CardCounts& c) {
  const nlohmann::json& config = d.manifest.at("config");
  nlohmann::json run = nlohmann::json::object();
  const fs::path run_json = d.dir / "run.json";
  if (fs::exists(run_json)) run = io::parse_json_text(io::read_text_file(run_json), run_json.string());
  nlohmann::json sizes = nlohmann::json::array(), depth = nlohmann::json::array();
  for (int k = 0; k < io::CardCounts::kSizeBins; ++k)
    sizes.push_back({{"min_pixels", uint64_t(1) << k}, {"instances", c.instance_sizes[size_t(k)]}});
  for (int k = 0; k < io::CardCounts::kDepthBins; ++k)
    depth.push_back({{"from_m", 2 * k}, {"to_m", 2 * k + 2}, {"pixels", c.depth[size_t(k)]}});
  return {{"seed", d.seed},
          {"silva_version", d.manifest.value("silva_version", "")},
          {"frames", d.manifest.at("frames")},
          {"resolution", config.at("output").at("resolution")},
          {"pixels", c.pixels},
          {"classes", class_rows(d, c)},
          {"instance_sizes", sizes},
          {"depth_histogram", depth},
          {"depth_no_hit_pixels", c.depth_no_hit},
          {"conditions",
           {{"time_of_day", config.at("lighting").at("time_of_day")},
            {"weather", config.at("lighting").at("weather")},
            {"season", config.at("vegetation").at("season")},
            {"aerial", config.at("captures").at("aerial")}}},
          {"config_differences", config_differences(config)},
          {"timings_s", run.value("timings_s", nlohmann::json())}};
}

/// The charts in <dir>/card/: classes, depth, instance_sizes and poses (PNG).
void write_charts(const fs::path& dir, const nlohmann::json& card, const io::CardCounts& c) {
  constexpr int w = 640, h = 320;
  std::vector<std::string> labels;
  std::vector<double> values;
  std::vector<std::array<uint8_t, 3>> colors;
  const auto chart = [&](const char* file, const char* title) {
    write_chart(dir / file, io::bar_chart(title, labels, values, colors, w, h), w, h);
    labels.clear(), values.clear(), colors = {{90, 120, 200}};
  };
  for (const auto& row : card["classes"]) {
    labels.push_back(row["name"]);
    values.push_back(100.0 * row["fraction"].get<double>());
    colors.push_back(row["color"]);
  }
  chart("classes.png", "pixel share per class (%)");
  for (int k = 0; k < io::CardCounts::kDepthBins; ++k) {
    labels.push_back(std::to_string(2 * k) + (k + 1 == io::CardCounts::kDepthBins ? "+ m" : " m"));
    values.push_back(double(c.depth[size_t(k)]));
  }
  chart("depth.png", "depth histogram (pixels per 2 m)");
  for (int k = 0; k < 20; ++k) {
    labels.push_back(std::to_string(uint64_t(1) << k) + "+ px");
    values.push_back(double(c.instance_sizes[size_t(k)]));
  }
  chart("instance_sizes.png", "instances per size (pixels, log2 bins)");
  write_chart(dir / "poses.png", io::pose_map(c, kSequenceColors, 480), 480, 480);
}

/// CARD.md: the card's numbers in words, a table and the charts.
std::string card_markdown(const io::Dataset& d, const nlohmann::json& card, const io::CardCounts& c) {
  const nlohmann::json& cond = card["conditions"];
  std::string md = "# Silva dataset " + io::seed_folder_name(d.seed) + "\n\n";
  md += "Silva " + card["silva_version"].get<std::string>() + ", seed " + std::to_string(d.seed) + ", " +
        std::to_string(d.frames.size()) + " frames at " + card["resolution"].get<std::string>() + " (";
  for (const auto& [s, n] : d.manifest.at("frames").items()) md += s + " " + std::to_string(n.get<int>()) + ", ";
  md.resize(md.size() - 2);
  md += "). Conditions: time of day `" + cond["time_of_day"].get<std::string>() + "`, weather `" +
        cond["weather"].get<std::string>() + "`, season `" + cond["season"].get<std::string>() + "`, " +
        (cond["aerial"].get<bool>() ? "aerial" : "ground") + " perspective.\n\n";
  md += "## Classes\n\n![pixel share per class](card/classes.png)\n\n"
        "| id | class | pixel share | instances | RUGD | RELLIS-3D |\n|---|---|---|---|---|---|\n";
  for (const auto& row : card["classes"])
    md += "| " + std::to_string(row["id"].get<int>()) + " | " + row["name"].get<std::string>() + " | " +
          percent(row["fraction"]) + " | " + std::to_string(row["instances"].get<uint64_t>()) + " | " +
          row["rugd"].get<std::string>() + " | " + row["rellis"].get<std::string>() + " |\n";
  md += "\nShares are of all " + std::to_string(c.pixels) +
        " semantic pixels, counted from the semantic PNGs; instances are instance-table rows with pixels. "
        "The RUGD and RELLIS-3D columns name the class each maps to (ontology.json).\n\n";
  md += "## Instance sizes\n\n![instances per size](card/instance_sizes.png)\n\n";
  md += "## Depth\n\n![depth histogram](card/depth.png)\n\n" + std::to_string(c.depth_no_hit) +
        " pixels hit nothing (sky or beyond camera.far); the last bin holds 64 m and farther.\n\n";
  md += "## Cameras\n\n![camera positions](card/poses.png)\n\nTop down, world X to the right, Y up; a stroke "
        "points along each view. Colours by sequence: ";
  std::map<int, std::string> order;
  for (size_t i = 0; i < d.frames.size(); ++i) order[c.sequence_of[i]] = d.frames[i].sequence;
  for (const auto& [k, s] : order) md += s + " " + kSequenceColorNames[size_t(k) % 3] + ", ";
  md.resize(md.size() - 2);
  md += ".\n\n## Config differences from the defaults\n\n";
  if (card["config_differences"].empty()) md += "None (seed and output.dir aside).\n";
  for (const auto& [key, v] : card["config_differences"].items())
    md += "- `" + key + "`: " + v["value"].dump() + " (default " + v["default"].dump() + ")\n";
  md += "\n## Timings\n\n";
  if (card["timings_s"].is_null()) md += "No run.json timings (e.g. merged shards).\n";
  for (const auto& [phase, s] : card["timings_s"].items())
    md += "- " + phase + ": " + (s.is_number() ? seconds(s.get<double>()) : s.dump()) + "\n";
  return md;
}

}  // namespace

void write_card(const fs::path& run_dir) {
  const io::Dataset d = io::open_dataset(run_dir);
  const io::CardCounts c = io::count_dataset(d);
  const nlohmann::json card = card_json(d, c);
  io::create_folder(run_dir / "card");
  write_charts(run_dir / "card", card, c);
  io::write_file_atomic(run_dir / "card.json", card.dump(2) + "\n");
  io::write_file_atomic(run_dir / "CARD.md", card_markdown(d, card, c));
}

int run_card(const fs::path& run_dir, const Reporter& reporter) {
  write_card(run_dir);
  reporter.result({{"ok", true}, {"run_dir", run_dir.string()}, {"card", (run_dir / "CARD.md").string()}},
                  "wrote " + (run_dir / "CARD.md").string() + ", card.json and card/*.png");
  return 0;
}

}  // namespace silva::app
