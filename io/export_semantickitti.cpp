// SemanticKITTI export (CONTRACT.md "Export formats"): sequences/NN/ with velodyne/ (the KITTI scans, linked),
// labels/ (Silva's class id in the low 16 bits replaced by the ontology's SemanticKITTI id; in the high 16 bits the
// object's index within its sequence, the same in every scan that sees it, where the dataset's own files number
// a scan's objects within the scan), calib.txt and poses.txt (Silva's, already in KITTI form), times.txt and image_2/ (the
// RGB images when the dataset has them: calib's P2 is the capture camera). Sequence numbers are fixed per Silva
// sequence: autopilot 00, random 01, custom 02, trajectory 03. semantic-kitti.yaml is the label map the semantic-kitti-api
// reads (labels, color_map, content, learning_map, learning_map_inv, learning_ignore, split).
#include <array>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <map>
#include <set>

#include "core/error.hpp"
#include "io/atomic_file.hpp"
#include "io/export_formats.hpp"
#include "io/json_read.hpp"
#include "io/lidar_files.hpp"

namespace silva::io {

namespace fs = std::filesystem;

namespace {

/// Silva class id -> SemanticKITTI label id and the colour of the first role with that id (role order).
struct KittiMap {
  std::array<int, 256> kitti{};                    ///< -1 for a class id no role uses.
  std::map<int, std::string> names;                ///< SemanticKITTI id -> its name.
  std::map<int, std::array<uint8_t, 3>> colors;    ///< SemanticKITTI id -> RGB of its first Silva class.
};

/// The ontology's SemanticKITTI mapping; InputError when roles sharing a class id map to different ids.
KittiMap kitti_map(const Dataset& d) {
  KittiMap m;
  m.kitti.fill(-1);
  for (const OntologyClass& c : d.ontology.classes) {
    int& k = m.kitti[c.id];
    if (k >= 0 && k != c.semantic_kitti_id)
      throw InputError((d.dir / "ontology.json").string() + ": class id " + std::to_string(c.id) +
                       " maps to SemanticKITTI ids " + std::to_string(k) + " and " +
                       std::to_string(c.semantic_kitti_id) + "; a SemanticKITTI export needs one per class id");
    k = c.semantic_kitti_id;
    m.names.emplace(k, c.semantic_kitti.empty() ? "unlabeled" : c.semantic_kitti);
    m.colors.emplace(k, c.color);
  }
  m.names.emplace(0, "unlabeled");
  m.colors.emplace(0, std::array<uint8_t, 3>{0, 0, 0});
  return m;
}

/// The fixed SemanticKITTI sequence number of a Silva sequence.
int sequence_number(const std::string& sequence) {
  static const std::map<std::string, int> numbers = {{"autopilot", 0}, {"random", 1}, {"custom", 2}, {"trajectory", 3}};
  const auto it = numbers.find(sequence);
  if (it == numbers.end())
    throw InputError("semantickitti: sequence '" + sequence + "' has no SemanticKITTI number (autopilot, random, custom, "
                     "trajectory)");
  return it->second;
}

std::string two_digits(int n) {
  char buf[8];
  std::snprintf(buf, sizeof buf, "%02d", n);
  return buf;
}

/// Per frame, its scan's instance index (the high 16 bits of a dataset label) -> the object's index within the
/// frame's sequence: objects numbered 1, 2, ... in the order the sequence's scans first see them (frame order, then
/// scan index), so one object keeps one index in every scan. InputError for a sequence of more than 65 535 objects.
std::vector<std::vector<uint32_t>> sequence_instances(const Dataset& d) {
  std::vector<std::vector<uint32_t>> remap(d.frames.size());
  std::map<std::string, std::map<uint64_t, uint32_t>> numbered;  // sequence -> instance_id -> index
  for (size_t i = 0; i < d.frames.size(); ++i) {
    const fs::path table = d.file(d.frames[i], "lidar_labels", "json");
    require_dataset_file(table);
    const nlohmann::json j = parse_json_text(read_text_file(table), table.string());
    std::map<uint64_t, uint32_t>& seen = numbered[d.frames[i].sequence];
    remap[i].assign(1, 0);
    try {
      for (const nlohmann::json& e : j.at("instances")) {
        const uint64_t scan_index = e.at("index").get<uint64_t>();
        if (scan_index != remap[i].size())
          throw InputError(table.string() + ": instance indices must run 1, 2, ...; found " + std::to_string(scan_index));
        const auto [it, added] = seen.emplace(e.at("instance_id").get<uint64_t>(), uint32_t(seen.size() + 1));
        if (added && it->second > 0xFFFFu)
          throw InputError(table.string() + ": sequence '" + d.frames[i].sequence +
                           "' holds more than 65535 objects, more than a SemanticKITTI label's 16 instance bits");
        remap[i].push_back(it->second);
      }
    } catch (const nlohmann::json::exception&) {
      throw InputError(table.string() + ": not an instance table {\"instances\": [{\"index\", \"instance_id\", ...}]}");
    }
  }
  return remap;
}

/// Rewrites frame `f`'s labels into `out` (instances renumbered by `instances`, from sequence_instances) and counts
/// its points per SemanticKITTI id.
void write_labels(const Dataset& d, const DatasetFrame& f, const KittiMap& map, const std::vector<uint32_t>& instances,
                  const fs::path& out, std::map<int, uint64_t>& counts) {
  const fs::path label = d.file(f, "lidar_labels", "label");
  std::vector<uint32_t> labels = d.lidar_labels(f);  // one per point, class ids of the ontology
  for (size_t i = 0; i < labels.size(); ++i) {
    uint32_t& v = labels[i];
    const uint32_t cls = v & 0xFFFFu, instance = v >> 16;
    if (instance >= instances.size())
      throw InputError(label.string() + ": point " + std::to_string(i) + " has instance " + std::to_string(instance) +
                       ", which " + f.sequence + "/lidar_labels/" + label.stem().string() + ".json does not hold");
    ++counts[map.kitti[cls]];
    v = instances[instance] << 16 | uint32_t(map.kitti[cls]);
  }
  std::vector<uint8_t> bytes(labels.size() * 4);
  if (!labels.empty()) std::memcpy(bytes.data(), labels.data(), bytes.size());
  write_file_atomic(out, bytes);
}

/// semantic-kitti.yaml: the label map in the semantic-kitti-api's form. Training ids are 0 (unlabeled,
/// ignored) and 1, 2, ... for the other SemanticKITTI ids the ontology uses, ascending; content is each id's
/// share of the exported points.
std::string label_yaml(const KittiMap& map, const std::map<int, uint64_t>& counts, const std::set<int>& sequences) {
  uint64_t total = 0;
  for (const auto& [id, n] : counts) total += n;
  std::string y = "# SemanticKITTI label map of a Silva export (semantic-kitti-api form); colours are BGR.\n"
                  "name: \"silva\"\nlabels:\n";
  for (const auto& [id, name] : map.names) y += "  " + std::to_string(id) + ": \"" + name + "\"\n";
  y += "color_map:\n";
  for (const auto& [id, c] : map.colors)
    y += "  " + std::to_string(id) + ": [" + std::to_string(c[2]) + ", " + std::to_string(c[1]) + ", " +
         std::to_string(c[0]) + "]\n";
  y += "content: # share of the exported points\n";
  for (const auto& [id, name] : map.names) {
    const auto it = counts.find(id);
    char share[32];
    std::snprintf(share, sizeof share, "%.9g", total && it != counts.end() ? double(it->second) / double(total) : 0.0);
    y += "  " + std::to_string(id) + ": " + share + "\n";
  }
  std::map<int, int> train;
  int next = 1;
  for (const auto& [id, name] : map.names) train[id] = id == 0 ? 0 : next++;
  y += "learning_map:\n";
  for (const auto& [id, t] : train) y += "  " + std::to_string(id) + ": " + std::to_string(t) + "\n";
  y += "learning_map_inv:\n";
  for (const auto& [id, t] : train) y += "  " + std::to_string(t) + ": " + std::to_string(id) + "\n";
  y += "learning_ignore:\n";
  for (const auto& [id, t] : train) y += "  " + std::to_string(t) + ": " + (t == 0 ? "True" : "False") + "\n";
  y += "split: # sequence numbers: autopilot 0, random 1, custom 2, trajectory 3\n  train:\n";
  for (int s : sequences) y += "    - " + std::to_string(s) + "\n";
  y += "  valid: []\n  test: []\n";
  return y;
}

}  // namespace

void export_semantickitti(const Dataset& d, const fs::path& out, const ExportOptions& options) {
  d.require("lidar", "semantickitti");
  const KittiMap map = kitti_map(d);
  const bool images = d.has("rgb");
  double period = 0;
  try {
    period = 1.0 / d.manifest.at("sensors").at("lidar").at("rotation_hz").get<double>();
  } catch (const nlohmann::json::exception&) {
  }
  if (!std::isfinite(period) || period <= 0 || period > 10)  // rotation_hz 0.1 ... 100, as the presets allow
    throw InputError((d.dir / "manifest.json").string() +
                     ": sensors.lidar.rotation_hz must be a number of 0.1 ... 100 for a dataset with lidar");
  std::map<std::string, size_t> frames_of;
  for (const DatasetFrame& f : d.frames) ++frames_of[f.sequence];
  std::map<std::string, std::string> times;
  std::set<int> numbers;
  for (const DatasetFrame& f : d.frames) {
    const fs::path seq = out / "sequences" / two_digits(sequence_number(f.sequence));
    if (numbers.insert(sequence_number(f.sequence)).second) {
      create_folder(seq / "velodyne");
      create_folder(seq / "labels");
      if (images) create_folder(seq / "image_2");
      require_dataset_file(d.dir / f.sequence / "calib.txt");
      require_dataset_file(d.dir / f.sequence / "poses.txt");
      check_kitti_calib(d.dir / f.sequence / "calib.txt");
      check_kitti_poses(d.dir / f.sequence / "poses.txt", frames_of[f.sequence]);
      for (const char* name : {"calib.txt", "poses.txt"}) place_file(d.dir / f.sequence / name, seq / name, options);
    }
    char line[32];
    std::snprintf(line, sizeof line, "%.6e\n", f.frame * period);
    times[f.sequence] += line;
  }
  for (const auto& [sequence, text] : times)
    write_file_atomic(out / "sequences" / two_digits(sequence_number(sequence)) / "times.txt", text);
  const std::vector<std::vector<uint32_t>> instances = sequence_instances(d);
  std::vector<std::map<int, uint64_t>> counts(d.frames.size());
  for_each_frame(d, [&](size_t i) {
    const DatasetFrame& f = d.frames[i];
    const fs::path seq = out / "sequences" / two_digits(sequence_number(f.sequence));
    char name[16];
    std::snprintf(name, sizeof name, "%06d", f.frame);
    write_labels(d, f, map, instances[i], seq / "labels" / (std::string(name) + ".label"), counts[i]);  // checks the scan too
    place_file(d.file(f, "lidar", "bin"), seq / "velodyne" / (std::string(name) + ".bin"), options);
    if (images) place_file(d.file(f, "rgb", "png"), seq / "image_2" / (std::string(name) + ".png"), options);
  });
  std::map<int, uint64_t> total;
  for (const auto& c : counts)
    for (const auto& [id, n] : c) total[id] += n;
  write_file_atomic(out / "semantic-kitti.yaml", label_yaml(map, total, numbers));
}

}  // namespace silva::io
