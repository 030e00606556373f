// rosbag2 export (CONTRACT.md "Export formats"): per sequence a bag folder <sequence>/ holding
// <sequence>_0.mcap (ROS 2 messages, CDR) and rosbag2's metadata.yaml, written frame by frame (memory bounded
// by one frame and one MCAP chunk). Topics, frames and stamps are documented in CONTRACT.md.
#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <map>
#include <sstream>

#include <opencv2/imgproc.hpp>

#include "core/error.hpp"
#include "io/atomic_file.hpp"
#include "io/camera_json.hpp"
#include "io/capture_set.hpp"
#include "io/export_formats.hpp"
#include "io/json_read.hpp"
#include "io/lidar_files.hpp"
#include "io/mcap_writer.hpp"
#include "io/ros2_messages.hpp"
#include "io/trajectory_files.hpp"

namespace silva::io {

namespace fs = std::filesystem;

namespace {

/// Frame ids of the bag's tf tree.
const std::string kMapFrame = "map", kBaseFrame = "base_link", kCameraFrame = "camera_optical_frame",
                  kRightCameraFrame = "camera_right_optical_frame", kLidarFrame = "lidar";

/// base_link (x forward, y left, z up) from the camera's optical axes (x right, y down, z forward).
Mat4d base_from_optical() {
  Mat4d m = Mat4d::Zero();
  m(0, 2) = 1;
  m(1, 0) = -1;
  m(2, 1) = -1;
  m(3, 3) = 1;
  return m;
}

/// A topic of the bag: its name, message type and QoS profile string (rosbag2's offered_qos_profiles).
struct Topic {
  std::string name;
  RosType type;
  std::string qos;
  uint16_t channel = 0;
};

/// rosbag2's QoS profile of /tf_static (reliable, transient local, keep last 1), so late subscribers get it.
const char* const kLatchedQos =
    "- history: 1\n  depth: 1\n  reliability: 1\n  durability: 1\n  deadline:\n    sec: 9223372036\n    nsec: "
    "854775807\n  lifespan:\n    sec: 9223372036\n    nsec: 854775807\n  liveliness: 1\n  liveliness_lease_duration:\n"
    "    sec: 9223372036\n    nsec: 854775807\n  avoid_ros_namespace_conventions: false";

/// The LiDAR numbers a point's ring and firing time follow from.
struct LidarBeams {
  std::vector<double> elevations_deg;
  int columns = 0;
  double rotation_hz = 0;
  Mat4d camera_from_lidar = Mat4d::Identity();
};

LidarBeams lidar_beams(const Dataset& d) {
  const std::string where = (d.dir / "manifest.json").string() + ": sensors.lidar";
  const nlohmann::json* s = nullptr;
  if (d.manifest.contains("sensors") && d.manifest["sensors"].contains("lidar")) s = &d.manifest["sensors"]["lidar"];
  if (s == nullptr) throw InputError(where + " is missing (the dataset has lidar output)");
  LidarBeams b;
  for (const nlohmann::json& e : json_member(*s, "elevations_deg", where)) {
    if (!e.is_number()) throw InputError(where + ".elevations_deg: not a list of numbers");
    b.elevations_deg.push_back(e.get<double>());
  }
  b.columns = int(json_int(*s, "columns", 1, 1 << 20, where));
  b.rotation_hz = json_number(*s, "rotation_hz", where);
  if (b.elevations_deg.empty() || !(b.rotation_hz > 0))
    throw InputError(where + ": needs elevations_deg and a positive rotation_hz");
  const auto m = json_matrix(*s, "lidar_to_camera", 4, 4, where);
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) b.camera_from_lidar(r, c) = m[size_t(r)][size_t(c)];
  return b;
}

/// The scan's points with ring (nearest beam elevation) and firing time (column from the azimuth, CONTRACT.md
/// "LiDAR": column c fires at azimuth 180° - 360° c / columns, c / (columns rotation_hz) after the sweep began).
std::vector<RosPoint> scan_points(const Dataset& d, const DatasetFrame& f, const LidarBeams& beams) {
  const std::vector<std::array<float, 4>> xyzi = read_kitti_scan_xyzi(d.file(f, "lidar", "bin"));
  const std::vector<uint32_t> labels = d.lidar_labels(f);
  std::vector<RosPoint> points(xyzi.size());
  constexpr double kDeg = 180.0 / 3.14159265358979323846;
  for (size_t i = 0; i < xyzi.size(); ++i) {
    const auto& [x, y, z, intensity] = xyzi[i];
    RosPoint& p = points[i];
    p = {x, y, z, intensity, 0.0f, 0, uint16_t(labels[i] & 0xFFFF), uint16_t(labels[i] >> 16)};
    const double elevation = std::atan2(double(z), std::hypot(double(x), double(y))) * kDeg;
    size_t ring = 0;
    for (size_t r = 1; r < beams.elevations_deg.size(); ++r)
      if (std::abs(beams.elevations_deg[r] - elevation) < std::abs(beams.elevations_deg[ring] - elevation)) ring = r;
    p.ring = uint16_t(ring);
    const double azimuth = std::atan2(double(y), double(x)) * kDeg;
    const double column = std::fmod(std::round((180.0 - azimuth) * beams.columns / 360.0), double(beams.columns));
    p.time = float((column < 0 ? column + beams.columns : column) / (double(beams.columns) * beams.rotation_hz));
  }
  return points;
}

/// An OpenCV image's rows as one packed byte buffer.
std::span<const uint8_t> pixels(const cv::Mat& m) {
  if (!m.isContinuous()) throw IoError("image rows are not packed");
  return {m.data, m.total() * m.elemSize()};
}

/// The stereo baseline of a two-camera dataset (metres, from its first frame's right camera file), 0 for one camera.
double stereo_baseline(const Dataset& d) {
  if (!manifest_stereo(d.manifest) || d.frames.empty()) return 0.0;
  const CameraRecord right = read_camera_json(d.file(d.frames.front(), camera_folder("camera", true), "json"));
  if (!right.stereo) throw InputError(d.file(d.frames.front(), camera_folder("camera", true), "json").string() +
                                      ": a right camera file without its \"stereo\" record");
  return right.stereo->baseline_m;
}

/// The rig's fixed transforms from base_link: the camera, the LiDAR (given its beams) and a stereo pair's right camera
/// (baseline_m > 0) along the camera's x.
std::vector<RosTransform> static_mounts(const LidarBeams* lidar, double baseline_m) {
  const Mat4d base_from_camera = base_from_optical();
  std::vector<RosTransform> mounts = {{kBaseFrame, kCameraFrame, base_from_camera}};
  if (lidar) mounts.push_back({kBaseFrame, kLidarFrame, base_from_camera * lidar->camera_from_lidar});
  if (baseline_m > 0) {
    Mat4d camera_from_right = Mat4d::Identity();
    camera_from_right(0, 3) = baseline_m;
    mounts.push_back({kBaseFrame, kRightCameraFrame, base_from_camera * camera_from_right});
  }
  return mounts;
}

/// The frame's image of RGB folder `folder` as a sensor_msgs/Image (rgb8) with `header`.
std::vector<uint8_t> rgb8_message(const Dataset& d, const DatasetFrame& f, const std::string& folder,
                                  const RosHeader& header) {
  cv::Mat image = d.image(f, folder, CV_8UC3);
  cv::cvtColor(image, image, cv::COLOR_BGR2RGB);
  return encode_image(header, uint32_t(d.width), uint32_t(d.height), "rgb8", 3 * uint32_t(d.width), pixels(image));
}

/// Writes the right camera's camera info (`camera`: the pair's shared intrinsics) and RGB (when the dataset has rgb)
/// of frame `f` at time t.
template <class Put>
void put_right_camera(const Dataset& d, const DatasetFrame& f, const Camera& camera, uint64_t t, double baseline_m,
                      const Put& put) {
  const RosHeader at_right{t, kRightCameraFrame};
  put("/camera/right/camera_info", t, encode_camera_info(at_right, camera, baseline_m));
  if (d.has("rgb")) put("/camera/right/image_raw", t, rgb8_message(d, f, camera_folder("rgb", true), at_right));
}


/// rosbag2's metadata.yaml for one MCAP file.
std::string metadata_yaml(const std::string& file, const std::vector<Topic>& topics,
                          const std::map<uint16_t, uint64_t>& counts, uint64_t start_ns, uint64_t end_ns) {
  uint64_t total = 0;
  for (const auto& [channel, n] : counts) total += n;
  std::ostringstream y;
  y << "rosbag2_bagfile_information:\n  version: 5\n  storage_identifier: mcap\n  duration:\n    nanoseconds: "
    << (end_ns - start_ns) << "\n  starting_time:\n    nanoseconds_since_epoch: " << start_ns
    << "\n  message_count: " << total << "\n  topics_with_message_count:\n";
  for (const Topic& t : topics) {
    std::string qos;
    for (const char c : t.qos) qos += c == '\n' ? std::string("\\n") : std::string(1, c);
    y << "    - topic_metadata:\n        name: " << t.name << "\n        type: " << ros_type_name(t.type)
      << "\n        serialization_format: cdr\n        offered_qos_profiles: \"" << qos
      << "\"\n      message_count: " << counts.at(t.channel) << "\n";
  }
  y << "  compression_format: \"\"\n  compression_mode: \"\"\n  relative_file_paths:\n    - " << file
    << "\n  files:\n    - path: " << file << "\n      starting_time:\n        nanoseconds_since_epoch: " << start_ns
    << "\n      duration:\n        nanoseconds: " << (end_ns - start_ns) << "\n      message_count: " << total << "\n";
  return y.str();
}

/// The trajectory sequence's IMU readings (imu.csv, with imu.yaml's noise as covariances) for its bag's /imu
/// topic, written between the frames in time order; inactive for every other sequence.
class ImuTopic {
 public:
  ImuTopic(const Dataset& d, const std::string& sequence) {
    if (sequence != "trajectory") return;
    readings_ = read_euroc_imu_csv(d.dir / sequence / "imu.csv");
    const KalibrImu model = read_kalibr_imu_yaml(d.dir / sequence / "imu.yaml");
    gyro_variance_ = model.noise.gyro_noise_density * model.noise.gyro_noise_density * model.rate_hz;
    accel_variance_ = model.noise.accel_noise_density * model.noise.accel_noise_density * model.rate_hz;
    active_ = true;
  }
  /// True for the trajectory sequence.
  bool active() const { return active_; }
  /// Stamp of the first reading (the largest stamp when there is none).
  uint64_t first_stamp() const { return readings_.empty() ? UINT64_MAX : uint64_t(readings_.front().t_ns); }
  /// Stamp of the last reading (0 when there is none).
  uint64_t last_stamp() const { return readings_.empty() ? 0 : uint64_t(readings_.back().t_ns); }
  /// Writes the readings from index `next` up to time t with `put(topic, stamp, bytes)`, advancing `next`.
  template <class Put>
  void write_until(uint64_t t, size_t& next, const Put& put) const {
    for (; next < readings_.size() && uint64_t(readings_[next].t_ns) <= t; ++next) {
      const ImuSample& r = readings_[next];
      const uint64_t at = uint64_t(r.t_ns);
      put("/imu", at, encode_imu({at, kCameraFrame}, r.gyro, gyro_variance_, r.accel, accel_variance_));
    }
  }

