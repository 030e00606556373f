/// @file The LiDAR sensor model (see lidar.hpp).
#include "raycast/lidar.hpp"

#include <algorithm>
#include <cmath>

#include <Eigen/Geometry>

#include "core/rng.hpp"

namespace silva::raycast {

namespace {
constexpr double kPi = 3.14159265358979323846;
/// Columns per block of the cast order: one ray-caster packet of a ring.
constexpr size_t kPacketColumns = 16;

/// Elevation of beam `ring` (radians).
double elevation_rad(const LidarPreset& preset, int ring) { return preset.elevations_deg[size_t(ring)] * kPi / 180.0; }

/// Azimuth of column `column` (radians): 180 degrees at column 0, turning clockwise.
double azimuth_rad(const LidarPreset& preset, int column) {
  return kPi - 2.0 * kPi * double(column) / double(preset.columns);
}

/// The unit direction of elevation and azimuth given by their cosines and sines.
Vec3d direction_of(double cos_elevation, double sin_elevation, double cos_azimuth, double sin_azimuth) {
  return {cos_elevation * cos_azimuth, cos_elevation * sin_azimuth, sin_elevation};
}

/// The cosines and sines of a preset's elevations and azimuths, so a sweep calls no trigonometry per ray.
struct BeamAngles {
  std::vector<double> cos_elevation, sin_elevation, cos_azimuth, sin_azimuth;  ///< By ring, by column.
  explicit BeamAngles(const LidarPreset& preset) {
    for (int r = 0; r < int(preset.elevations_deg.size()); ++r) {
      cos_elevation.push_back(std::cos(elevation_rad(preset, r)));
      sin_elevation.push_back(std::sin(elevation_rad(preset, r)));
    }
    for (int c = 0; c < preset.columns; ++c) {
      cos_azimuth.push_back(std::cos(azimuth_rad(preset, c)));
      sin_azimuth.push_back(std::sin(azimuth_rad(preset, c)));
    }
  }
  /// beam_direction(preset, ring, column), bit for bit.
  Vec3d direction(size_t ring, size_t column) const {
    return direction_of(cos_elevation[ring], sin_elevation[ring], cos_azimuth[column], sin_azimuth[column]);
  }
};

}  // namespace

Vec3d beam_direction(const LidarPreset& preset, int ring, int column) {
  const double elevation = elevation_rad(preset, ring), azimuth = azimuth_rad(preset, column);
  return direction_of(std::cos(elevation), std::sin(elevation), std::cos(azimuth), std::sin(azimuth));
}

float nir_reflectivity(Material m) {
  switch (m) {
    case Material::Needles: case Material::Leaves: case Material::Grass: case Material::Fern:
    case Material::ShrubLeaves: case Material::NeedlesSpruce: case Material::NeedlesPine:
    case Material::NeedlesLarch: case Material::LeavesBeech: case Material::LeavesBirch: case Material::LeavesOak:
    case Material::Herb: case Material::SpringLeaves:
      return 0.55f;  // green foliage reflects strongly in the near infrared
    case Material::Petals:
      return 0.6f;
    case Material::Moss:
      return 0.45f;
    case Material::AutumnLeaves: case Material::AutumnNeedles: case Material::LeafLitter:
      return 0.4f;
    case Material::BarkBirch: case Material::BarkBeech: case Material::BrokenWood: case Material::Wood:
      return 0.45f;
    case Material::Rock:
      return 0.35f;
    case Material::Ground: case Material::Trail: case Material::Soil:
      return 0.25f;
    default:
      return 0.3f;  // bark, dead wood, bare twigs
  }
}

std::vector<LidarPoint> cast_sweep(const RayScene& scene, const LidarPreset& preset, const SweepPose& pose,
                                   const CastOptions& options) {
  const size_t rings = preset.elevations_deg.size(), columns = size_t(preset.columns);
  const size_t n = rings * columns;
  std::vector<Mat3d> column_to_world(columns, pose.sensor_to_world);
  std::vector<Vec3d> column_origin(columns, pose.position);
  if (pose.end) {
    const Eigen::Quaterniond q0(pose.sensor_to_world), q1(pose.end->sensor_to_world);
    for (size_t c = 1; c < columns; ++c) {
      const double f = double(c) / double(columns);
      column_to_world[c] = q0.slerp(f, q1).toRotationMatrix();
      column_origin[c] = pose.position + f * (pose.end->position - pose.position);
    }
  }
  // Cast order: blocks of kPacketColumns neighbouring columns, ring by ring, so that a packet of the
  // caster holds one beam's rays a fraction of a degree apart (16 beams of one column spread over
  // several degrees and traverse far less coherently). Firing order i = column * rings + ring.
  const auto firing = [&](size_t k) {
    const size_t block = k / (kPacketColumns * rings), first_column = block * kPacketColumns;
    const size_t width = std::min(kPacketColumns, columns - first_column);
    const size_t within = k - block * kPacketColumns * rings;
    return (first_column + within % width) * rings + within / width;
  };
  const BeamAngles beams(preset);
  std::vector<Mat3d> world_to_column(columns);
  for (size_t c = 0; c < columns; ++c) world_to_column[c] = column_to_world[c].transpose();
  LidarPoint none;
  none.range = -1.0f;  // a kept return has range >= min_range >= 0
  std::vector<LidarPoint> points(n, none);  // a slot per firing; the empty ones are squeezed out at the end
  const auto make = [&](size_t k) {
    const size_t i = firing(k), c = i / rings;
    Ray ray;
    ray.origin = column_origin[c];
    ray.direction = column_to_world[c] * beams.direction(i % rings, c);
    ray.t_near = preset.min_range;
    ray.t_far = preset.max_range;
    return ray;
  };
  const auto take = [&](size_t k, const Ray& ray, const RayHit& h) {
    if (!h.hit) return;
    const size_t i = firing(k);
    Rng rng(pose.seed, pose.key, Purpose::LidarNoise, 8 * i);  // draws 8i .. 8i+4 belong to ray i
    if (rng.uniform_double() < preset.dropout) return;
    const double range = double(h.t) + preset.range_noise_m * double(rng.normal());
    if (range < preset.min_range || range > preset.max_range) return;
    const Vec3d& dir = ray.direction;
    const double incidence = std::abs(h.geometric_normal.cast<double>().dot(dir));
    const double clean = double(nir_reflectivity(h.material)) * incidence * std::exp(-preset.intensity_falloff * double(h.t));
    LidarPoint& p = points[i];
    p.position = (world_to_column[i / rings] * (dir * range)).cast<float>();
    p.range = float(range);
    p.intensity = float(std::clamp(clean + preset.intensity_noise * double(rng.normal()), 0.0, 1.0));
    p.column = uint16_t(i / rings);
    p.ring = uint16_t(i % rings);
    p.time = float(double(p.column) / (double(preset.columns) * preset.rotation_hz));
    p.role = h.role;
    p.instance_id = role_has_instances(h.role) ? h.instance_id : 0;
  };
  CastOptions cast_options = options;
  cast_options.normals = false;  // intensity needs only the geometric normal
  scene.cast_each(n, make, take, cast_options);
  points.erase(std::remove_if(points.begin(), points.end(), [](const LidarPoint& p) { return p.range < 0.0f; }),
               points.end());
  return points;
}

}  // namespace silva::raycast
