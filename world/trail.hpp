#pragma once
/// @file The trail (thesis 4.2): a pure function of seed + config, built once in setup.
/// Seeded walk of control points from the origin, reflected inside the capture region ->
/// centripetal Catmull-Rom spline resampled x50 -> draped on the terrain with an odd number of
/// symmetric lateral samples -> per-chunk trail mesh pieces + terrain-following nav spline.
#include <vector>

#include "core/config.hpp"
#include "core/mesh.hpp"
#include "world/nav_spline.hpp"
#include "world/terrain.hpp"

namespace silva::world {

/// Samples per control-point segment when resampling the spline (thesis: x50).
inline constexpr int kTrailResample = 50;
/// Lateral samples across the trail (odd, symmetric about the centre line).
inline constexpr int kTrailLateralSamples = 5;
/// Height of the trail surface above the terrain mesh (metres).
inline constexpr float kTrailLift = 0.04f;
/// Margin beyond the trail's half width in which nothing grows (metres).
inline constexpr double kTrailMargin = 0.25;
/// Distance from the capture region's edge at which the walk is reflected (metres).
inline constexpr double kTrailEdgeInset = 32.0;

/// The whole trail of a world.
struct Trail {
  bool enabled = false;                  ///< false: no trail (trail.enabled = false).
  double width = 1.5;                    ///< Full width (metres).
  std::vector<Eigen::Vector2d> control;  ///< Control points of the seeded walk (xy).
  std::vector<Eigen::Vector2d> centre;   ///< Resampled centre line (xy).
  std::vector<Vec3f> lateral;            ///< Draped vertices, row-major: centre.size() x kTrailLateralSamples.
  NavSpline nav;                         ///< Terrain-following centre line by arc length.
  /// Half width of the corridor where nothing grows: width/2 + kTrailMargin.
  double corridor_half_width() const { return 0.5 * width + kTrailMargin; }
};

/// Builds the trail of a world (empty with enabled = false when trail.enabled is false).
/// Throws InputError when the capture region is too small for the reflected walk.
Trail build_trail(const Config& cfg, const TerrainField& field);

/// Control points of the seeded walk: from the origin, control_spacing apart, reflected at
/// +-(extent/2 - kTrailEdgeInset).
std::vector<Eigen::Vector2d> trail_control_points(const Config& cfg);

/// Trail mesh piece of one chunk: the segments whose centre-line midpoint lies in the chunk.
/// Role Trail, material Trail; uv.x in [0, 1] across the width, uv.y = arc length (metres).
Mesh build_trail_mesh(const Trail& trail, double chunk_size, ChunkCoord coord);

/// Indices k of centre-line segments [k, k+1] whose bounds, padded by `pad`, meet the box.
std::vector<uint32_t> trail_segments_near(const Trail& trail, double xmin, double ymin, double xmax, double ymax,
                                          double pad);

/// Horizontal distance from (x, y) to the nearest of the given centre-line segments (+inf if none).
double trail_distance(const Trail& trail, const std::vector<uint32_t>& segments, double x, double y);

}  // namespace silva::world
