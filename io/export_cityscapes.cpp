// Cityscapes export (CONTRACT.md "Export formats"): city = the seed, file stem <seed>_<sequence>_<frame>, in the
// split folder ExportOptions::cityscapes_split; labelIds are Silva class ids (not Cityscapes' own ids),
// labelTrainIds the train ids of label_train_ids.json (the classes but the background's, in id order, from 0;
// the background 255, ignored), instanceIds = class id · 1000 + k (k = 0, 1, ... the frame's instances of that
// class in ascending instance_id order), the class id alone for stuff and canopy pixels; polygons.json the
// outlines of every region (larger first) with the image size the loaders read.
#include <algorithm>
#include <array>

#include <opencv2/imgproc.hpp>

#include "core/error.hpp"
#include "io/atomic_file.hpp"
#include "io/coco_common.hpp"
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

/// Train id of every Silva class id: the ontology's class ids but the background role's, ascending, numbered from 0;
/// 255 (ignored) for the background and for ids no class uses.
std::array<uint8_t, 256> train_ids(const Ontology& ontology) {
  std::array<bool, 256> used{};
  for (const OntologyClass& c : ontology.classes) used[c.id] = true;
  used[ontology.id(Role::Background)] = false;
  std::array<uint8_t, 256> ids;
  ids.fill(255);
  uint8_t next = 0;
  for (int id = 0; id < 256; ++id)
    if (used[size_t(id)]) ids[size_t(id)] = next++;
  return ids;
}

/// label_train_ids.json: each Silva class id's train id and name, and the ignore value.
nlohmann::json train_ids_json(const Ontology& ontology) {
  const std::array<uint8_t, 256> ids = train_ids(ontology);
  nlohmann::json classes = nlohmann::json::array();
  std::array<bool, 256> listed{};
  for (const OntologyClass& c : ontology.classes) {
    if (listed[c.id]) continue;
    listed[c.id] = true;
    classes.push_back({{"id", c.id}, {"name", c.name}, {"train_id", ids[c.id]}});
  }
  return {{"ignore_train_id", 255}, {"classes", classes}};
}

/// One outline of polygons.json: its label, its points (frame pixels) and the area it encloses.
struct Outline {
  std::string label;              ///< Class name.
  std::vector<cv::Point> points;  ///< The outer contour.
  double area = 0;                ///< Area enclosed (pixels), for the drawing order.
};

/// Outer outlines of the pixels where `mask` (a window of the frame at `origin`) is non-zero, one per connected
/// region, appended to `outlines`.
void add_outlines(const cv::Mat& mask, cv::Point origin, const std::string& label, std::vector<Outline>& outlines) {
  std::vector<std::vector<cv::Point>> contours;
  cv::findContours(mask, contours, cv::RETR_EXTERNAL, cv::CHAIN_APPROX_SIMPLE, origin);
  for (std::vector<cv::Point>& contour : contours) {
    const double area = cv::contourArea(contour);
    outlines.push_back({label, std::move(contour), area});
  }
}

/// A box's pixels as an OpenCV rectangle (empty when it holds none).
cv::Rect rect_of(const PixelBox& b) { return b.area ? cv::Rect(b.x0, b.y0, b.x1 - b.x0 + 1, b.y1 - b.y0 + 1) : cv::Rect(); }

/// polygons.json of one frame: image size and the outlines of every class's stuff regions (the background's too)
/// and of every instance, labelled with the class names, larger enclosed areas first: drawn in order, as the
/// Cityscapes tools draw them, a region inside another (a patch of sky in a crown) lands on top of it.
nlohmann::json polygons_json(const Ontology& ontology, const cv::Mat& semantic, const cv::Mat& instance,
                             const std::vector<InstanceEntry>& table) {
  std::array<std::string, 256> names;
  for (const OntologyClass& c : ontology.classes)
    if (names[c.id].empty()) names[c.id] = c.name;
  std::array<PixelBox, 256> stuff;
  std::vector<PixelBox> things(table.size() + 1);
  for (int y = 0; y < semantic.rows; ++y)
    for (int x = 0; x < semantic.cols; ++x) {
      const uint16_t k = instance.at<uint16_t>(y, x);
      if (k) {
        if (k < things.size()) things[k].add(x, y);
      } else {
        stuff[semantic.at<uint8_t>(y, x)].add(x, y);
      }
    }
  std::vector<Outline> outlines;
  for (int id = 0; id < 256; ++id) {
    const cv::Rect r = rect_of(stuff[size_t(id)]);
    if (!r.empty()) add_outlines((semantic(r) == id) & (instance(r) == 0), r.tl(), names[size_t(id)], outlines);
  }
  for (const InstanceEntry& e : table) {
    const cv::Rect r = rect_of(things[e.index]);
    if (!r.empty()) add_outlines(instance(r) == int(e.index), r.tl(), names[e.class_id], outlines);
  }
  std::stable_sort(outlines.begin(), outlines.end(), [](const Outline& a, const Outline& b) { return a.area > b.area; });
  nlohmann::json objects = nlohmann::json::array();
  for (const Outline& o : outlines) {
    nlohmann::json polygon = nlohmann::json::array();
    for (const cv::Point& p : o.points) polygon.push_back({p.x, p.y});
    objects.push_back({{"label", o.label}, {"polygon", polygon}});
  }
  return {{"imgHeight", semantic.rows}, {"imgWidth", semantic.cols}, {"objects", objects}};
}

/// Writes frame `f`'s ground truth into `gt` and places its RGB into `left`.
void cityscapes_frame(const Dataset& d, const DatasetFrame& f, const std::string& city,
                      const std::filesystem::path& left, const std::filesystem::path& gt, const ExportOptions& options) {
  const std::string stem = city + "_" + f.stem();
  place_file(d.file(f, "rgb", "png"), left / (stem + "_leftImg8bit.png"), options);
  place_file(d.file(f, "semantic", "png"), gt / (stem + "_gtFine_labelIds.png"), options);
  const cv::Mat semantic = d.image(f, "semantic", CV_8UC1);
  const cv::Mat instance = d.image(f, "instance", CV_16UC1);
  const std::vector<InstanceEntry> table = read_instance_table(d.file(f, "instance", "json"));
  const std::vector<uint16_t> ids = cityscapes_ids(table, d.file(f, "instance", "json"));
  const int w = semantic.cols, h = semantic.rows;
  const std::array<uint8_t, 256> train = train_ids(d.ontology);
  std::vector<uint8_t> train_pixels(size_t(w) * h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) train_pixels[size_t(y) * w + x] = train[semantic.at<uint8_t>(y, x)];
  write_file_atomic(gt / (stem + "_gtFine_labelTrainIds.png"), encode_png_grey8(train_pixels, w, h));
  write_json(gt / (stem + "_gtFine_polygons.json"), polygons_json(d.ontology, semantic, instance, table));
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
  const std::string& split = options.cityscapes_split;
  if (split != "train" && split != "val" && split != "test")
    throw InputError("--split: unknown split '" + split + "' (allowed: train, val, test)");
  const std::filesystem::path left = out / "leftImg8bit" / split / city, gt = out / "gtFine" / split / city;
  create_folder(left);
  create_folder(gt);
  for_each_frame(d, [&](size_t i) { cityscapes_frame(d, d.frames[i], city, left, gt, options); });
  write_file_atomic(out / "ontology.json", ontology_json(d.ontology));
  write_json(out / "label_train_ids.json", train_ids_json(d.ontology));
}

}  // namespace silva::io
