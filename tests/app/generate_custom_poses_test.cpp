// Custom poses round-trip: pose file (JSON/CSV, angles or 4x4 matrix) -> camera/NNNNNN.json,
// checked against the CONTRACT.md convention R = Rz(yaw) Ry(-pitch) Rx(roll) B written out here.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>

#include <nlohmann/json.hpp>

#include "core/config.hpp"
#include "silva_process.hpp"
#include "world/terrain.hpp"

namespace silva::test {
namespace {

namespace fs = std::filesystem;
using Matrix = std::array<std::array<double, 4>, 4>;

constexpr int64_t kSeed = 99;
constexpr double kTolerance = 1e-9;

/// A pose as the test writes it: position (z may be absent) and angles in degrees.
struct Pose {
  double x, y;
  std::optional<double> z;
  double yaw, pitch, roll;
};

/// camera-to-world of `p` at height z, from the contract's formula.
Matrix contract_pose(const Pose& p, double z) {
  const double d = M_PI / 180.0;
  const double cy = std::cos(p.yaw * d), sy = std::sin(p.yaw * d);
  const double cp = std::cos(-p.pitch * d), sp = std::sin(-p.pitch * d);
  const double cr = std::cos(p.roll * d), sr = std::sin(p.roll * d);
  const double rz[3][3] = {{cy, -sy, 0}, {sy, cy, 0}, {0, 0, 1}};
  const double ry[3][3] = {{cp, 0, sp}, {0, 1, 0}, {-sp, 0, cp}};
  const double rx[3][3] = {{1, 0, 0}, {0, cr, -sr}, {0, sr, cr}};
  // B: camera z -> body x, camera x -> body -y, camera y -> body -z (columns).
  const double b[3][3] = {{0, 0, 1}, {-1, 0, 0}, {0, -1, 0}};
  auto mul = [](const double a[3][3], const double c[3][3], double out[3][3]) {
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) {
        out[i][j] = 0;
        for (int k = 0; k < 3; ++k) out[i][j] += a[i][k] * c[k][j];
      }
  };
  double t1[3][3], t2[3][3], r[3][3];
  mul(rz, ry, t1);
  mul(t1, rx, t2);
  mul(t2, b, r);
  Matrix m{};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) m[i][j] = r[i][j];
  m[0][3] = p.x;
  m[1][3] = p.y;
  m[2][3] = z;
  m[3][3] = 1;
  return m;
}

Matrix matrix_of(const nlohmann::json& j) {
  Matrix m{};
  for (int i = 0; i < 4; ++i)
    for (int k = 0; k < 4; ++k) m[i][k] = j.at(i).at(k).get<double>();
  return m;
}

void expect_matrix_near(const Matrix& a, const Matrix& b) {
  for (int i = 0; i < 4; ++i)
    for (int k = 0; k < 4; ++k) EXPECT_NEAR(a[i][k], b[i][k], kTolerance) << "entry " << i << "," << k;
}

std::string number(double v) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}

/// Height of a pose written without z: camera.ground_height above the seed's terrain.
double ground_z(double x, double y) {
  Config cfg;
  cfg.seed = kSeed;
  return double(world::terrain_height(world::make_terrain_field(cfg), x, y)) + cfg.camera.ground_height;
}

const std::vector<Pose> kPoses = {
    {3, -2, 4.25, 30, -12.5, 7},
    {12, -4, std::nullopt, 45, -10, 0},
    {-20.5, 17.25, 9.5, -135, 33, -20},
    {0.125, 0.5, 1.5, 180, 0, 0},
};

/// Runs the custom sequence of `pose_file`; returns the run folder.
fs::path run_custom(const fs::path& dir, const fs::path& pose_file) {
  const fs::path out = dir / ("out_" + pose_file.filename().string());
  std::vector<std::string> args = tiny_run_args(out, kSeed, R"(["depth"])");
  args.insert(args.end(), {"--set", R"(captures.sequences=["custom"])", "--set",
                           "captures.poses_file=" + pose_file.string()});
  const ProcessResult r = run_silva(args, dir);
  EXPECT_EQ(r.code, 0) << r.err;
  return out / "0000000099";
}

nlohmann::json camera_file(const fs::path& run_dir, int frame) {
  char name[32];
  std::snprintf(name, sizeof name, "%06d.json", frame);
  return nlohmann::json::parse(read_file(run_dir / "custom" / "camera" / name));
}

