// COCO panoptic export (CONTRACT.md "Export formats"): segment id = instance index · 256 + class id, the
// background role void (0); a tree is its trunk instance, canopy pixels are the stuff class tree_canopy. Thing
// segments covering fewer than ExportOptions::min_instance_area pixels of the frame are iscrowd 1.
#include <map>

#include "io/atomic_file.hpp"
#include "io/coco_common.hpp"
#include "io/export_formats.hpp"
#include "io/png_writer.hpp"

namespace silva::io {

namespace {

/// Writes frame `f`'s panoptic PNG and returns its annotation.
nlohmann::json panoptic_frame(const Dataset& d, const DatasetFrame& f, const std::filesystem::path& out,
                              const ExportOptions& options, const std::string& image_name, nlohmann::json& image) {
  const cv::Mat semantic = d.image(f, "semantic", CV_8UC1);
  const cv::Mat instance = d.image(f, "instance", CV_16UC1);
  const uint8_t void_id = d.ontology.id(Role::Background);
  bool has_instances[256] = {};
  for (int r = 0; r < kRoleCount; ++r)
    if (role_has_instances(Role(r))) has_instances[d.ontology.id(Role(r))] = true;
  const int w = semantic.cols, h = semantic.rows;
  std::vector<uint8_t> rgb(size_t(w) * h * 3);
  std::map<uint32_t, PixelBox> segments;
  uint32_t cached_id = 0;
  PixelBox* cached = nullptr;
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      const uint8_t c = semantic.at<uint8_t>(y, x);
      const uint32_t id = c == void_id ? 0 : uint32_t(instance.at<uint16_t>(y, x)) * 256u + c;
      uint8_t* px = &rgb[(size_t(y) * w + x) * 3];
      px[0] = uint8_t(id), px[1] = uint8_t(id >> 8), px[2] = uint8_t(id >> 16);
      if (!id) continue;
      if (id != cached_id || !cached) cached = &segments[id], cached_id = id;
      cached->add(x, y);
    }
  }
  write_file_atomic(out / "panoptic" / (f.stem() + ".png"), encode_png_rgb8(rgb, w, h));
  nlohmann::json infos = nlohmann::json::array();
  for (const auto& [id, s] : segments) {
    const uint8_t c = uint8_t(id & 255u);
    // A thing-class pixel without an instance cannot be told apart from its neighbours: a crowd region; so is a
    // thing too small to learn.
    const bool crowd = has_instances[c] && (id < 256u || s.area < options.min_instance_area);
    infos.push_back({{"id", id}, {"category_id", c}, {"iscrowd", crowd ? 1 : 0},
                     {"bbox", s.bbox()}, {"area", s.area}});
  }
  image = coco_image_entry(f, image_name, w, h);
  return {{"image_id", f.global_index}, {"file_name", f.stem() + ".png"}, {"segments_info", infos}};
}

}  // namespace

void export_coco_panoptic(const Dataset& d, const std::filesystem::path& out, const ExportOptions& options) {
  for (const char* type : {"rgb", "semantic", "instance"}) d.require(type, "coco-panoptic");
  create_folder(out / "images");
  create_folder(out / "panoptic");
  std::vector<nlohmann::json> images(d.frames.size()), annotations(d.frames.size());
  for_each_frame(d, [&](size_t i) {
    const DatasetFrame& f = d.frames[i];
    const std::string image_name = place_coco_image(d, f, out / "images", options);
    annotations[i] = panoptic_frame(d, f, out, options, image_name, images[i]);
  });
  write_json(out / "panoptic.json", {{"info", coco_info(d)},
                                     {"images", images},
                                     {"annotations", annotations},
                                     {"categories", coco_categories(d.ontology, false)}});
}

}  // namespace silva::io
