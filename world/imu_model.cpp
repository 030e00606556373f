#include "world/imu_model.hpp"

#include <cmath>
#include <stdexcept>

#include "core/rng.hpp"

namespace silva::world {

ImuNoise imu_noise_model(const std::string& name) {
  if (name == "none") return {};
  // The ADIS16448 of the EuRoC MAV datasets, as its Kalibr imu.yaml states it.
  if (name == "adis16448") return {1.6968e-04, 1.9393e-05, 2.0e-3, 3.0e-3};
  throw std::invalid_argument("unknown IMU noise model '" + name + "'");
}

ImuSample ideal_imu(const RigState& s) {
  ImuSample r;
  r.t_ns = std::llround(s.t * 1e9);
  r.gyro = s.angular_velocity;
  r.accel = s.rotation.transpose() * (s.acceleration + Vec3d(0, 0, kGravity));
  return r;
}

std::vector<ImuSample> imu_samples(const Trajectory& walk, double rate_hz, const ImuNoise& noise, uint64_t seed) {
  const auto count = size_t(std::llround(walk.duration() * rate_hz));
  const double root_rate = std::sqrt(rate_hz);
  Rng rng(seed, 0, Purpose::ImuNoise);
  Vec3d gyro_bias = Vec3d::Zero(), accel_bias = Vec3d::Zero();
  const auto normal3 = [&rng] { return Vec3d(rng.normal(), rng.normal(), rng.normal()); };
  std::vector<ImuSample> out;
  out.reserve(count);
  for (size_t k = 0; k < count; ++k) {
    ImuSample r = ideal_imu(walk.at(double(k) / rate_hz));
    r.t_ns = std::llround(double(k) * 1e9 / rate_hz);
    r.gyro_bias = gyro_bias;
    r.accel_bias = accel_bias;
    r.gyro += gyro_bias + noise.gyro_noise_density * root_rate * normal3();
    r.accel += accel_bias + noise.accel_noise_density * root_rate * normal3();
    gyro_bias += noise.gyro_random_walk / root_rate * normal3();
    accel_bias += noise.accel_random_walk / root_rate * normal3();
    out.push_back(r);
  }
  return out;
}

std::vector<ImuState> imu_states(const Trajectory& walk, double rate_hz, std::span<const ImuSample> readings) {
  std::vector<ImuState> out;
  out.reserve(readings.size());
  for (size_t k = 0; k < readings.size(); ++k) {
    const RigState s = walk.at(double(k) / rate_hz);
    out.push_back({readings[k].t_ns, s.position, s.rotation, s.velocity, readings[k].gyro_bias, readings[k].accel_bias});
  }
  return out;
}

}  // namespace silva::world