/// Checks a camera file of an angle pose: the matrix, the angles and the fixed fields.
void expect_angle_pose(const nlohmann::json& cam, const Pose& p, int frame) {
  SCOPED_TRACE("frame " + std::to_string(frame));
  EXPECT_EQ(cam.at("frame"), frame);
  EXPECT_EQ(cam.at("sequence"), "custom");
  EXPECT_EQ(cam.at("perspective"), "ground");
  EXPECT_EQ(cam.at("width"), 64);
  EXPECT_EQ(cam.at("height"), 48);
  const double k[3][3] = {{32, 0, 32}, {0, 32, 24}, {0, 0, 1}};  // fx = fy = 64 / (2 tan 45°)
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) EXPECT_NEAR(cam.at("K").at(i).at(j).get<double>(), k[i][j], kTolerance);
  EXPECT_TRUE(cam.at("trail_s").is_null());
  EXPECT_NEAR(cam.at("yaw_deg").get<double>(), p.yaw, kTolerance);
  EXPECT_NEAR(cam.at("pitch_deg").get<double>(), p.pitch, kTolerance);
  EXPECT_NEAR(cam.at("roll_deg").get<double>(), p.roll, kTolerance);
  const double z = p.z ? *p.z : ground_z(p.x, p.y);
  expect_matrix_near(matrix_of(cam.at("camera_to_world")), contract_pose(p, z));
}

TEST(GenerateCustomPoses, JsonAnglesAndMatricesRoundTrip) {
  const fs::path dir = fresh_test_dir();
  // Angle poses, then the same poses as matrices (the contract's formula, printed in full).
  nlohmann::json file = {{"poses", nlohmann::json::array()}};
  for (const Pose& p : kPoses) {
    nlohmann::json pose = {{"yaw_deg", p.yaw}, {"pitch_deg", p.pitch}, {"roll_deg", p.roll}};
    pose["position"] = p.z ? nlohmann::json{p.x, p.y, *p.z} : nlohmann::json{p.x, p.y};
    file["poses"].push_back(pose);
  }
  std::string text = file.dump();
  text.pop_back();  // reopen the list to append matrix poses with full-precision numbers
  text.pop_back();
  for (const Pose& p : kPoses) {
    const Matrix m = contract_pose(p, p.z ? *p.z : 2.0);
    text += ",{\"camera_to_world\":[";
    for (int i = 0; i < 4; ++i)
      text += std::string(i ? "," : "") + "[" + number(m[i][0]) + "," + number(m[i][1]) + "," + number(m[i][2]) + "," +
              number(m[i][3]) + "]";
    text += "]}";
  }
  text += "]}";
  const fs::path pose_file = dir / "poses.json";
  std::ofstream(pose_file) << text;
  const fs::path run_dir = run_custom(dir, pose_file);
  const int n = int(kPoses.size());
  for (int k = 0; k < n; ++k) expect_angle_pose(camera_file(run_dir, k), kPoses[k], k);
  for (int k = 0; k < n; ++k) {
    SCOPED_TRACE("matrix pose " + std::to_string(k));
    const nlohmann::json cam = camera_file(run_dir, n + k);
    const Pose& p = kPoses[k];
    const Matrix input = contract_pose(p, p.z ? *p.z : 2.0);
    expect_matrix_near(matrix_of(cam.at("camera_to_world")), input);
    // The decomposed angles rebuild the same matrix.
    const Pose angles{p.x, p.y, 0.0, cam.at("yaw_deg").get<double>(), cam.at("pitch_deg").get<double>(),
                      cam.at("roll_deg").get<double>()};
    expect_matrix_near(contract_pose(angles, input[2][3]), input);
  }
  EXPECT_FALSE(fs::exists(run_dir / "custom" / "camera" / "000008.json"));
}

TEST(GenerateCustomPoses, CsvRoundTrips) {
  const fs::path dir = fresh_test_dir();
  std::string text = "x,y,z,yaw_deg,pitch_deg,roll_deg\n";
  for (const Pose& p : kPoses)
    text += number(p.x) + "," + number(p.y) + "," + (p.z ? number(*p.z) : "") + "," + number(p.yaw) + "," +
            number(p.pitch) + "," + number(p.roll) + "\n";
  const fs::path pose_file = dir / "poses.csv";
  std::ofstream(pose_file) << text;
  const fs::path run_dir = run_custom(dir, pose_file);
  for (int k = 0; k < int(kPoses.size()); ++k) expect_angle_pose(camera_file(run_dir, k), kPoses[k], k);
}

TEST(GenerateCustomPoses, ShippedExamplesRun) {
  const fs::path dir = fresh_test_dir();
  const fs::path json_run = run_custom(dir, fs::path(SILVA_SOURCE_DIR) / "configs" / "poses.example.json");
  const fs::path csv_run = run_custom(dir, fs::path(SILVA_SOURCE_DIR) / "configs" / "poses.example.csv");
  expect_angle_pose(camera_file(json_run, 1), {12, -4, std::nullopt, 45, -10, 0}, 1);
  expect_angle_pose(camera_file(csv_run, 1), {12, -4, std::nullopt, 45, -10, 0}, 1);
  // The example matrix looks along +X from (40, 0, 2): yaw = pitch = roll = 0.
  const nlohmann::json cam = camera_file(json_run, 3);
  expect_angle_pose(cam, {40, 0, 2.0, 0, 0, 0}, 3);
  EXPECT_TRUE(fs::exists(csv_run / "custom" / "camera" / "000002.json"));
}

}  // namespace
}  // namespace silva::test
