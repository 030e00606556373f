// `silva card DIR`: counts the dataset's own files (io/dataset_card.hpp) and writes CARD.md, card.json and
// the charts card_*.png beside it. Every number is recounted from the label, depth and camera files, so the card is the
// same for a single run, a resumed run and merged shards.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <optional>
#include <set>

#include "app/commands/card/card_map.hpp"
#include "app/commands/card/card_command.hpp"
#include "app/commands/card/published_classes.hpp"
#include "pipeline/config/config_print.hpp"
#include "core/error.hpp"
#include "io/atomic_file.hpp"
#include "io/dataset_card.hpp"
#include "io/export_formats.hpp"
#include "io/json_read.hpp"
#include "io/png_writer.hpp"
#include "io/printf_string.hpp"
#include "io/run_folder.hpp"
#include "world/forest_types.hpp"
#include "world/trail_surface_choice.hpp"
#include "app/cli/pipeline_names.hpp"

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

std::string percent(double share) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.2f %%", 100.0 * share);
  return buf;
}

/// The forest type the dataset's world grew: vegetation.forest_type, the drawn one for "random" (and
/// "mixed" for datasets from before the key).
std::string forest_type_name(const nlohmann::json& config, uint64_t seed) {
  const nlohmann::json& vegetation = config.at("vegetation");
  return world::forest_type_of(vegetation.value("forest_type", std::string("mixed")), seed).name;
}

/// The trail's surface family: trail.surface, the drawn one for "random" ("packed_earth" for datasets from
/// before the key, "none" without a trail).
std::string trail_surface_label(const nlohmann::json& config, uint64_t seed) {
  const nlohmann::json& trail = config.at("trail");
  if (!trail.value("enabled", true)) return "none";
  return std::string(trail_surface_name(world::trail_surface_of(trail.value("surface", std::string("packed_earth")), seed)));
}

/// card.json's "rig": its preset, cameras, height (null: camera.ground_height), tilt, LiDAR, the stereo baseline (null:
/// one camera) and, with the trajectory sequence, the IMU's rate and noise model (else null), from the manifest's config.

nlohmann::json rig_summary(const nlohmann::json& manifest) {
  const nlohmann::json& config = manifest.at("config");
  const nlohmann::json rig = config.value("rig", nlohmann::json::object());
  const bool stereo = io::manifest_stereo(manifest);
  const bool imu = manifest.at("frames").contains("trajectory") && config.contains("trajectory");
  // A key of another type (a hand-edited manifest) reads as its default.
  const auto number = [&](const char* key) {
    return rig.contains(key) && rig[key].is_number() ? rig[key].get<double>() : 0.0;
  };
  const double height = number("height_m");
  return {{"preset", rig.contains("preset") && rig["preset"].is_string() ? rig["preset"] : nlohmann::json("mono")},
          {"cameras", stereo ? 2 : 1},
          {"height_m", height > 0 ? nlohmann::json(height) : nlohmann::json()},
          {"pitch_deg", number("pitch_deg")},
          {"lidar", rig.contains("lidar") && rig["lidar"].is_boolean() && rig["lidar"].get<bool>()},
          {"baseline_m", stereo && number("baseline_m") > 0 ? rig["baseline_m"] : nlohmann::json()},
          {"imu_hz", imu ? config.at("trajectory").at("imu_hz") : nlohmann::json()},
          {"imu_noise", imu ? config.at("trajectory").at("imu_noise") : nlohmann::json()}};
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
                    {"instances", c.class_instances[size_t(id)]},
                    {"lidar_points", c.lidar_class_points[size_t(id)]}});
  }
  return rows;
}

void write_chart(const fs::path& path, const std::vector<uint8_t>& rgb, int w, int h) {
  io::write_file_atomic(path, io::encode_png_rgb8(rgb, w, h));
}

/// Colours (and their names in CARD.md) of the sequences on the pose map, in first-seen order.
const std::vector<std::array<uint8_t, 3>> kSequenceColors = {{220, 30, 30}, {30, 90, 230}, {220, 40, 220}};
constexpr const char* kSequenceColorNames[] = {"red", "blue", "magenta"};

