#pragma once
/// @file The output types of a capture set (CONTRACT.md `output.types`) and a selection of them.
#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace silva::io {

/// One kind of output image (its name is also its folder name).
enum class OutputType : uint8_t { Rgb, Semantic, SemanticColor, Instance, Depth, DepthExr, DepthPreview, Normal, Lidar };

/// Number of output types.
inline constexpr int kOutputTypeCount = 9;

/// Name / folder of an output type: "rgb", "semantic", "semantic_color", "instance", "depth",
/// "depth_exr", "depth_preview", "normal", "lidar" (a LiDAR sweep per frame: lidar/ and lidar_labels/).
const char* output_type_name(OutputType t);

/// Which output types a run writes.
struct OutputSelection {
  std::array<bool, kOutputTypeCount> enabled{};  ///< Indexed by OutputType.
  /// True if `t` is selected.
  bool has(OutputType t) const { return enabled[size_t(t)]; }
  /// Every output type.
  static OutputSelection all();
  /// Parses names (e.g. config `output.types`); InputError naming `key`, the bad value and the
  /// allowed names for an unknown or repeated one.
  static OutputSelection from_names(const std::vector<std::string>& names, const std::string& key = "output.types");
};

}  // namespace silva::io
