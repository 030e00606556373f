#pragma once
/// @file The trail (thesis 4.2): a pure function of seed + config, built once in setup. Its path
/// (world/trail_path.hpp) shapes the terrain, which carries it as an overlay (no mesh of its
/// own); here the terrain-following nav spline and the corridor queries of placement.
#include <memory>
#include <vector>

#include "core/config.hpp"
#include "world/nav_spline.hpp"
#include "world/terrain.hpp"
#include "world/trail_path.hpp"

namespace silva::world {

/// Margin beyond the trail's half width in which nothing grows (metres).
inline constexpr double kTrailMargin = 0.25;

/// The whole trail of a world.
struct Trail {
  bool enabled = false;                   ///< false: no trail (trail.enabled = false).
  double width = 1.5;                     ///< Full width (metres).
  std::shared_ptr<const TrailPath> path;  ///< Centre line and bed, shared with the terrain field (null: none).
  NavSpline nav;                          ///< Terrain-following centre line by arc length.
  /// Half width of the corridor where nothing grows: width/2 + kTrailMargin.
  double corridor_half_width() const { return 0.5 * width + kTrailMargin; }
};

/// The trail of a world whose terrain `field` was made from the same config (empty with
/// enabled = false when trail.enabled is false): its path and the nav spline on the terrain.
Trail build_trail(const Config& cfg, const TerrainField& field);

/// Indices k of centre-line segments [k, k+1] whose bounds, padded by `pad`, meet the box.
std::vector<uint32_t> trail_segments_near(const Trail& trail, double xmin, double ymin, double xmax, double ymax,
                                          double pad);

/// Horizontal distance from (x, y) to the nearest of the given centre-line segments (+inf if none).
double trail_distance(const Trail& trail, const std::vector<uint32_t>& segments, double x, double y);

}  // namespace silva::world