/// The published distribution beside the dataset's: per class name of `pub` that the ontology maps a class to
/// (`rellis` names), the published share of its labelled points and the dataset's pixel and LiDAR point
/// shares of the classes mapped to it; the rest of the published classes as one "other" row.
nlohmann::json published_rows(const io::Dataset& d, const io::CardCounts& c, const PublishedDistribution& pub) {
  uint64_t labelled = 0;
  for (const PublishedClass& k : pub.classes)
    if (k.name != pub.unlabelled) labelled += k.count;
  std::vector<std::string> names;
  for (const OntologyClass& oc : d.ontology.classes)
    if (std::find(names.begin(), names.end(), oc.rellis) == names.end()) names.push_back(oc.rellis);
  nlohmann::json rows = nlohmann::json::array();
  uint64_t other = 0;
  for (const PublishedClass& k : pub.classes)
    if (k.name != pub.unlabelled && std::find(names.begin(), names.end(), k.name) == names.end()) other += k.count;
  const auto share = [](uint64_t n, uint64_t total) { return total ? double(n) / double(total) : 0.0; };
  for (const std::string& name : names) {
    uint64_t published = 0, pixels = 0, points = 0;
    std::string classes;
    for (const PublishedClass& k : pub.classes)
      if (k.name == name) published = k.count;
    std::set<uint8_t> ids;
    for (const OntologyClass& oc : d.ontology.classes)
      if (oc.rellis == name && ids.insert(oc.id).second) {
        pixels += c.class_pixels[oc.id];
        points += c.lidar_class_points[oc.id];
        classes += (classes.empty() ? "" : ", ") + oc.name;
      }
    rows.push_back({{"name", name}, {"published", published}, {"published_share", share(published, labelled)},
                    {"silva_classes", classes}, {"silva_pixel_share", share(pixels, c.pixels)},
                    {"silva_lidar_share", share(points, c.lidar_points)}});
  }
  rows.push_back({{"name", "other"}, {"published", other}, {"published_share", share(other, labelled)},
                  {"silva_classes", ""}, {"silva_pixel_share", 0.0}, {"silva_lidar_share", 0.0}});
  return rows;
}

/// The sentence on instances smaller than the COCO exports' default crowd threshold (size bins are powers of two).
std::string small_instances_note(const io::CardCounts& c) {
  constexpr int64_t threshold = io::ExportOptions::kDefaultMinInstanceArea;
  uint64_t small = 0, all = 0;
  for (int k = 0; k < io::CardCounts::kSizeBins; ++k) {
    all += c.instance_sizes[size_t(k)];
    if ((int64_t(1) << (k + 1)) <= threshold) small += c.instance_sizes[size_t(k)];
  }
  return std::to_string(small) + " of " + std::to_string(all) + " instances in a frame cover fewer than " +
         std::to_string(threshold) + " pixels of it: `coco-instances` and `coco-panoptic` mark them iscrowd 1, so "
         "that a detector neither learns nor is scored on such fragments (`silva export --min-area N` sets the "
         "threshold; 0 marks none).\n\n";
}

/// card.json's object: counts, conditions and config differences (no timings: they live in run.json, so the card
/// is the same for any thread count).
nlohmann::json card_json(const io::Dataset& d, const io::CardCounts& c, const CameraMap& map) {
  const nlohmann::json& config = d.manifest.at("config");
  nlohmann::json sizes = nlohmann::json::array(), depth = nlohmann::json::array();
  for (int k = 0; k < io::CardCounts::kSizeBins; ++k)
    sizes.push_back({{"min_pixels", uint64_t(1) << k}, {"instances", c.instance_sizes[size_t(k)]}});
  for (int k = 0; k < io::CardCounts::kDepthBins; ++k) {  // the last bin is open-ended: to_m null
    const bool last = k + 1 == io::CardCounts::kDepthBins;
    depth.push_back({{"from_m", 2 * k}, {"to_m", last ? nlohmann::json() : nlohmann::json(2 * k + 2)},
                     {"pixels", c.depth[size_t(k)]}});
  }
  return {{"seed", d.seed},
          {"silva_version", d.manifest.value("silva_version", "")},
          {"frames", d.manifest.at("frames")},
          {"resolution", config.at("output").at("resolution")},
          {"pixels", c.pixels},
          {"classes", class_rows(d, c)},
          {"instance_sizes", sizes},
          {"depth_histogram", depth},
          {"depth_no_hit_pixels", c.depth_no_hit},
          {"lidar_points", c.lidar_points},
          {"class_map", map.map ? nlohmann::json{{"x0", map.map->x0}, {"y1", map.map->y1},
                                                 {"metres_per_pixel", map.map->metres_per_pixel},
                                                 {"width", map.map->width}, {"height", map.map->height}}
                                : nlohmann::json()},
          {"published",
           {{"rellis3d",
             {{"unit", rellis3d_lidar_points().unit}, {"source", rellis3d_lidar_points().source},
              {"classes", published_rows(d, c, rellis3d_lidar_points())}}},
            {"rugd", nullptr}}},
          {"rig", rig_summary(d.manifest)},
          {"conditions",
           {{"time_of_day", config.at("lighting").at("time_of_day")},
            {"weather", config.at("lighting").at("weather")},
            {"season", config.at("vegetation").at("season")},
            {"forest_type", forest_type_name(config, uint64_t(d.seed))},
            {"trail_surface", trail_surface_label(config, uint64_t(d.seed))},
            {"aerial", config.at("captures").at("aerial")}}},
          {"config_differences", config_differences(config)}};
}

