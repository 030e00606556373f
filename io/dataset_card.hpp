#pragma once
/// @file What `silva card` counts in a finished dataset: class pixels, instances and their sizes, a depth
/// histogram and the camera positions, read back from the dataset's own files.
#include <array>
#include <cstdint>
#include <vector>

#include "io/dataset_reader.hpp"

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
  std::vector<Vec3d> positions;                  ///< Camera centre per frame (world, metres).
  std::vector<Vec3d> forwards;                   ///< Optical axis per frame (world).
  std::vector<int> sequence_of;                  ///< Per frame: index of its sequence in first-seen order.
};

/// Reads every frame's semantic, instance and depth PNGs (those the run wrote) and camera file.
CardCounts count_dataset(const Dataset& dataset);

/// A bar chart as an RGB image (width x height, interleaved R, G, B): one bar per value, coloured, with a
/// label under each bar and the title on top; values are drawn as given (the caller scales them).
std::vector<uint8_t> bar_chart(const std::string& title, const std::vector<std::string>& labels,
                               const std::vector<double>& values, const std::vector<std::array<uint8_t, 3>>& colors,
                               int width, int height);

/// A top-down map (world X right, Y up) of camera positions with a short stroke along each view direction,
/// coloured by sequence, as an RGB image `size` x `size`.
std::vector<uint8_t> pose_map(const CardCounts& counts, const std::vector<std::array<uint8_t, 3>>& sequence_colors,
                              int size);

}  // namespace silva::io
