#pragma once
/// @file `silva verify`'s per-pixel comparison: a frame's label, depth and normal files against the
/// ray caster's hits through the same pixel centres, tallied per class, interior and silhouette apart.
#include <array>
#include <cstdint>
#include <map>
#include <span>
#include <utility>
#include <vector>

#include "core/ontology.hpp"
#include "core/types.hpp"
#include "raycast/ray_scene.hpp"

namespace silva::app {

/// Counts of non-negative values in logarithmic bins (50 per decade from 1e-9 to 1e3), for
/// percentiles of error distributions that merge across frames in any order.
struct ErrorHistogram {
  static constexpr int kPerDecade = 50;        ///< Bins per factor of 10.
  static constexpr int kDecades = 12;          ///< Decades from kLowest up.
  static constexpr double kLowest = 1e-9;      ///< Values below go to bin 0 (exact zeros included).
  std::array<uint64_t, kPerDecade * kDecades + 2> bins{};  ///< [0]: below kLowest; last: kLowest·10^12 and up.
  uint64_t count = 0;                          ///< Values added.
  double max = 0;                              ///< Largest value added.
  /// Adds one value (negative values count as 0).
  void add(double value);
  /// Adds every value of `other`.
  void merge(const ErrorHistogram& other);
  /// The q-quantile (0 < q ≤ 1) as the upper edge of its bin, never above max (0 when empty).
  double quantile(double q) const;
  /// Values at or below `limit` (exact up to the bin holding `limit`, which counts whole).
  uint64_t at_most(double limit) const;
};

/// What the dataset holds for one frame, per pixel (row-major).
struct FrameTruth {
  int width = 0;                  ///< Pixels across.
  int height = 0;                 ///< Pixels down.
  std::vector<uint8_t> semantic;  ///< Class ids (semantic PNG).
  std::vector<uint32_t> instance; ///< Packed instance id of each pixel (0 = none); empty when not written.
  std::vector<float> depth;       ///< Metres along the optical axis, 0 = no hit.
  double depth_step = 0;          ///< Quantisation step of `depth` (0.001 for the mm PNG, 0 for EXR).
  std::vector<Vec3f> normal;      ///< World normal (decoded from the PNG), zero = no hit; empty when not written.
};

/// Per-class pixel counts: how many pixels of the dataset's class the ray caster gave the same class.
struct ClassCounts {
  std::array<uint64_t, 256> pixels{};  ///< Pixels whose semantic PNG holds the class.
  std::array<uint64_t, 256> agree{};   ///< Of those, pixels the ray caster gives the same class.
  /// Sums over all classes: {pixels, agree}.
  std::pair<uint64_t, uint64_t> total() const;
};

/// One pixel where the files and the ray caster disagree, for the report.
struct PixelDisagreement {
  int x = 0, y = 0;          ///< Pixel.
  uint8_t file_class = 0;    ///< Semantic PNG class.
  uint8_t ray_class = 0;     ///< Ray caster's class.
  float file_depth = 0;      ///< Depth file (m, 0 = no hit).
  float ray_depth = 0;       ///< Ray caster's depth (m, 0 = no hit).
  bool interior = false;     ///< The pixel's 3x3 neighbourhood holds one class.
};

/// Tolerances of the comparison.
struct CompareOptions {
  double depth_tolerance = 0.001;  ///< Relative depth error accepted (0.1 %).
  size_t examples = 8;             ///< Disagreements kept per frame (the largest depth errors first).
};

/// Everything counted over the compared pixels of one or more frames.
struct VerifyTally {
  ClassCounts interior;             ///< Pixels whose 3x3 neighbourhood in the semantic PNG holds one class.
  ClassCounts silhouette;           ///< The other pixels.
  uint64_t instance_pixels = 0;     ///< Interior pixels compared for instances (instance images written).
  uint64_t instance_agree = 0;      ///< Of those, pixels with the same packed instance id.
  uint64_t depth_hit = 0;           ///< Pixels where the file or the ray caster (or both) hit a surface.
  uint64_t depth_within = 0;        ///< Of those, both hit and the depths agree within the tolerance.
  uint64_t depth_only_file = 0;     ///< The file holds a depth, the ray caster hit nothing.
  uint64_t depth_only_ray = 0;      ///< The ray caster hit a surface, the file holds no depth.
  std::array<uint64_t, 256> depth_hit_by_class{};     ///< depth_hit by semantic PNG class.
  std::array<uint64_t, 256> depth_within_by_class{};  ///< depth_within by semantic PNG class.
  ErrorHistogram depth_error;       ///< |z_ray − z_file| / z_file where both hit.
  ErrorHistogram normal_error_deg;  ///< Angle between the normals (degrees) where both hit the same class
                                    ///< at depths within the tolerance.
  std::map<std::pair<uint8_t, uint8_t>, uint64_t> confusion;  ///< (file class, ray class) -> interior pixels.
  std::vector<PixelDisagreement> examples;  ///< Up to CompareOptions::examples (one frame's; never merged).
  /// Adds `other`'s counts (not its examples).
  void merge(const VerifyTally& other);
};

/// True when pixel p's 3x3 neighbourhood (clipped to the image) holds one class in `semantic`.
bool interior_pixel(std::span<const uint8_t> semantic, int width, int height, uint32_t p);

/// Compares `truth` at `pixels` (indices y * width + x) with the ray caster's `hits` there; `ontology`
/// gives the class ids of the hits' roles.
VerifyTally compare_frame(const FrameTruth& truth, std::span<const uint32_t> pixels,
                          std::span<const raycast::RayHit> hits, const Ontology& ontology,
                          const CompareOptions& options);

}  // namespace silva::app
