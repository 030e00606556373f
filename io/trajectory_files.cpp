#include "io/trajectory_files.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <sstream>
#include <stdexcept>

#include <Eigen/Geometry>

#include "core/error.hpp"
#include "core/input_limits.hpp"
#include "io/dataset_reader.hpp"
#include "io/printf_string.hpp"

namespace silva::io {

std::string euroc_imu_csv(std::span<const ImuSample> samples) {
  std::string out =
      "#timestamp [ns],w_RS_S_x [rad s^-1],w_RS_S_y [rad s^-1],w_RS_S_z [rad s^-1],a_RS_S_x [m s^-2],"
      "a_RS_S_y [m s^-2],a_RS_S_z [m s^-2]\n";
  out.reserve(out.size() + samples.size() * 120);
  for (const ImuSample& s : samples)
    out += printf_string("%lld,%.12g,%.12g,%.12g,%.12g,%.12g,%.12g\n", static_cast<long long>(s.t_ns), s.gyro.x(),
                  s.gyro.y(), s.gyro.z(), s.accel.x(), s.accel.y(), s.accel.z());
  return out;
}

std::string euroc_state_csv(std::span<const ImuState> states) {
  std::string out =
      "#timestamp, p_RS_R_x [m], p_RS_R_y [m], p_RS_R_z [m], q_RS_w [], q_RS_x [], q_RS_y [], q_RS_z [], "
      "v_RS_R_x [m s^-1], v_RS_R_y [m s^-1], v_RS_R_z [m s^-1], b_w_RS_S_x [rad s^-1], b_w_RS_S_y [rad s^-1], "
      "b_w_RS_S_z [rad s^-1], b_a_RS_S_x [m s^-2], b_a_RS_S_y [m s^-2], b_a_RS_S_z [m s^-2]\n";
  for (const ImuState& s : states) {
    Eigen::Quaterniond q(s.rotation);
    q.normalize();
    if (q.w() < 0) q.coeffs() = -q.coeffs();
    out += printf_string("%lld,%.9f,%.9f,%.9f,%.12f,%.12f,%.12f,%.12f,%.9f,%.9f,%.9f,%.12g,%.12g,%.12g,%.12g,%.12g,%.12g\n",
                         static_cast<long long>(s.t_ns), s.position.x(), s.position.y(), s.position.z(), q.w(), q.x(),
                         q.y(), q.z(), s.velocity.x(), s.velocity.y(), s.velocity.z(), s.gyro_bias.x(),
                         s.gyro_bias.y(), s.gyro_bias.z(), s.accel_bias.x(), s.accel_bias.y(), s.accel_bias.z());
  }
  return out;
}

std::string kalibr_imu_yaml(const ImuNoise& noise, double rate_hz) {
  return printf_string(
      "# IMU noise of the trajectory sequence (Kalibr imu.yaml); axes are the camera's (x right, y down, z forward)\n"
      "rostopic: /imu0\n"
      "update_rate: %.9g  # Hz\n"
      "accelerometer_noise_density: %.9g  # m/s^2/sqrt(Hz)\n"
      "accelerometer_random_walk: %.9g  # m/s^3/sqrt(Hz)\n"
      "gyroscope_noise_density: %.9g  # rad/s/sqrt(Hz)\n"
      "gyroscope_random_walk: %.9g  # rad/s^2/sqrt(Hz)\n",
      rate_hz, noise.accel_noise_density, noise.accel_random_walk, noise.gyro_noise_density, noise.gyro_random_walk);
}

KalibrImu read_kalibr_imu_yaml(const std::filesystem::path& path) {
  require_dataset_file(path);
  std::istringstream in(limits::read_input_file(path, "IMU file"));
  std::map<std::string, double> values;
  for (std::string line; std::getline(in, line);) {
    const size_t colon = line.find(':');
    if (line.empty() || line[0] == '#' || colon == std::string::npos) continue;
    const std::string rest = line.substr(colon + 1);
    char* end = nullptr;
    const double v = std::strtod(rest.c_str(), &end);
    if (end != rest.c_str() && std::isfinite(v)) values[line.substr(0, colon)] = v;
  }
  const auto get = [&](const char* key) {
    const auto it = values.find(key);
    if (it == values.end()) throw InputError(path.string() + ": no number for '" + key + "' (a Kalibr imu.yaml)");
    return it->second;
  };
  return {get("update_rate"),
          {get("gyroscope_noise_density"), get("gyroscope_random_walk"), get("accelerometer_noise_density"),
           get("accelerometer_random_walk")}};
}

std::vector<ImuSample> read_euroc_imu_csv(const std::filesystem::path& path) {
  require_dataset_file(path);
  std::istringstream in(limits::read_input_file(path, "IMU file"));
  std::vector<ImuSample> samples;
  int line_number = 0;
  for (std::string line; std::getline(in, line);) {
    ++line_number;
    if (line.empty() || line[0] == '#') continue;
    ImuSample s;
    long long t = 0;
    int used = 0;
    if (std::sscanf(line.c_str(), "%lld,%lf,%lf,%lf,%lf,%lf,%lf%n", &t, &s.gyro.x(), &s.gyro.y(), &s.gyro.z(),
                    &s.accel.x(), &s.accel.y(), &s.accel.z(), &used) != 7 ||
        size_t(used) != line.size() || !s.gyro.allFinite() || !s.accel.allFinite() ||
        (!samples.empty() && t <= samples.back().t_ns))
      throw InputError(path.string() + ": line " + std::to_string(line_number) +
                       " is not 't_ns,wx,wy,wz,ax,ay,az' (finite numbers, timestamps increasing)");
    s.t_ns = t;
    samples.push_back(s);
  }
  return samples;
}

std::string tum_trajectory(std::span<const double> times_s, std::span<const Mat4d> camera_to_world) {
  if (times_s.size() != camera_to_world.size()) throw std::invalid_argument("tum_trajectory: one time per pose");
  std::string out = "# timestamp tx ty tz qx qy qz qw (camera_to_world, CONTRACT.md camera axes)\n";
  for (size_t i = 0; i < times_s.size(); ++i) {
    const Mat4d& m = camera_to_world[i];
    Eigen::Quaterniond q(Mat3d(m.block<3, 3>(0, 0)));
    q.normalize();
    if (q.w() < 0) q.coeffs() = -q.coeffs();
    out += printf_string("%.9f %.9f %.9f %.9f %.12f %.12f %.12f %.12f\n", times_s[i], m(0, 3), m(1, 3), m(2, 3), q.x(),
                  q.y(), q.z(), q.w());
  }
  return out;
}

}  // namespace silva::io
