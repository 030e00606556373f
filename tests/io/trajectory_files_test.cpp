// The trajectory sequence's files in the forms their readers expect: EuRoC's IMU CSV, Kalibr's imu.yaml,
// TUM trajectories.
#include "io/trajectory_files.hpp"

#include <gtest/gtest.h>

#include "core/error.hpp"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <vector>

namespace silva::io {
namespace {

TEST(TrajectoryFiles, EurocImuCsvHasItsHeaderAndOneLinePerReading) {
  const std::vector<ImuSample> samples = {{0, Vec3d(0.1, -0.2, 0.3), Vec3d(0, -9.81, 0)},
                                          {5000000, Vec3d(0, 0, 0), Vec3d(1.5, 2, -3)}};
  EXPECT_EQ(euroc_imu_csv(samples),
            "#timestamp [ns],w_RS_S_x [rad s^-1],w_RS_S_y [rad s^-1],w_RS_S_z [rad s^-1],a_RS_S_x [m s^-2],"
            "a_RS_S_y [m s^-2],a_RS_S_z [m s^-2]\n"
            "0,0.1,-0.2,0.3,0,-9.81,0\n"
            "5000000,0,0,0,1.5,2,-3\n");
}

TEST(TrajectoryFiles, EurocStateCsvPutsTheQuaternionsWFirst) {
  ImuState s;
  s.t_ns = 5000000;
  s.position = Vec3d(1, 2, 3);
  s.rotation << 0, -1, 0, 1, 0, 0, 0, 0, 1;  // 90 degrees about z
  s.velocity = Vec3d(0.5, 0, -0.25);
  s.gyro_bias = Vec3d(1e-5, 0, 0);
  s.accel_bias = Vec3d(0, 0, 0.002);
  const std::vector<ImuState> states = {s};
  const std::string csv = euroc_state_csv(states);
  EXPECT_EQ(csv.substr(0, csv.find('\n')),
            "#timestamp, p_RS_R_x [m], p_RS_R_y [m], p_RS_R_z [m], q_RS_w [], q_RS_x [], q_RS_y [], q_RS_z [], "
            "v_RS_R_x [m s^-1], v_RS_R_y [m s^-1], v_RS_R_z [m s^-1], b_w_RS_S_x [rad s^-1], b_w_RS_S_y [rad s^-1], "
            "b_w_RS_S_z [rad s^-1], b_a_RS_S_x [m s^-2], b_a_RS_S_y [m s^-2], b_a_RS_S_z [m s^-2]");
  EXPECT_EQ(csv.substr(csv.find('\n') + 1),
            "5000000,1.000000000,2.000000000,3.000000000,0.707106781187,0.000000000000,0.000000000000,0.707106781187,"
            "0.500000000,0.000000000,-0.250000000,1e-05,0,0,0,0,0.002\n");
}

TEST(TrajectoryFiles, ImuFilesReadBackWhatTheyWroteAndRefuseDamage) {
  const std::filesystem::path dir = std::filesystem::path(::testing::TempDir()) / "silva_imu_files";
  std::filesystem::create_directories(dir);
  const std::vector<ImuSample> samples = {{0, Vec3d(0.1, -0.2, 0.3), Vec3d(0, -9.81, 0)},
                                          {5000000, Vec3d(0, 0, 1e-7), Vec3d(1.5, 2, -3)}};
  std::ofstream(dir / "imu.csv") << euroc_imu_csv(samples);
  std::ofstream(dir / "imu.yaml") << kalibr_imu_yaml({1.6968e-04, 1.9393e-05, 2.0e-3, 3.0e-3}, 200);
  const std::vector<ImuSample> back = read_euroc_imu_csv(dir / "imu.csv");
  ASSERT_EQ(back.size(), 2u);
  EXPECT_EQ(back[1].t_ns, 5000000);
  EXPECT_EQ(back[1].gyro, samples[1].gyro);
  EXPECT_EQ(back[0].accel, samples[0].accel);
  const KalibrImu yaml = read_kalibr_imu_yaml(dir / "imu.yaml");
  EXPECT_EQ(yaml.rate_hz, 200);
  EXPECT_EQ(yaml.noise.gyro_random_walk, 1.9393e-05);
  for (const char* bad : {"0,1,2,3,4,5\n", "0,1,2,3,4,5,nan\n", "5,0,0,0,0,0,0\n5,0,0,0,0,0,0\n", "0,1,2,3,4,5,6x\n"}) {
    std::ofstream(dir / "imu.csv", std::ios::trunc) << bad;
    EXPECT_THROW(read_euroc_imu_csv(dir / "imu.csv"), InputError) << bad;
  }
  std::ofstream(dir / "imu.yaml", std::ios::trunc) << "update_rate: 200\n";
  EXPECT_THROW(read_kalibr_imu_yaml(dir / "imu.yaml"), InputError);
  std::filesystem::remove_all(dir);
}

TEST(TrajectoryFiles, KalibrYamlNamesEveryNoiseParameter) {
  const std::string yaml = kalibr_imu_yaml({1.6968e-04, 1.9393e-05, 2.0e-3, 3.0e-3}, 200);
  for (const char* line : {"update_rate: 200 ", "accelerometer_noise_density: 0.002 ", "accelerometer_random_walk: 0.003 ",
                           "gyroscope_noise_density: 0.00016968 ", "gyroscope_random_walk: 1.9393e-05 ",
                           "rostopic: /imu0\n"})
    EXPECT_NE(yaml.find(line), std::string::npos) << line;
}

TEST(TrajectoryFiles, TumLinesHoldTimePositionAndTheRotationsQuaternion) {
  Mat4d still = Mat4d::Identity();
  still.block<3, 1>(0, 3) = Vec3d(1, 2, 3);
  Mat4d turned = Mat4d::Identity();  // 90 degrees about z: q = (0, 0, sin 45, cos 45)
  turned.block<3, 3>(0, 0) << 0, -1, 0, 1, 0, 0, 0, 0, 1;
  Mat4d flipped = Mat4d::Identity();  // 180 degrees about x: q = (1, 0, 0, 0), w kept >= 0
  flipped.block<3, 3>(0, 0) << 1, 0, 0, 0, -1, 0, 0, 0, -1;
  const std::vector<double> times = {0.0, 0.1, 0.2};
  const std::vector<Mat4d> poses = {still, turned, flipped};
  const std::string tum = tum_trajectory(times, poses);
  const double h = std::sqrt(0.5);
  char expected[256];
  std::snprintf(expected, sizeof expected, "0.100000000 0.000000000 0.000000000 0.000000000 0.000000000000 0.000000000000 %.12f %.12f\n", h, h);
  EXPECT_EQ(tum.substr(0, tum.find('\n') + 1), "# timestamp tx ty tz qx qy qz qw (camera_to_world, CONTRACT.md camera axes)\n");
  EXPECT_NE(tum.find("0.000000000 1.000000000 2.000000000 3.000000000 0.000000000000 0.000000000000 0.000000000000 "
                     "1.000000000000\n"), std::string::npos) << tum;
  EXPECT_NE(tum.find(expected), std::string::npos) << tum;
  EXPECT_NE(tum.find("0.200000000 0.000000000 0.000000000 0.000000000 1.000000000000 0.000000000000 0.000000000000 "
                     "0.000000000000\n"), std::string::npos) << tum;
}

}  // namespace
}  // namespace silva::io