 private:
  std::vector<ImuSample> readings_;
  double gyro_variance_ = 0, accel_variance_ = 0;
  bool active_ = false;
};

/// The topics of a bag of `d`: the poses and camera info always, each image and the LiDAR when the dataset has
/// them, /imu with `imu`.
std::vector<Topic> bag_topics(const Dataset& d, bool imu) {
  std::vector<Topic> topics = {{"/tf_static", RosType::TFMessage, kLatchedQos},
                               {"/tf", RosType::TFMessage, ""},
                               {"/odom", RosType::Odometry, ""},
                               {"/camera/camera_info", RosType::CameraInfo, ""}};
  if (d.has("rgb")) topics.push_back({"/camera/image_raw", RosType::Image, ""});
  if (d.has("depth") || d.has("depth_exr")) topics.push_back({"/camera/depth/image_raw", RosType::Image, ""});
  if (d.has("semantic")) topics.push_back({"/camera/semantic/image_raw", RosType::Image, ""});
  if (d.has("instance")) topics.push_back({"/camera/instance/image_raw", RosType::Image, ""});
  if (d.has("lidar")) topics.push_back({"/lidar/points", RosType::PointCloud2, ""});
  if (imu) topics.push_back({"/imu", RosType::Imu, ""});
  if (manifest_stereo(d.manifest)) {
    topics.push_back({"/camera/right/camera_info", RosType::CameraInfo, ""});
    if (d.has("rgb")) topics.push_back({"/camera/right/image_raw", RosType::Image, ""});
  }
  return topics;
}

/// Writes one sequence's frames (`frames`, indices into d.frames in frame order) as the bag folder `bag`.
void write_bag(const Dataset& d, const std::string& sequence, const std::vector<size_t>& frames, const fs::path& bag,
               const ExportOptions& options, size_t& done) {
  create_folder(bag);
  const std::string file = sequence + "_0.mcap";
  McapWriter mcap(bag / file, "ros2", "silva");
  const bool lidar = d.has("lidar"), rgb = d.has("rgb"), depth = d.has("depth") || d.has("depth_exr"),
             semantic = d.has("semantic"), instance = d.has("instance");
  const ImuTopic imu(d, sequence);
  std::vector<Topic> topics = bag_topics(d, imu.active());
  const double camera_hz = imu.active() ? trajectory_camera_hz(d) : 0.0;
  const auto stamp = [&](const DatasetFrame& f) {  // trajectory frames at their capture times
    return imu.active() ? uint64_t(std::llround(double(f.frame) * 1e9 / camera_hz))
                        : uint64_t(f.frame) * kRosbagFramePeriodNs;
  };
  std::map<RosType, uint16_t> schema;
  std::map<std::string, uint16_t> channel;
  for (Topic& t : topics) {
    if (!schema.contains(t.type)) schema[t.type] = mcap.add_schema(ros_type_name(t.type), "ros2msg", ros_type_definition(t.type));
    std::map<std::string, std::string> metadata;
    metadata["offered_qos_profiles"] = t.qos;
    t.channel = mcap.add_channel(t.name, schema[t.type], "cdr", metadata);
    channel[t.name] = t.channel;
  }
  const LidarBeams beams = lidar ? lidar_beams(d) : LidarBeams{};
  const Mat4d base_from_camera = base_from_optical();
  const auto put = [&](const std::string& topic, uint64_t t, const std::vector<uint8_t>& bytes) {
    mcap.write(channel.at(topic), t, t, bytes);
  };
  const uint64_t start = std::min(stamp(d.frames[frames.front()]), imu.first_stamp());
  size_t next_imu = 0;
  const double baseline = stereo_baseline(d);
  put("/tf_static", start, encode_tf(start, static_mounts(lidar ? &beams : nullptr, baseline)));
  uint64_t last = start;
  for (const size_t i : frames) {
    const DatasetFrame& f = d.frames[i];
    const uint64_t t = stamp(f);
    imu.write_until(t, next_imu, put);
    const CameraRecord cam = read_camera_json(d.file(f, "camera", "json"));
    const Mat4d map_from_base = cam.camera.camera_to_world * base_from_camera.transpose();
    const std::vector<RosTransform> pose = {{kMapFrame, kBaseFrame, map_from_base}};
    put("/tf", t, encode_tf(t, pose));
    put("/odom", t, encode_odometry({t, kMapFrame}, kBaseFrame, map_from_base));
    const RosHeader at_camera{t, kCameraFrame};
    put("/camera/camera_info", t, encode_camera_info(at_camera, cam.camera));
    if (cam.camera.width != d.width || cam.camera.height != d.height)
      throw InputError(d.file(f, "camera", "json").string() + ": " + std::to_string(cam.camera.width) + "x" +
                       std::to_string(cam.camera.height) + ", not the run's output.resolution");
    const uint32_t w = uint32_t(d.width), h = uint32_t(d.height);
    if (rgb) put("/camera/image_raw", t, rgb8_message(d, f, "rgb", at_camera));
    if (depth) {
      const cv::Mat m = d.depth_metres(f, false);
      if (m.cols != int(w) || m.rows != int(h))
        throw InputError(d.file(f, d.has("depth_exr") ? "depth_exr" : "depth", d.has("depth_exr") ? "exr" : "png").string() +
                         ": not the size its camera file gives");
      put("/camera/depth/image_raw", t, encode_image(at_camera, w, h, "32FC1", 4 * w, pixels(m)));
    }
    if (semantic)
      put("/camera/semantic/image_raw", t,
          encode_image(at_camera, w, h, "mono8", w, pixels(d.image(f, "semantic", CV_8UC1))));
    if (instance)
      put("/camera/instance/image_raw", t,
          encode_image(at_camera, w, h, "mono16", 2 * w,
                       pixels(d.image(f, "instance", CV_16UC1))));
    if (lidar) put("/lidar/points", t, encode_point_cloud({t, kLidarFrame}, scan_points(d, f, beams)));
    if (baseline > 0) put_right_camera(d, f, cam.camera, t, baseline, put);
    last = t;
    ++done;
    if (options.progress) options.progress(done, d.frames.size());
  }
  imu.write_until(UINT64_MAX, next_imu, put);
  last = std::max(last, imu.last_stamp());
  mcap.close();
  std::map<uint16_t, uint64_t> counts = mcap.message_counts();
  write_file_atomic(bag / "metadata.yaml", metadata_yaml(file, topics, counts, start, last));
}

}  // namespace

void export_rosbag2(const Dataset& dataset, const fs::path& out, const ExportOptions& options) {
  std::map<std::string, std::vector<size_t>> sequences;
  std::vector<std::string> order;
  for (size_t i = 0; i < dataset.frames.size(); ++i) {
    const std::string& s = dataset.frames[i].sequence;
    if (!sequences.contains(s)) order.push_back(s);
    sequences[s].push_back(i);
  }
  size_t done = 0;
  if (options.progress) options.progress(0, dataset.frames.size());
  for (const std::string& s : order) write_bag(dataset, s, sequences[s], out / s, options, done);
}

}  // namespace silva::io
