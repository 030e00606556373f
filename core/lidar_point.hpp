#pragma once
/// @file One LiDAR return, as the sensor model produces it and the file writers read it.
#include <cstdint>

#include "core/ontology.hpp"
#include "core/types.hpp"

namespace silva {

/// One return of a LiDAR sweep (CONTRACT.md "LiDAR").
struct LidarPoint {
  Vec3f position = Vec3f::Zero();  ///< x forward, y left, z up in the sensor frame (metres).
  float intensity = 0.0f;          ///< Reflectivity x incidence x range falloff, with noise, in [0, 1].
  float range = 0.0f;              ///< Measured range (metres): |position|.
  float time = 0.0f;               ///< Seconds since the sweep began.
  uint16_t ring = 0;               ///< Beam index, 0 = lowest elevation.
  uint16_t column = 0;             ///< Firing index within the revolution.
  Role role = Role::Background;    ///< Class role of the surface hit.
  uint32_t instance_id = 0;        ///< Packed instance id, 0 where the class carries none.
};

}  // namespace silva
