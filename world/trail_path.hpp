#pragma once
/// @file The trail's path on the ground (thesis 4.2): the seeded walk of control points from the
/// origin, reflected inside the capture region -> centripetal Catmull-Rom centre line resampled
/// x50, a segment grid for nearest-point queries, and the trail bed: the natural terrain height
/// along the centre line, smoothed, that the terrain is flattened to across the trail.
#include <cstdint>
#include <functional>
#include <limits>
#include <vector>

#include "core/config.hpp"
#include "core/types.hpp"

namespace silva::world {

/// Samples per control-point segment when resampling the spline (thesis: x50).
inline constexpr int kTrailResample = 50;
/// Distance from the capture region's edge at which the walk is reflected (metres).
inline constexpr double kTrailEdgeInset = 32.0;
/// Width of the shoulder beyond the trail edge over which the terrain blends from the flattened
/// trail bed back to its natural height (metres); also how far the edge coordinate reaches.
inline constexpr double kTrailShoulder = 1.0;
/// How much deeper the trail's centre is worn than its edges (metres, parabolic across).
inline constexpr double kTrailWear = 0.03;
/// Half length of the window over which the bed height is averaged along the trail (metres).
inline constexpr double kTrailBedSmoothing = 2.0;

/// Distance beyond reach() within which nearest_trail_point still answers (metres), so that the
/// along-trail coordinate is continuous over every terrain triangle that touches the shoulder.
inline constexpr double kTrailQuerySlack = 1.0;

/// The nearest point of the trail's centre line to a ground point.
struct TrailPoint {
  double distance = std::numeric_limits<double>::infinity();  ///< Horizontal distance (inf: none near).
  double along = 0;  ///< Arc length (xy) of the nearest centre-line point, metres.
  double bed = 0;    ///< Bed height at the nearest centre-line point, metres.
};

/// The trail's path: centre line, bed heights and the segment grid (immutable once built).
struct TrailPath {
  double half_width = 0.75;              ///< Half the trail width (metres).
  std::vector<Eigen::Vector2d> control;  ///< Control points of the seeded walk (xy).
  std::vector<Eigen::Vector2d> centre;   ///< Resampled centre line (xy).
  std::vector<double> along;             ///< Arc length (xy) at each centre sample.
  std::vector<double> bed;               ///< Bed height at each centre sample (metres).
  double grid_x0 = 0, grid_y0 = 0;       ///< Lower corner of the segment grid (metres).
  double cell = 4.0;                     ///< Grid cell edge (metres).
  int grid_nx = 0, grid_ny = 0;          ///< Grid cells across and down.
  std::vector<uint32_t> cell_start;      ///< CSR offsets into cell_segments, grid_nx*grid_ny + 1 entries.
  std::vector<uint32_t> cell_segments;   ///< Segments k ([k, k+1]) within query_radius() of each cell.
  /// Distance from the centre line up to which the trail shapes the terrain: half width + shoulder.
  double reach() const { return half_width + kTrailShoulder; }
  /// Distance from the centre line within which nearest_trail_point answers.
  double query_radius() const { return reach() + kTrailQuerySlack; }
};

/// Control points of the seeded walk: from the origin, control_spacing apart, reflected at
/// +-(extent/2 - kTrailEdgeInset). Throws InputError when the capture region is too small.
std::vector<Eigen::Vector2d> trail_control_points(const Config& cfg);

/// Builds the path of cfg's trail; `natural_height` is the terrain height before shaping.
TrailPath make_trail_path(const Config& cfg, const std::function<double(double, double)>& natural_height);

/// Nearest centre-line point to (x, y) if it lies within path.query_radius(), else distance = inf.
TrailPoint nearest_trail_point(const TrailPath& path, double x, double y);

/// Ground height at distance `d` from the centre line: `natural` pulled to the worn bed inside
/// the trail, blended back over the shoulder (C1 smooth), unchanged beyond reach().
double shaped_height(const TrailPath& path, const TrailPoint& p, double natural);

}  // namespace silva::world
