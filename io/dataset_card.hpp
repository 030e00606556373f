#pragma once
/// @file What `silva card` counts in a finished dataset: class pixels, instances and their sizes, a depth
/// histogram and the camera positions, read back from the dataset's own files.
#include <array>
#include <cstdint>
#include <set>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "core/lidar_point.hpp"
#include "io/dataset_reader.hpp"
#include "io/label_planes.hpp"

namespace silva::io {

/// Counts over every frame of a dataset.
struct CardCounts {
  uint64_t pixels = 0;                           ///< Pixels of the semantic images.
  std::array<uint64_t, 256> class_pixels{};      ///< Per class id, from the semantic PNGs.
  std::array<uint64_t, 256> class_instances{};   ///< Per class id: instance-table rows with pixels.
  static constexpr int kSizeBins = 24;           ///< Instance size bins: [2^k, 2^(k+1)) pixels.
  std::array<uint64_t, kSizeBins> instance_sizes{};  ///< Instances per size bin.
  static constexpr int kDepthBins = 33;          ///< Depth bins of 2 m over [0, 66) m.
  std::array<uint64_t, kDepthBins> depth{};      ///< Hit pixels per depth bin (depth PNG, millimetres).
  uint64_t depth_no_hit = 0;                     ///< Pixels with depth 0 (sky, beyond far).
  uint64_t lidar_points = 0;                     ///< LiDAR returns (lidar_labels files).
  std::array<uint64_t, 256> lidar_class_points{};  ///< LiDAR returns per class id.
  std::vector<Vec3d> positions;                  ///< Camera centre per frame (world, metres).
  std::vector<Vec3d> forwards;                   ///< Optical axis per frame (world).
  std::vector<int> sequence_of;                  ///< Per frame: index of its sequence in first-seen order.
};

/// Label counts some frames already have (made by the run that wrote them, from the images in memory),
/// so that the card need not read those frames' PNGs back.
struct KnownCounts {
  CardCounts totals;                                ///< Summed label counts of `frames` (no positions).
  std::set<std::pair<std::string, int>> frames;     ///< (sequence, frame) of the frames counted.
};

/// Adds `other`'s label counts (pixels, class pixels and instances, instance sizes, depth bins) to `into`.
void add_label_counts(CardCounts& into, const CardCounts& other);

/// One frame's label counts from its planes and LiDAR points: the numbers count_dataset reads from the frame's
/// files (semantic when `semantic`, the instance image when `instance`, depth when `depth`, the LiDAR labels
/// when `lidar`), without encoding or decoding.
CardCounts count_planes(const LabelPlanes& planes, std::span<const LidarPoint> lidar, const Ontology& ontology,
                        bool semantic, bool instance, bool depth, bool lidar_selected);

/// Counts every frame: the label counts of the frames in `known` from it, the others' from their semantic,
/// instance and depth PNGs (those the run wrote); the camera position of every frame from its camera file.
CardCounts count_dataset(const Dataset& dataset, const KnownCounts& known = {});

/// A bar chart as an RGB image (width x height, interleaved R, G, B): one bar per value, coloured, with a
/// label under each bar and the title on top; values are drawn as given (the caller scales them).
std::vector<uint8_t> bar_chart(const std::string& title, const std::vector<std::string>& labels,
                               const std::vector<double>& values, const std::vector<std::array<uint8_t, 3>>& colors,
                               int width, int height);

/// A top-down RGB image of the world (the class map under the cameras): row 0 is the north edge.
struct MapBackground {
  int width = 0, height = 0;     ///< Pixels.
  double x0 = 0, y1 = 0;         ///< World x of the left edge, y of the top edge (metres).
  double metres_per_pixel = 1;   ///< Ground sample distance.
  std::span<const uint8_t> rgb;  ///< width * height * 3 bytes, R, G, B.
};

/// A legend entry: a name and its colour.
using LegendEntry = std::pair<std::string, std::array<uint8_t, 3>>;

/// A top-down map (world X right, Y up) of camera positions with a short stroke along each view direction,
/// coloured by sequence: over `background` (framed to its extent) when given, else on white framed to the
/// cameras; with `legend` in a column on the right. An RGB image (`size` + 150 when there is a legend) x `size`.
std::vector<uint8_t> pose_map(const CardCounts& counts, const std::vector<std::array<uint8_t, 3>>& sequence_colors,
                              int size, const MapBackground* background, const std::vector<LegendEntry>& legend);

/// Width of pose_map's image.
int pose_map_width(int size, const std::vector<LegendEntry>& legend);

}  // namespace silva::io
