#pragma once
/// @file The files of the `trajectory` sequence (CONTRACT.md "Trajectory files"): IMU readings as EuRoC's
/// imu0/data.csv, the IMU's noise as Kalibr's imu.yaml, and the camera poses as a TUM trajectory.
#include <filesystem>
#include <span>
#include <string>
#include <vector>

#include "core/imu_sample.hpp"
#include "core/types.hpp"

namespace silva::io {

/// EuRoC's imu0/data.csv: its header line, then per reading "t_ns,wx,wy,wz,ax,ay,az" (rad/s, m/s²).
std::string euroc_imu_csv(std::span<const ImuSample> samples);

/// EuRoC's state_groundtruth_estimate0/data.csv: its header line, then per state "t_ns, p (m), q (w x y z, the IMU's
/// rotation to the world, w >= 0), v (m/s), gyro bias (rad/s), accelerometer bias (m/s²)".
std::string euroc_state_csv(std::span<const ImuState> states);

/// Kalibr's imu.yaml for an IMU of `noise` read at `rate_hz`, on ROS topic /imu0.
std::string kalibr_imu_yaml(const ImuNoise& noise, double rate_hz);

/// The rate and noise of a Kalibr imu.yaml as kalibr_imu_yaml writes it.
struct KalibrImu {
  double rate_hz = 0;  ///< update_rate.
  ImuNoise noise;      ///< The four noise parameters.
};

/// Reads a dataset's imu.yaml; InputError naming the file and key when one of kalibr_imu_yaml's numbers is missing.
KalibrImu read_kalibr_imu_yaml(const std::filesystem::path& path);

/// Reads a dataset's imu.csv (euroc_imu_csv's form; the biases are not in the file and read as 0); InputError
/// naming the file and line unless every line holds 7 finite numbers with increasing timestamps.
std::vector<ImuSample> read_euroc_imu_csv(const std::filesystem::path& path);

/// A TUM trajectory: a comment line, then per pose "t tx ty tz qx qy qz qw" (seconds, metres, the unit
/// quaternion of the rotation with qw >= 0), times_s[i] with camera_to_world[i].
std::string tum_trajectory(std::span<const double> times_s, std::span<const Mat4d> camera_to_world);

}  // namespace silva::io
