#pragma once
/// @file The IMU of the `trajectory` sequence: gyroscope and accelerometer readings from the walk's exact
/// angular velocity and acceleration, with the white noise and bias random walks VIO calibrations use.
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "core/imu_sample.hpp"
#include "world/trajectory.hpp"

namespace silva::world {

/// The noise model trajectory.imu_noise names: "adis16448" (EuRoC's ADIS16448, its published Kalibr
/// parameters) or "none" (all zero). std::invalid_argument otherwise (the config schema allows no other).
ImuNoise imu_noise_model(const std::string& name);

/// The noise-free reading of the state `s`.
ImuSample ideal_imu(const RigState& s);

/// llround(duration x rate_hz) readings at k / rate_hz seconds, k = 0, 1, ...: the ideal ones plus, per axis,
/// white noise of standard deviation density x √rate and a bias starting at 0 that walks by
/// random_walk / √rate per sample; drawn from `seed` (the same seed gives the same readings).
std::vector<ImuSample> imu_samples(const Trajectory& walk, double rate_hz, const ImuNoise& noise, uint64_t seed);

/// The walk's true state at each of `readings` (made by imu_samples with the same rate), with their biases.
std::vector<ImuState> imu_states(const Trajectory& walk, double rate_hz, std::span<const ImuSample> readings);

}  // namespace silva::world
