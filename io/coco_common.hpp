#pragma once
/// @file What the two COCO exports share: categories, image entries and COCO's compressed RLE.
#include <algorithm>
#include <cstdint>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>
#include <opencv2/core.hpp>

#include "io/dataset_reader.hpp"

namespace silva::io {

/// Pixel count and bounding box of one segment or instance.
struct PixelBox {
  int64_t area = 0;                                     ///< Pixels added.
  int x0 = INT32_MAX, y0 = INT32_MAX, x1 = -1, y1 = -1;  ///< Inclusive pixel extents.
  /// Counts pixel (x, y).
  void add(int x, int y) {
    ++area;
    x0 = std::min(x0, x), y0 = std::min(y0, y), x1 = std::max(x1, x), y1 = std::max(y1, y);
  }
  /// COCO bbox [x, y, width, height] in pixels.
  nlohmann::json bbox() const { return {x0, y0, x1 - x0 + 1, y1 - y0 + 1}; }
};

/// COCO categories: one per distinct ontology class id but the background role's (void), with
/// isthing = 1 when a role of that id has instances; `things_only` keeps those alone.
nlohmann::json coco_categories(const Ontology& ontology, bool things_only);

/// The "images" entry of frame `f`: id = global index, file_name (the image as placed), width, height,
/// plus Silva's sequence and frame.
nlohmann::json coco_image_entry(const DatasetFrame& f, const std::string& file_name, int width, int height);

/// The COCO "info" object naming the source dataset.
nlohmann::json coco_info(const Dataset& dataset);

/// Per-frame COCO RLE of every non-zero value of a 16-bit label image: runs over the image in column-major
/// order, starting with a run of zeros. result[k] holds the counts of value k + 1.
std::vector<std::vector<uint32_t>> column_major_runs(const cv::Mat& labels, int values);

/// COCO's compressed RLE string of run counts (pycocotools' rleToString).
std::string rle_string(const std::vector<uint32_t>& counts);

}  // namespace silva::io
