// `silva generate` with output type lidar: the KITTI files, and LiDAR points that agree with the
// camera's labels and depth where both see the same surface.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>
#include <opencv2/imgcodecs.hpp>

#include "core/types.hpp"
#include "silva_process.hpp"

namespace silva::test {
namespace {

namespace fs = std::filesystem;

/// A noiseless 32-beam preset within the camera's view, 30 m range (a small world is enough), at the
/// camera's origin, so that both see the same surfaces (a mount offset shows the LiDAR what the
/// camera cannot see, and hides some of what it sees).
constexpr const char* kConfig = R"(
[output]
resolution = "320x240"
types = ["semantic", "instance", "depth", "lidar"]
[captures]
autopilot_points = 1
autopilot_yaws = [0]
random_count = 2
[world]
extent = 128
render_distance = 48
[trail]
control_points = 6
[camera]
far = 40
[render]
lod = false
[lidar]
preset = "exact"
mount_offset = [0, 0, 0]
[lidar.presets.exact]
channels = 32
elevation_min_deg = -25
elevation_max_deg = 5
columns = 1024
min_range = 0.3
max_range = 30
range_noise_m = 0
dropout = 0
[lidar.presets.noisy]
max_range = 30
range_noise_m = 0.02
dropout = 0.05
)";

/// The 12 numbers after "key:" in a calib.txt, as a 3x4 matrix.
Eigen::Matrix<double, 3, 4> calib_row(const std::string& calib, const std::string& key) {
  std::istringstream in(calib.substr(calib.find(key + ":") + key.size() + 1));
  Eigen::Matrix<double, 3, 4> m;
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 4; ++c) in >> m(r, c);
  return m;
}

/// The whole of a file as values of T.
template <class T>
std::vector<T> values_of(const fs::path& path) {
  const std::string bytes = read_file(path);
  std::vector<T> out(bytes.size() / sizeof(T));
  std::memcpy(out.data(), bytes.data(), out.size() * sizeof(T));
  return out;
}

TEST(GenerateLidar, PointsAgreeWithTheCameraLabelsAndDepth) {
  const fs::path dir = fresh_test_dir();
  std::ofstream(dir / "lidar.toml") << kConfig;
  const ProcessResult r =
      run_silva({"generate", "--config", (dir / "lidar.toml").string(), "--seed", "11", "--out", (dir / "out").string()}, dir);
  ASSERT_EQ(r.code, 0) << r.err;
  const fs::path run = dir / "out" / "0000000011";
  const auto manifest = nlohmann::json::parse(read_file(run / "manifest.json"));
  const auto& sensor = manifest.at("sensors").at("lidar");
  EXPECT_EQ(sensor.at("preset"), "exact");
  EXPECT_EQ(sensor.at("channels"), 32);
  size_t points = 0, classed = 0, class_agree = 0, depth_checked = 0, depth_agree = 0;
  for (const char* seq : {"autopilot", "random"}) {
    const fs::path s = run / seq;
    const std::string calib = read_file(s / "calib.txt");
    const Eigen::Matrix<double, 3, 4> p0 = calib_row(calib, "P0");
    Mat4d tr = Mat4d::Identity();
    tr.topRows<3>() = calib_row(calib, "Tr");
    const int frames = manifest.at("frames").at(seq);
    EXPECT_EQ(lines_of(read_file(s / "poses.txt")).size(), size_t(frames));
    for (int f = 0; f < frames; ++f) {
      char name[16];
      std::snprintf(name, sizeof name, "%06d", f);
      const std::vector<float> scan = values_of<float>(s / "lidar" / (std::string(name) + ".bin"));
      const std::vector<uint32_t> labels = values_of<uint32_t>(s / "lidar_labels" / (std::string(name) + ".label"));
      ASSERT_EQ(scan.size() % 4, 0u);
      ASSERT_EQ(labels.size(), scan.size() / 4);
      ASSERT_GT(labels.size(), 1000u);
      EXPECT_TRUE(fs::exists(s / "lidar_labels" / (std::string(name) + ".json")));
      const cv::Mat semantic = cv::imread((s / "semantic" / (std::string(name) + ".png")).string(), cv::IMREAD_UNCHANGED);
      const cv::Mat instance = cv::imread((s / "instance" / (std::string(name) + ".png")).string(), cv::IMREAD_UNCHANGED);
      const cv::Mat depth = cv::imread((s / "depth" / (std::string(name) + ".png")).string(), cv::IMREAD_UNCHANGED);
      ASSERT_EQ(semantic.cols, 320);
      points += labels.size();
      for (size_t i = 0; i < labels.size(); ++i) {
        const Eigen::Vector4d cam = tr * Eigen::Vector4d(scan[4 * i], scan[4 * i + 1], scan[4 * i + 2], 1.0);
        if (cam.z() < 0.1) continue;
        const Vec3d uvw = p0 * cam;
        const double u = uvw.x() / uvw.z(), v = uvw.y() / uvw.z();
        const int x = int(std::lround(u)), y = int(std::lround(v));
        if (x < 2 || y < 2 || x >= semantic.cols - 2 || y >= semantic.rows - 2) continue;
        // Away from silhouettes: the 5x5 pixels around hold one class and one instance.
        const uint8_t c = semantic.at<uint8_t>(y, x);
        const uint16_t inst = instance.at<uint16_t>(y, x);
        bool interior = true;
        for (int dy = -2; dy <= 2; ++dy)
          for (int dx = -2; dx <= 2; ++dx)
            interior = interior && semantic.at<uint8_t>(y + dy, x + dx) == c && instance.at<uint16_t>(y + dy, x + dx) == inst;
        if (!interior || c == 0) continue;
        ++classed;
        class_agree += (labels[i] & 0xffffu) == c;
        // Depth along the same ray: the depth image interpolated between the four nearest pixel centres.
        const int x0 = int(std::floor(u)), y0 = int(std::floor(v));
        const double a = u - x0, b = v - y0;
        const double d00 = depth.at<uint16_t>(y0, x0), d10 = depth.at<uint16_t>(y0, x0 + 1),
                     d01 = depth.at<uint16_t>(y0 + 1, x0), d11 = depth.at<uint16_t>(y0 + 1, x0 + 1);
        // Interpolation holds to 1 cm only where the depth is smooth: skip 2x2 blocks spanning more.
        if (std::max({d00, d10, d01, d11}) - std::min({d00, d10, d01, d11}) > 10) continue;
        const double mm = (1 - b) * ((1 - a) * d00 + a * d10) + b * ((1 - a) * d01 + a * d11);
        ++depth_checked;
        depth_agree += std::abs(mm - 1000.0 * cam.z()) <= 10.0;
      }
    }
  }
  std::printf("lidar vs camera: %zu points, %zu interior in view: class %.4f; %zu depth-checked: within 1 cm %.4f\n",
              points, classed, double(class_agree) / double(classed), depth_checked,
              double(depth_agree) / double(depth_checked));
  ASSERT_GT(classed, 2000u);
  EXPECT_GE(double(class_agree) / double(classed), 0.99);
  ASSERT_GT(depth_checked, 200u);
  EXPECT_GE(double(depth_agree) / double(depth_checked), 0.99);
}

