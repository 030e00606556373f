// EuRoC / ASL export (CONTRACT.md "Export formats"): the trajectory sequence as the folder every visual-inertial
// odometry system reads, mav0/ with cam0/ (data.csv, data/<t_ns>.png, sensor.yaml), a stereo rig's right camera as
// cam1/, imu0/ (data.csv, sensor.yaml) and state_groundtruth_estimate0/data.csv. The dataset already writes the IMU
// readings and the true states in EuRoC's columns, so they are placed unchanged; the IMU sits at the left camera
// (T_BS the identity for cam0 and imu0, the baseline along x for cam1), and the principal point is Silva's − 0.5 px
// (Kalibr's pixel centres are integers).
#include <cmath>
#include <filesystem>
#include <optional>
#include <string>

#include <tbb/parallel_for.h>

#include "core/error.hpp"
#include "io/atomic_file.hpp"
#include "io/camera_json.hpp"
#include "io/export_formats.hpp"
#include "io/printf_string.hpp"
#include "io/trajectory_files.hpp"

namespace silva::io {

namespace fs = std::filesystem;

namespace {

/// The T_BS block of an EuRoC sensor.yaml: the sensor `x` metres along the body's +x axis (the body is the IMU, at
/// the left camera).
std::string tbs_yaml(double x) {
  return printf_string("T_BS:\n  cols: 4\n  rows: 4\n  data: [1.0, 0.0, 0.0, %.17g, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0, "
                       "0.0, 0.0, 0.0, 0.0, 1.0]\n",
                       x);
}

/// Writes the camera folder `name` (cam0, cam1) of mav0/: data/<t_ns>.png from output folder `rgb_folder` of each
/// frame, data.csv and sensor.yaml, the camera `x` metres along the left camera's +x.
void write_euroc_camera(const Dataset& d, const std::vector<DatasetFrame>& frames, const std::string& rgb_folder,
                        const fs::path& folder, double x, double hz, const ExportOptions& options) {
  create_folder(folder / "data");
  const auto stamp = [hz](const DatasetFrame& f) { return std::llround(double(f.frame) * 1e9 / hz); };
  tbb::parallel_for(size_t(0), frames.size(), [&](size_t i) {
    place_file(d.file(frames[i], rgb_folder, "png"), folder / "data" / (std::to_string(stamp(frames[i])) + ".png"),
               options);
  });
  std::string list = "#timestamp [ns],filename\n";
  for (const DatasetFrame& f : frames) list += std::to_string(stamp(f)) + "," + std::to_string(stamp(f)) + ".png\n";
  write_file_atomic(folder / "data.csv", list);
  const Camera cam = read_camera_json(d.file(frames.front(), "camera", "json")).camera;
  write_file_atomic(folder / "sensor.yaml",
                    "sensor_type: camera\ncomment: Silva trajectory camera (pinhole, no distortion)\n" + tbs_yaml(x) +
                        printf_string("rate_hz: %.9g\nresolution: [%d, %d]\ncamera_model: pinhole\n"
                                      "intrinsics: [%.17g, %.17g, %.17g, %.17g]\n"
                                      "distortion_model: radial-tangential\ndistortion_coefficients: [0.0, 0.0, 0.0, 0.0]\n",
                                      hz, cam.width, cam.height, cam.fx, cam.fy, cam.cx - 0.5, cam.cy - 0.5));
}

}  // namespace

void export_euroc(const Dataset& d, const fs::path& out, const ExportOptions& options) {
  d.require("rgb", "euroc");
  std::vector<DatasetFrame> frames;
  for (const DatasetFrame& f : d.frames)
    if (f.sequence == "trajectory") frames.push_back(f);
  if (frames.empty())
    throw InputError(d.dir.string() + ": euroc needs the trajectory sequence, which this dataset does not hold "
                     "(add \"trajectory\" to captures.sequences)");
  const double hz = trajectory_camera_hz(d);
  const fs::path seq = d.dir / "trajectory", mav = out / "mav0";
  for (const char* folder : {"imu0", "state_groundtruth_estimate0"}) create_folder(mav / folder);
  write_euroc_camera(d, frames, "rgb", mav / "cam0", 0.0, hz, options);
  const std::optional<StereoRecord> stereo = read_camera_json(d.file(frames.front(), "camera", "json")).stereo;
  if (stereo) write_euroc_camera(d, frames, "rgb_right", mav / "cam1", stereo->baseline_m, hz, options);
  const KalibrImu imu = read_kalibr_imu_yaml(seq / "imu.yaml");
  write_file_atomic(mav / "imu0" / "sensor.yaml",
                    "sensor_type: imu\ncomment: Silva IMU, axes the camera's (x right, y down, z forward)\n" +
                        tbs_yaml(0.0) +
                        printf_string("rate_hz: %.9g\ngyroscope_noise_density: %.9g\ngyroscope_random_walk: %.9g\n"
                                      "accelerometer_noise_density: %.9g\naccelerometer_random_walk: %.9g\n",
                                      imu.rate_hz, imu.noise.gyro_noise_density, imu.noise.gyro_random_walk,
                                      imu.noise.accel_noise_density, imu.noise.accel_random_walk));
  place_file(seq / "imu.csv", mav / "imu0" / "data.csv", options);
  place_file(seq / "state_groundtruth.csv", mav / "state_groundtruth_estimate0" / "data.csv", options);
}

}  // namespace silva::io
