// Cityscapes export (CONTRACT.md "Export formats"): city = the seed, file stem <seed>_<sequence>_<frame>;
// labelIds are Silva class ids, instanceIds = class id · 1000 + k (k = 0, 1, ... the frame's instances of
// that class in ascending instance_id order), the class id alone for stuff and canopy pixels.
#include "core/error.hpp"
#include "io/atomic_file.hpp"
#include "io/export_formats.hpp"
#include "io/ontology_file.hpp"
#include "io/png_writer.hpp"
#include "io/run_folder.hpp"

namespace silva::io {

namespace {

/// Cityscapes instance id of each instance index 1..n (0 unused) of one frame.
std::vector<uint16_t> cityscapes_ids(const std::vector<InstanceEntry>& table, const std::filesystem::path& source) {
  std::vector<uint16_t> ids(table.size() + 1, 0);
  int per_class[256] = {};
  for (const InstanceEntry& e : table) {
    const int k = per_class[e.class_id]++;
    const int id = e.class_id * 1000 + k;
    if (k > 999 || id > 65535)
      throw InputError(source.string() + ": instance " + std::to_string(e.instance_id) + " of class " +
                       std::to_string(e.class_id) + " has no Cityscapes id (class*1000 + k must stay below 65536 "
                       "with k < 1000)");
    ids[e.index] = uint16_t(id);
  }
  return ids;
}

/// Writes frame `f`'s ground truth into `gt` and places its RGB into `left`.
void cityscapes_frame(const Dataset& d, const DatasetFrame& f, const std::string& city,
                      const std::filesystem::path& left, const std::filesystem::path& gt, const ExportOptions& options) {
  const std::string stem = city + "_" + f.stem();
  place_file(d.file(f, "rgb", "png"), left / (stem + "_leftImg8bit.png"), options);
  place_file(d.file(f, "semantic", "png"), gt / (stem + "_gtFine_labelIds.png"), options);
  const cv::Mat semantic = read_image(d.file(f, "semantic", "png"), CV_8UC1);
  const cv::Mat instance = read_image(d.file(f, "instance", "png"), CV_16UC1, semantic);
  const std::vector<uint16_t> ids = cityscapes_ids(read_instance_table(d.file(f, "instance", "json")),
                                                   d.file(f, "instance", "json"));
  const int w = semantic.cols, h = semantic.rows;
  std::vector<uint16_t> out(size_t(w) * h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const uint16_t v = instance.at<uint16_t>(y, x);
      out[size_t(y) * w + x] = v && v < ids.size() ? ids[v] : semantic.at<uint8_t>(y, x);
    }
  write_file_atomic(gt / (stem + "_gtFine_instanceIds.png"), encode_png_grey16(out, w, h));
  if (d.has("semantic_color")) {
    place_file(d.file(f, "semantic_color", "png"), gt / (stem + "_gtFine_color.png"), options);
    return;
  }
  std::array<std::array<uint8_t, 3>, 256> colors{};
  for (int r = 0; r < kRoleCount; ++r) colors[d.ontology.id(Role(r))] = d.ontology.color(Role(r));
  std::vector<uint8_t> rgb(size_t(w) * h * 3);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const auto& c = colors[semantic.at<uint8_t>(y, x)];
      std::copy(c.begin(), c.end(), &rgb[(size_t(y) * w + x) * 3]);
    }
  write_file_atomic(gt / (stem + "_gtFine_color.png"), encode_png_rgb8(rgb, w, h));
}

}  // namespace

void export_cityscapes(const Dataset& d, const std::filesystem::path& out, const ExportOptions& options) {
  for (const char* type : {"rgb", "semantic", "instance"}) d.require(type, "cityscapes");
  const std::string city = seed_folder_name(d.seed);
  const std::filesystem::path left = out / "leftImg8bit" / "train" / city, gt = out / "gtFine" / "train" / city;
  create_folder(left);
  create_folder(gt);
  for_each_frame(d, [&](size_t i) { cityscapes_frame(d, d.frames[i], city, left, gt, options); });
  write_file_atomic(out / "ontology.json", ontology_json(d.ontology));
}

}  // namespace silva::io
