// COCO instances export (CONTRACT.md "Export formats"): one annotation per row of each frame's instance
// table, its mask as compressed RLE; a tree is its trunk instance (canopy pixels carry no instance). Instances
// covering fewer than ExportOptions::min_instance_area pixels of the frame are iscrowd 1.
#include "io/coco_common.hpp"
#include "io/export_formats.hpp"

namespace silva::io {

namespace {

/// The annotations of frame `f` (ids assigned later); instances under options.min_instance_area pixels are crowds.
std::vector<nlohmann::json> instance_annotations(const Dataset& d, const DatasetFrame& f, const ExportOptions& options,
                                                 const std::string& image_name, nlohmann::json& image) {
  const cv::Mat instance = d.image(f, "instance", CV_16UC1);
  const std::vector<InstanceEntry> table = read_instance_table(d.file(f, "instance", "json"));
  const int n = int(table.size());
  std::vector<PixelBox> boxes(table.size());
  for (int y = 0; y < instance.rows; ++y)
    for (int x = 0; x < instance.cols; ++x) {
      const int v = instance.at<uint16_t>(y, x);
      if (v && v <= n) boxes[size_t(v - 1)].add(x, y);
    }
  const auto runs = column_major_runs(instance, n);
  std::vector<nlohmann::json> annotations;
  for (const InstanceEntry& e : table) {
    const PixelBox& b = boxes[e.index - 1u];
    if (!b.area) continue;
    annotations.push_back({{"image_id", f.global_index},
                           {"category_id", e.class_id},
                           {"iscrowd", b.area < options.min_instance_area ? 1 : 0},
                           {"area", b.area},
                           {"bbox", b.bbox()},
                           {"segmentation", {{"size", {instance.rows, instance.cols}},
                                             {"counts", rle_string(runs[e.index - 1u])}}},
                           {"instance_id", e.instance_id}});
  }
  image = coco_image_entry(f, image_name, instance.cols, instance.rows);
  return annotations;
}

}  // namespace

void export_coco_instances(const Dataset& d, const std::filesystem::path& out, const ExportOptions& options) {
  for (const char* type : {"rgb", "instance"}) d.require(type, "coco-instances");
  create_folder(out / "images");
  std::vector<nlohmann::json> images(d.frames.size());
  std::vector<std::vector<nlohmann::json>> per_frame(d.frames.size());
  for_each_frame(d, [&](size_t i) {
    const DatasetFrame& f = d.frames[i];
    const std::string image_name = place_coco_image(d, f, out / "images", options);
    per_frame[i] = instance_annotations(d, f, options, image_name, images[i]);
  });
  nlohmann::json annotations = nlohmann::json::array();
  for (auto& frame : per_frame)
    for (auto& a : frame) {
      a["id"] = annotations.size() + 1;
      annotations.push_back(std::move(a));
    }
  write_json(out / "instances.json", {{"info", coco_info(d)},
                                      {"images", images},
                                      {"annotations", annotations},
                                      {"categories", coco_categories(d.ontology, true)}});
}

}  // namespace silva::io