TEST(GenerateLidar, SameSeedSameBytesForAnyThreadCount) {
  const fs::path dir = fresh_test_dir();
  std::ofstream(dir / "lidar.toml") << kConfig;
  std::map<std::string, std::string> files[2];
  for (int t = 0; t < 2; ++t) {
    const fs::path out = dir / ("out" + std::to_string(t));
    const ProcessResult r = run_silva({"generate", "--config", (dir / "lidar.toml").string(), "--seed", "12", "--out",
                                       out.string(), "--threads", std::to_string(t + 1), "--set",
                                       "output.types=[\"lidar\"]", "--set", "lidar.preset=noisy"},
                                      dir);
    ASSERT_EQ(r.code, 0) << r.err;
    files[t] = folder_files(out / "0000000012");
  }
  EXPECT_EQ(file_differences(files[0], files[1]), "");
  EXPECT_TRUE(files[0].count("random/lidar/000001.bin"));
}

TEST(GenerateLidar, LidarAloneAndMotionDistortion) {
  const fs::path dir = fresh_test_dir();
  std::ofstream(dir / "lidar.toml") << kConfig;
  // The same sweeps without any camera image; then with motion distortion, which moves only autopilot sweeps.
  const std::vector<std::vector<std::string>> runs = {
      {"output.types=[\"semantic\",\"lidar\"]"},
      {"output.types=[\"lidar\"]"},
      {"output.types=[\"lidar\"]", "lidar.motion_distortion=true", "camera.autopilot_speed=20"}};
  std::map<std::string, std::string> files[3];
  for (size_t k = 0; k < runs.size(); ++k) {
    std::vector<std::string> args = {"generate", "--config", (dir / "lidar.toml").string(), "--seed", "13", "--out",
                                     (dir / ("out" + std::to_string(k))).string(), "--quiet"};
    for (const std::string& set : runs[k]) args.insert(args.end(), {"--set", set});
    const ProcessResult r = run_silva(args, dir);
    ASSERT_EQ(r.code, 0) << r.err;
    files[k] = folder_files(dir / ("out" + std::to_string(k)) / "0000000013");
  }
  size_t scans = 0;
  for (const auto& [name, bytes] : files[1]) {
    if (name.find("/lidar") == std::string::npos) continue;
    ++scans;
    EXPECT_EQ(files[0].at(name), bytes) << name << ": the sweep depends on the camera outputs";
    if (name.starts_with("random/")) {
      EXPECT_EQ(files[2].at(name), bytes) << name << ": a random frame's sweep moved";
    } else if (name.ends_with(".bin")) {
      EXPECT_NE(files[2].at(name), bytes) << name << ": motion distortion left an autopilot sweep unchanged";
    }
  }
  EXPECT_EQ(scans, 3u * 3u);  // three frames, each .bin, .label and .json
  for (const auto& [name, bytes] : files[1]) EXPECT_EQ(name.find("/semantic/"), std::string::npos) << name;
  EXPECT_TRUE(files[1].count("autopilot/camera/000000.json"));
}

}  // namespace
}  // namespace silva::test
