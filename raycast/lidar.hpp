#pragma once
/// @file A spinning LiDAR cast through the ray-cast scene: beams, columns, range noise, dropout and
/// intensity, seeded per ray, so a sweep is the same for any thread count.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "core/lidar_point.hpp"
#include "core/material.hpp"
#include "raycast/ray_scene.hpp"

namespace silva::raycast {

/// A LiDAR model (configs/lidar.toml `[lidar.presets.<name>]`).
struct LidarPreset {
  std::string name;                    ///< Preset name, e.g. "vlp16".
  std::vector<double> elevations_deg;  ///< Beam elevations, ascending; ring r fires at elevations_deg[r].
  int columns = 1800;                  ///< Firings per revolution (evenly spaced in azimuth).
  double rotation_hz = 10;             ///< Revolutions per second.
  double min_range = 0.5;              ///< Nearest return (metres).
  double max_range = 100;              ///< Farthest return (metres).
  double range_noise_m = 0.015;        ///< Standard deviation of the range noise (metres).
  double dropout = 0.005;              ///< Probability that a return is lost.
  double intensity_falloff = 0.005;    ///< Intensity attenuation per metre of range: exp(-falloff * range).
  double intensity_noise = 0.02;       ///< Standard deviation of the additive intensity noise.
};

/// The sensor's pose one revolution (1 / rotation_hz) after the sweep began, for a sensor that moves.
struct SweepEnd {
  Mat3d sensor_to_world = Mat3d::Identity();  ///< Orientation at the end of the sweep.
  Vec3d position = Vec3d::Zero();             ///< Origin at the end of the sweep.
};

/// Where a sweep is cast from and how its randomness is keyed.
struct SweepPose {
  Mat3d sensor_to_world = Mat3d::Identity();  ///< Columns: the sensor's x (forward), y (left), z (up) in the world.
  Vec3d position = Vec3d::Zero();             ///< Sensor origin in the world (at the sweep's start).
  uint64_t seed = 0;                          ///< World seed.
  uint64_t key = 0;                           ///< Sweep key (e.g. hash of sequence and frame).
  /// Motion distortion: the pose at the sweep's end. Column c then fires from the pose interpolated c / columns
  /// of the way (position linearly, orientation by slerp), and its points keep that firing pose's sensor
  /// coordinates. Empty: the sensor is still.
  std::optional<SweepEnd> end;
};

/// Unit direction of beam `ring`, column `column` in the sensor frame: the sweep starts facing
/// backwards (azimuth 180 degrees) and turns clockwise seen from above, as Velodyne and Ouster do.
Vec3d beam_direction(const LidarPreset& preset, int ring, int column);

/// Near-infrared (905 nm) reflectivity of a material, in [0, 1].
float nir_reflectivity(Material m);

/// Casts one sweep (every column, every beam) and returns its returns in firing order (column, then
/// ring), rays that hit nothing within range and dropped returns left out; each point in the sensor frame of
/// its column's firing pose (the sweep's pose when the sensor is still). `options.eye` is the
/// viewpoint of the ground-cover cut-off (the capture camera's).
std::vector<LidarPoint> cast_sweep(const RayScene& scene, const LidarPreset& preset, const SweepPose& pose,
                                   const CastOptions& options);

}  // namespace silva::raycast
