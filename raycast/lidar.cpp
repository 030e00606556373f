/// @file The LiDAR sensor model (see lidar.hpp).
#include "raycast/lidar.hpp"

#include <algorithm>
#include <cmath>

#include <Eigen/Geometry>

#include "core/rng.hpp"

namespace silva::raycast {

namespace {
constexpr double kPi = 3.14159265358979323846;
}  // namespace

Vec3d beam_direction(const LidarPreset& preset, int ring, int column) {
  const double elevation = preset.elevations_deg[size_t(ring)] * kPi / 180.0;
  const double azimuth = kPi - 2.0 * kPi * double(column) / double(preset.columns);
  return {std::cos(elevation) * std::cos(azimuth), std::cos(elevation) * std::sin(azimuth), std::sin(elevation)};
}

float nir_reflectivity(Material m) {
  switch (m) {
    case Material::Needles: case Material::Leaves: case Material::Grass: case Material::Fern:
    case Material::ShrubLeaves: case Material::NeedlesSpruce: case Material::NeedlesPine:
    case Material::NeedlesLarch: case Material::LeavesBeech: case Material::LeavesBirch: case Material::LeavesOak:
      return 0.55f;  // green foliage reflects strongly in the near infrared
    case Material::Moss:
      return 0.45f;
    case Material::AutumnLeaves: case Material::AutumnNeedles: case Material::LeafLitter:
      return 0.4f;
    case Material::BarkBirch: case Material::BarkBeech: case Material::BrokenWood: case Material::Wood:
      return 0.45f;
    case Material::Rock:
      return 0.35f;
    case Material::Ground: case Material::Trail:
      return 0.25f;
    default:
      return 0.3f;  // bark, dead wood, bare twigs
  }
}

std::vector<LidarPoint> cast_sweep(const RayScene& scene, const LidarPreset& preset, const SweepPose& pose,
                                   const CastOptions& options) {
  const int rings = int(preset.elevations_deg.size());
  const size_t n = size_t(rings) * size_t(preset.columns);
  std::vector<Mat3d> column_to_world(size_t(preset.columns), pose.sensor_to_world);
  std::vector<Vec3d> column_origin(size_t(preset.columns), pose.position);
  if (pose.end) {
    const Eigen::Quaterniond q0(pose.sensor_to_world), q1(pose.end->sensor_to_world);
    for (int c = 1; c < preset.columns; ++c) {
      const double f = double(c) / double(preset.columns);
      column_to_world[size_t(c)] = q0.slerp(f, q1).toRotationMatrix();
      column_origin[size_t(c)] = pose.position + f * (pose.end->position - pose.position);
    }
  }
  std::vector<Ray> rays(n);
  for (int c = 0; c < preset.columns; ++c)
    for (int r = 0; r < rings; ++r) {
      Ray& ray = rays[size_t(c) * size_t(rings) + size_t(r)];
      ray.origin = column_origin[size_t(c)];
      ray.direction = column_to_world[size_t(c)] * beam_direction(preset, r, c);
      ray.t_near = preset.min_range;
      ray.t_far = preset.max_range;
    }
  std::vector<RayHit> hits(n);
  scene.cast(rays, hits, options);
  std::vector<Mat3d> world_to_column(column_to_world.size());
  for (size_t c = 0; c < column_to_world.size(); ++c) world_to_column[c] = column_to_world[c].transpose();
  std::vector<LidarPoint> points;
  points.reserve(n);
  for (size_t i = 0; i < n; ++i) {
    const RayHit& h = hits[i];
    if (!h.hit) continue;
    Rng rng(pose.seed, pose.key, Purpose::LidarNoise, 8 * i);  // draws 8i .. 8i+4 belong to ray i
    if (rng.uniform_double() < preset.dropout) continue;
    const double range = double(h.t) + preset.range_noise_m * double(rng.normal());
    if (range < preset.min_range || range > preset.max_range) continue;
    const Vec3d dir = rays[i].direction;
    const double incidence = std::abs(h.geometric_normal.cast<double>().dot(dir));
    const double clean = double(nir_reflectivity(h.material)) * incidence * std::exp(-preset.intensity_falloff * double(h.t));
    LidarPoint p;
    p.position = (world_to_column[i / size_t(rings)] * (dir * range)).cast<float>();
    p.range = float(range);
    p.intensity = float(std::clamp(clean + preset.intensity_noise * double(rng.normal()), 0.0, 1.0));
    p.column = uint16_t(i / size_t(rings));
    p.ring = uint16_t(i % size_t(rings));
    p.time = float(double(p.column) / (double(preset.columns) * preset.rotation_hz));
    p.role = h.role;
    p.instance_id = role_has_instances(h.role) ? h.instance_id : 0;
    points.push_back(p);
  }
  return points;
}

}  // namespace silva::raycast