/// The charts <dir>/card_classes.png, card_depth.png, card_instance_sizes.png and card_poses.png.
void write_charts(const fs::path& dir, const nlohmann::json& card, const io::CardCounts& c, const CameraMap& map) {
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
  chart("card_classes.png", "pixel share per class (%)");
  for (int k = 0; k < io::CardCounts::kDepthBins; ++k) {
    labels.push_back(std::to_string(2 * k) + (k + 1 == io::CardCounts::kDepthBins ? "+ m" : " m"));
    values.push_back(double(c.depth[size_t(k)]));
  }
  chart("card_depth.png", "depth histogram (pixels per 2 m)");
  for (int k = 0; k < 20; ++k) {
    labels.push_back(std::to_string(uint64_t(1) << k) + "+ px");
    values.push_back(double(c.instance_sizes[size_t(k)]));
  }
  chart("card_instance_sizes.png", "instances per size (pixels, log2 bins)");
  std::vector<io::LegendEntry> legend;
  for (const auto& row : card["classes"])
    if (row["roles"] != "background")
      legend.emplace_back(row["name"].get<std::string>(), row["color"].get<std::array<uint8_t, 3>>());
  std::optional<io::MapBackground> background;
  if (map.map)
    background = io::MapBackground{map.map->width, map.map->height, map.map->x0, map.map->y1,
                                   map.map->metres_per_pixel, map.map->rgb};
  if (!background) legend.clear();
  write_chart(dir / "card_poses.png", io::pose_map(c, kSequenceColors, kMapSize, background ? &*background : nullptr, legend),
              io::pose_map_width(kMapSize, legend), kMapSize);
}

/// CARD.md's sentence on the rig: its cameras and, with the trajectory sequence, the IMU.
std::string rig_sentence(const nlohmann::json& rig) {
  std::string text = "Rig: `" + rig["preset"].get<std::string>() + "`, ";
  text += rig["baseline_m"].is_null()
              ? std::string("one camera")
              : io::printf_string("a rectified stereo pair, baseline %.3g m (the right camera's outputs in `<type>_right/`, "
                                  "the left camera's disparity in `disparity/`),",
                                  rig["baseline_m"].get<double>());
  text += rig["height_m"].is_null() ? std::string(" at camera.ground_height")
                                    : io::printf_string(" %.3g m above the ground", rig["height_m"].get<double>());
  if (const double pitch = rig["pitch_deg"].get<double>(); pitch != 0)
    text += io::printf_string(", tilted %.3g° %s", std::abs(pitch), pitch < 0 ? "down" : "up");
  text += rig["lidar"].get<bool>() ? ", with a LiDAR." : ".";
  if (!rig["imu_hz"].is_null())
    text += io::printf_string(" The trajectory sequence carries an IMU at the left camera, %.4g Hz, noise `%s`.",
                          rig["imu_hz"].get<double>(), rig["imu_noise"].get<std::string>().c_str());
  return text + "\n\n";
}

