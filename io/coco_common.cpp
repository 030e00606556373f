#include "io/coco_common.hpp"

#include <map>

#include "io/run_folder.hpp"

namespace silva::io {

nlohmann::json coco_categories(const Ontology& ontology, bool things_only) {
  std::map<int, nlohmann::json> by_id;
  const uint8_t void_id = ontology.id(Role::Background);
  for (int r = 0; r < kRoleCount; ++r) {
    const OntologyClass& c = ontology.classes[size_t(r)];
    if (c.id == void_id) continue;
    const bool thing = role_has_instances(Role(r));
    auto it = by_id.find(c.id);
    if (it == by_id.end()) {
      by_id[c.id] = {{"id", c.id}, {"name", c.name}, {"supercategory", "forest"}, {"isthing", thing ? 1 : 0},
                     {"color", c.color}};
    } else if (thing) {
      it->second["isthing"] = 1;
    }
  }
  nlohmann::json categories = nlohmann::json::array();
  for (const auto& [id, c] : by_id)
    if (!things_only || c["isthing"] == 1) categories.push_back(c);
  return categories;
}

nlohmann::json coco_image_entry(const DatasetFrame& f, const std::string& file_name, int width, int height) {
  return {{"id", f.global_index}, {"file_name", file_name}, {"width", width}, {"height", height},
          {"sequence", f.sequence}, {"frame", f.frame}};
}

nlohmann::json coco_info(const Dataset& dataset) {
  return {{"description", "Silva dataset " + seed_folder_name(dataset.seed)},
          {"version", dataset.manifest.value("silva_version", "")},
          {"seed", dataset.seed}};
}

std::vector<std::vector<uint32_t>> column_major_runs(const cv::Mat& labels, int values) {
  std::vector<std::vector<uint32_t>> counts(static_cast<size_t>(values));
  std::vector<uint32_t> last(static_cast<size_t>(values), 0);  // position of each value's last run change
  const int w = labels.cols, h = labels.rows;
  uint32_t p = 0;
  uint16_t previous = 0;
  for (int x = 0; x < w; ++x) {
    for (int y = 0; y < h; ++y, ++p) {
      const uint16_t v = labels.at<uint16_t>(y, x);
      if (v == previous) continue;
      if (previous) {  // a run of ones of `previous` ends
        counts[previous - 1u].push_back(p - last[previous - 1u]);
        last[previous - 1u] = p;
      }
      if (v && v <= values) {  // a run of zeros of `v` ends
        counts[v - 1u].push_back(p - last[v - 1u]);
        last[v - 1u] = p;
      }
      previous = v <= values ? v : 0;
    }
  }
  for (size_t k = 0; k < counts.size(); ++k)
    if (p > last[k]) counts[k].push_back(p - last[k]);
  return counts;
}

std::string rle_string(const std::vector<uint32_t>& counts) {
  std::string s;
  for (size_t i = 0; i < counts.size(); ++i) {
    int64_t x = counts[i];
    if (i > 2) x -= int64_t(counts[i - 2]);
    bool more = true;
    while (more) {
      char c = char(x & 0x1f);
      x >>= 5;
      more = (c & 0x10) ? x != -1 : x != 0;
      if (more) c |= 0x20;
      s.push_back(char(c + 48));
    }
  }
  return s;
}

}  // namespace silva::io
