#pragma once
/// @file An IMU reading and the IMU noise parameters, shared by the IMU model (world/) and its files (io/).
#include <cstdint>

#include "core/types.hpp"

namespace silva {

/// One IMU reading, in the camera's axes (CONTRACT.md: x right, y down, z forward).
struct ImuSample {
  int64_t t_ns = 0;  ///< Nanoseconds from the walk's start.
  Vec3d gyro;        ///< Angular velocity, rad/s.
  Vec3d accel;       ///< Specific force (acceleration minus gravity), m/s²: at rest it reads +9.81 upwards.
};

/// Continuous-time IMU noise parameters, as Kalibr's imu.yaml gives them.
struct ImuNoise {
  double gyro_noise_density = 0;   ///< Gyroscope white noise, rad/s/√Hz.
  double gyro_random_walk = 0;     ///< Gyroscope bias random walk, rad/s²/√Hz.
  double accel_noise_density = 0;  ///< Accelerometer white noise, m/s²/√Hz.
  double accel_random_walk = 0;    ///< Accelerometer bias random walk, m/s³/√Hz.
};

}  // namespace silva
