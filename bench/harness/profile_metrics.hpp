#pragma once
/// @file Measures of a placed world that `silva profile placement` reports: nearest-neighbour
/// distance distributions, cover of discs on a grid, crown radii of assets.
#include <cstdint>
#include <optional>
#include <vector>

#include <Eigen/Core>

#include "assets/library.hpp"

namespace silva::bench {

/// Distribution of nearest-neighbour distances (metres, nearest-rank percentiles).
struct NearestStats {
  double min = 0, p10 = 0, median = 0, p90 = 0;  ///< Metres.
};

/// Horizontal distance from each point to its nearest other point, summarised; none for fewer
/// than 2 points. Exact (grid search), O(n) for spread-out points.
std::optional<NearestStats> nearest_neighbours(const std::vector<Eigen::Vector2d>& points);

/// The q-quantile (0..1) of sorted values by nearest rank: values[floor(q * (n - 1))].
double nearest_rank(const std::vector<double>& sorted, double q);

/// A disc on the ground: centre and radius, metres.
struct Disc {
  Eigen::Vector2d centre;  ///< (x, y).
  double radius = 0;       ///< Metres.
};

/// A square grid over a set of chunks that marks which cells each of up to 8 layers covers.
class CoverGrid {
 public:
  /// Cells of side `cell` metres over chunks [i0, i1] x [j0, j1] of side `chunk_size`; only cells in
  /// chunks of `inside` (row-major over that range, i fastest) count.
  CoverGrid(int i0, int j0, int i1, int j1, double chunk_size, double cell, std::vector<bool> inside);
  /// Marks the cells whose centre lies in `disc` on `layer` (0..7).
  void add(const Disc& disc, int layer);
  /// Percentage (0..100) of counted cells covered on `layer`.
  double percent(int layer) const;

 private:
  double x0_, y0_, cell_, chunk_size_;
  int i0_, j0_, chunks_x_, chunks_y_, nx_, ny_;
  std::vector<bool> inside_;
  std::vector<uint8_t> bits_;
  uint64_t counted_ = 0;
};

/// Radius of an asset's crown seen from above: the farthest horizontal distance from its origin of
/// a vertex of its canopy parts (tree_canopy), or of any part when it has none; lods[0], unscaled.
double crown_radius(const assets::Asset& asset);

}  // namespace silva::bench
