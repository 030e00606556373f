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
  Vec3d gyro_bias = Vec3d::Zero();   ///< The gyroscope bias inside `gyro`, rad/s.
  Vec3d accel_bias = Vec3d::Zero();  ///< The accelerometer bias inside `accel`, m/s².
};

/// The true state of the IMU (= camera) at one reading, as EuRoC's state_groundtruth_estimate0 gives it.
struct ImuState {
  int64_t t_ns = 0;           ///< Nanoseconds from the walk's start.
  Vec3d position;             ///< World metres.
  Mat3d rotation;             ///< IMU (camera axes) to world.
  Vec3d velocity;             ///< World m/s.
  Vec3d gyro_bias, accel_bias;  ///< The reading's biases.
};

/// Continuous-time IMU noise parameters, as Kalibr's imu.yaml gives them.
struct ImuNoise {
  double gyro_noise_density = 0;   ///< Gyroscope white noise, rad/s/√Hz.
  double gyro_random_walk = 0;     ///< Gyroscope bias random walk, rad/s²/√Hz.
  double accel_noise_density = 0;  ///< Accelerometer white noise, m/s²/√Hz.
  double accel_random_walk = 0;    ///< Accelerometer bias random walk, m/s³/√Hz.
};

}  // namespace silva