/// CARD.md: the card's numbers in words, a table and the charts.
std::string card_markdown(const io::Dataset& d, const nlohmann::json& card, const io::CardCounts& c,
                          const CameraMap& map) {
  const nlohmann::json& cond = card["conditions"];
  std::string md = "# Silva dataset " + io::seed_folder_name(d.seed) + "\n\n";
  md += "Silva " + card["silva_version"].get<std::string>() + ", seed " + std::to_string(d.seed) + ", " +
        std::to_string(d.frames.size()) + " frames at " + card["resolution"].get<std::string>() + " (";
  for (const auto& [s, n] : d.manifest.at("frames").items()) md += s + " " + std::to_string(n.get<int>()) + ", ";
  md.resize(md.size() - 2);
  md += "). Conditions: time of day `" + cond["time_of_day"].get<std::string>() + "`, weather `" +
        cond["weather"].get<std::string>() + "`, season `" + cond["season"].get<std::string>() + "`, forest `" +
        cond["forest_type"].get<std::string>() + "`, trail `" + cond["trail_surface"].get<std::string>() + "`, " +
        (cond["aerial"].get<bool>() ? "aerial" : "ground") + " perspective.\n\n";
  md += "## Classes\n\n![pixel share per class](card_classes.png)\n\n"
        "| id | class | pixel share | instances | RUGD | RELLIS-3D |\n|---|---|---|---|---|---|\n";
  for (const auto& row : card["classes"])
    md += "| " + std::to_string(row["id"].get<int>()) + " | " + row["name"].get<std::string>() + " | " +
          percent(row["fraction"]) + " | " + std::to_string(row["instances"].get<uint64_t>()) + " | " +
          row["rugd"].get<std::string>() + " | " + row["rellis"].get<std::string>() + " |\n";
  md += "\nShares are of all " + std::to_string(c.pixels) +
        " semantic pixels, counted from the semantic PNGs; instances are instance-table rows with pixels. "
        "The RUGD and RELLIS-3D columns name the class each maps to (ontology.json). A tree's instance is its "
        "woody skeleton, trunk and branches together (one instance can span the whole crown); its leaves and needles "
        "are canopy, which has no instance.\n\n";
  md += "## Instance sizes\n\n![instances per size](card_instance_sizes.png)\n\n" + small_instances_note(c);
  md += "## Depth\n\n![depth histogram](card_depth.png)\n\n" + std::to_string(c.depth_no_hit) +
        " pixels hit nothing (sky or beyond camera.far); the last bin holds 64 m and farther.\n\n";
  md += "## Cameras\n\n" + rig_sentence(card["rig"]) +
        "![camera positions](card_poses.png)\n\nTop down, world X to the right, Y up; a stroke points along each "
        "view. ";
  md += map.map ? "Under them the class map of the world within " + std::to_string(int(kMapMargin)) +
                      " m of the cameras (each object a disc of its crown or top in the colour of its class seen from "
                      "above, the trail and solid footprints on top; built again from the run's config). "
                : "No class map under them: " + map.missing + ". ";
  md += "Colours by sequence: ";
  std::map<int, std::string> order;
  for (size_t i = 0; i < d.frames.size(); ++i) order[c.sequence_of[i]] = d.frames[i].sequence;
  for (const auto& [k, s] : order) md += s + " " + kSequenceColorNames[size_t(k) % 3] + ", ";
  md.resize(md.size() - 2);
  md += ".\n\n## Compared with a real dataset\n\n";
  const nlohmann::json& rellis = card["published"]["rellis3d"];
  md += "RELLIS-3D's published class distribution (" + rellis["unit"].get<std::string>() +
        ", shares of its labelled points, void left out) beside this dataset's, per RELLIS-3D class the "
        "ontology maps to";
  md += c.lidar_points ? ":\n\n| RELLIS-3D class | RELLIS-3D points | Silva classes | Silva pixels | Silva LiDAR points |\n"
                         "|---|---|---|---|---|\n"
                       : ":\n\n| RELLIS-3D class | RELLIS-3D points | Silva classes | Silva pixels |\n|---|---|---|---|\n";
  for (const auto& row : rellis["classes"]) {
    md += "| " + row["name"].get<std::string>() + " | " + percent(row["published_share"]) + " | " +
          row["silva_classes"].get<std::string>() + " | " + percent(row["silva_pixel_share"]) + " |";
    if (c.lidar_points) md += " " + percent(row["silva_lidar_share"]) + " |";
    md += "\n";
  }
  md += "\nSource: " + rellis["source"].get<std::string>() +
        ". RUGD (Wigness et al., IROS 2019) is not set beside it: no per-class numbers of RUGD with a citable source "
        "were found, and the card reads no values off published charts.\n";
  md += "\n## Config differences from the defaults\n\n";
  if (card["config_differences"].empty()) md += "None (seed and output.dir aside).\n";
  for (const auto& [key, v] : card["config_differences"].items())
    md += "- `" + key + "`: " + v["value"].dump() + " (default " + v["default"].dump() + ")\n";
  md += "\n## Timings\n\n`run.json` holds the run's timings per phase (each shard's in `run.shard-i-of-N.json`): they "
        "differ from run to run, so the card, like every other file of the dataset, does not quote them.\n";
  return md;
}

}  // namespace

void write_card(const fs::path& run_dir, const CardInputs& inputs) {
  const io::Dataset d = io::open_dataset(run_dir);
  const io::CardCounts c = io::count_dataset(d, inputs.known ? *inputs.known : io::KnownCounts{});
  const CameraMap map = camera_map(d, c, inputs);
  const nlohmann::json card = card_json(d, c, map);
  write_charts(run_dir, card, c, map);  // beside CARD.md: the seed folder holds only sequence folders
  io::write_file_atomic(run_dir / "card.json", card.dump(2) + "\n");
  io::write_file_atomic(run_dir / "CARD.md", card_markdown(d, card, c, map));
}

int run_card(const fs::path& run_dir, const Reporter& reporter) {
  write_card(run_dir);
  reporter.result({{"ok", true}, {"run_dir", run_dir.string()}, {"card", (run_dir / "CARD.md").string()}},
                  "wrote " + (run_dir / "CARD.md").string() + ", card.json and card_*.png");
  return 0;
}

}  // namespace silva::app
