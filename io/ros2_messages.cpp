#include "io/ros2_messages.hpp"

#include <array>
#include <cstring>

#include <Eigen/Geometry>

#include "io/cdr_writer.hpp"

namespace silva::io {

namespace {

// Definitions of the ROS 2 (Humble and later) interface files, fields only (constants where a reader needs them).
const char* const kTime = "int32 sec\nuint32 nanosec\n";
const char* const kHeader = "builtin_interfaces/Time stamp\nstring frame_id\n";
const char* const kImage =
    "std_msgs/Header header\nuint32 height\nuint32 width\nstring encoding\nuint8 is_bigendian\nuint32 step\n"
    "uint8[] data\n";
const char* const kRegionOfInterest = "uint32 x_offset\nuint32 y_offset\nuint32 height\nuint32 width\nbool do_rectify\n";
const char* const kCameraInfo =
    "std_msgs/Header header\nuint32 height\nuint32 width\nstring distortion_model\nfloat64[] d\nfloat64[9] k\n"
    "float64[9] r\nfloat64[12] p\nuint32 binning_x\nuint32 binning_y\nsensor_msgs/RegionOfInterest roi\n";
const char* const kPointField =
    "uint8 INT8 = 1\nuint8 UINT8 = 2\nuint8 INT16 = 3\nuint8 UINT16 = 4\nuint8 INT32 = 5\nuint8 UINT32 = 6\n"
    "uint8 FLOAT32 = 7\nuint8 FLOAT64 = 8\nstring name\nuint32 offset\nuint8 datatype\nuint32 count\n";
const char* const kPointCloud2 =
    "std_msgs/Header header\nuint32 height\nuint32 width\nsensor_msgs/PointField[] fields\nbool is_bigendian\n"
    "uint32 point_step\nuint32 row_step\nuint8[] data\nbool is_dense\n";
const char* const kVector3 = "float64 x\nfloat64 y\nfloat64 z\n";
const char* const kQuaternion = "float64 x 0\nfloat64 y 0\nfloat64 z 0\nfloat64 w 1\n";
const char* const kTransform = "geometry_msgs/Vector3 translation\ngeometry_msgs/Quaternion rotation\n";
const char* const kTransformStamped = "std_msgs/Header header\nstring child_frame_id\ngeometry_msgs/Transform transform\n";
const char* const kTFMessage = "geometry_msgs/TransformStamped[] transforms\n";
const char* const kPoint = "float64 x\nfloat64 y\nfloat64 z\n";
const char* const kPose = "geometry_msgs/Point position\ngeometry_msgs/Quaternion orientation\n";
const char* const kPoseWithCovariance = "geometry_msgs/Pose pose\nfloat64[36] covariance\n";
const char* const kTwist = "geometry_msgs/Vector3 linear\ngeometry_msgs/Vector3 angular\n";
const char* const kTwistWithCovariance = "geometry_msgs/Twist twist\nfloat64[36] covariance\n";
const char* const kOdometry =
    "std_msgs/Header header\nstring child_frame_id\ngeometry_msgs/PoseWithCovariance pose\n"
    "geometry_msgs/TwistWithCovariance twist\n";
const char* const kImu =
    "std_msgs/Header header\ngeometry_msgs/Quaternion orientation\nfloat64[9] orientation_covariance\n"
    "geometry_msgs/Vector3 angular_velocity\nfloat64[9] angular_velocity_covariance\n"
    "geometry_msgs/Vector3 linear_acceleration\nfloat64[9] linear_acceleration_covariance\n";

/// `main`, then each dependency after the separator rosbag2 uses.
std::string definition(const char* main, std::initializer_list<std::pair<const char*, const char*>> deps) {
  std::string text = main;
  for (const auto& [name, body] : deps)
    text += std::string(80, '=') + "\nMSG: " + name + "\n" + body;
  return text;
}

/// PointField datatypes.
constexpr uint8_t kUint16 = 4, kFloat32 = 7;

void put_header(CdrWriter& w, const RosHeader& h) {
  w.i32(int32_t(h.stamp_ns / 1'000'000'000ull));
  w.u32(uint32_t(h.stamp_ns % 1'000'000'000ull));
  w.string(h.frame_id);
}

/// geometry_msgs translation/position (x, y, z) then quaternion (x, y, z, w) of a rigid transform.
void put_pose(CdrWriter& w, const Mat4d& m) {
  const Eigen::Quaterniond q(Eigen::Matrix3d(m.block<3, 3>(0, 0)));
  for (int i = 0; i < 3; ++i) w.f64(m(i, 3));
  const Eigen::Quaterniond n = q.normalized();
  w.f64(n.x());
  w.f64(n.y());
  w.f64(n.z());
  w.f64(n.w());
}

}  // namespace

const std::string& ros_type_name(RosType type) {
  static const std::array<std::string, 6> names = {"sensor_msgs/msg/Image", "sensor_msgs/msg/CameraInfo",
                                                   "sensor_msgs/msg/PointCloud2", "tf2_msgs/msg/TFMessage",
                                                   "nav_msgs/msg/Odometry", "sensor_msgs/msg/Imu"};
  return names[size_t(type)];
}

const std::string& ros_type_definition(RosType type) {
  static const std::array<std::string, 6> texts = {
      definition(kImage, {{"std_msgs/Header", kHeader}, {"builtin_interfaces/Time", kTime}}),
      definition(kCameraInfo, {{"std_msgs/Header", kHeader},
                               {"builtin_interfaces/Time", kTime},
                               {"sensor_msgs/RegionOfInterest", kRegionOfInterest}}),
      definition(kPointCloud2, {{"std_msgs/Header", kHeader},
                                {"builtin_interfaces/Time", kTime},
                                {"sensor_msgs/PointField", kPointField}}),
      definition(kTFMessage, {{"geometry_msgs/TransformStamped", kTransformStamped},
                              {"std_msgs/Header", kHeader},
                              {"builtin_interfaces/Time", kTime},
                              {"geometry_msgs/Transform", kTransform},
                              {"geometry_msgs/Vector3", kVector3},
                              {"geometry_msgs/Quaternion", kQuaternion}}),
      definition(kOdometry, {{"std_msgs/Header", kHeader},
                             {"builtin_interfaces/Time", kTime},
                             {"geometry_msgs/PoseWithCovariance", kPoseWithCovariance},
                             {"geometry_msgs/Pose", kPose},
                             {"geometry_msgs/Point", kPoint},
                             {"geometry_msgs/Quaternion", kQuaternion},
                             {"geometry_msgs/TwistWithCovariance", kTwistWithCovariance},
                             {"geometry_msgs/Twist", kTwist},
                             {"geometry_msgs/Vector3", kVector3}}),
      definition(kImu, {{"std_msgs/Header", kHeader},
                        {"builtin_interfaces/Time", kTime},
                        {"geometry_msgs/Quaternion", kQuaternion},
                        {"geometry_msgs/Vector3", kVector3}}),
  };
  return texts[size_t(type)];
}

std::vector<uint8_t> encode_image(const RosHeader& header, uint32_t width, uint32_t height, const std::string& encoding,
                                  uint32_t step, std::span<const uint8_t> data) {
  CdrWriter w;
  put_header(w, header);
  w.u32(height);
  w.u32(width);
  w.string(encoding);
  w.u8(0);  // little-endian
  w.u32(step);
  w.bytes(data);
  return w.take();
}

std::vector<uint8_t> encode_camera_info(const RosHeader& header, const Camera& c, double baseline_m) {
  CdrWriter w;
  put_header(w, header);
  w.u32(uint32_t(c.height));
  w.u32(uint32_t(c.width));
  w.string("plumb_bob");
  const std::array<double, 5> d{};
  w.f64_array(d, false);
  const double cx = c.cx - 0.5, cy = c.cy - 0.5;
  const std::array<double, 9> k{c.fx, 0, cx, 0, c.fy, cy, 0, 0, 1};
  const std::array<double, 9> r{1, 0, 0, 0, 1, 0, 0, 0, 1};
  const double tx = baseline_m > 0 ? -c.fx * baseline_m : 0.0;  // never -0.0: one camera keeps P = [K | 0]
  const std::array<double, 12> p{c.fx, 0, cx, tx, 0, c.fy, cy, 0, 0, 0, 1, 0};
  w.f64_array(k, true);
  w.f64_array(r, true);
  w.f64_array(p, true);
  w.u32(0);  // binning_x
  w.u32(0);  // binning_y
  for (int i = 0; i < 4; ++i) w.u32(0);  // roi: the full image
  w.u8(0);
  return w.take();
}

std::vector<uint8_t> encode_point_cloud(const RosHeader& header, std::span<const RosPoint> points) {
  CdrWriter w;
  put_header(w, header);
  w.u32(1);
  w.u32(uint32_t(points.size()));
  struct Field {
    const char* name;
    uint32_t offset;
    uint8_t type;
  };
  const std::array<Field, 8> fields{{{"x", 0, kFloat32}, {"y", 4, kFloat32}, {"z", 8, kFloat32},
                                     {"intensity", 12, kFloat32}, {"time", 16, kFloat32}, {"ring", 20, kUint16},
                                     {"label", 22, kUint16}, {"instance", 24, kUint16}}};
  w.u32(uint32_t(fields.size()));
  for (const Field& f : fields) {
    w.string(f.name);
    w.u32(f.offset);
    w.u8(f.type);
    w.u32(1);
  }
  w.u8(0);  // little-endian
  w.u32(kRosPointStep);
  w.u32(kRosPointStep * uint32_t(points.size()));
  uint8_t* out = w.reserve_bytes(points.size() * kRosPointStep);
  for (const RosPoint& p : points) {
    std::memset(out, 0, kRosPointStep);
    const float f[5] = {p.x, p.y, p.z, p.intensity, p.time};
    const uint16_t u[3] = {p.ring, p.label, p.instance};
    std::memcpy(out, f, sizeof f);
    std::memcpy(out + 20, u, sizeof u);
    out += kRosPointStep;
  }
  w.u8(1);  // is_dense: every point is a return
  return w.take();
}

std::vector<uint8_t> encode_tf(uint64_t stamp_ns, std::span<const RosTransform> transforms) {
  CdrWriter w;
  w.u32(uint32_t(transforms.size()));
  for (const RosTransform& t : transforms) {
    put_header(w, {stamp_ns, t.parent});
    w.string(t.child);
    put_pose(w, t.parent_from_child);
  }
  return w.take();
}

std::vector<uint8_t> encode_odometry(const RosHeader& header, const std::string& child_frame, const Mat4d& pose) {
  CdrWriter w;
  put_header(w, header);
  w.string(child_frame);
  put_pose(w, pose);
  const std::array<double, 36> zero{};
  w.f64_array(zero, true);
  for (int i = 0; i < 6; ++i) w.f64(0.0);  // twist: unknown for still captures, reported as zero
  w.f64_array(zero, true);
  return w.take();
}

std::vector<uint8_t> encode_imu(const RosHeader& header, const Vec3d& angular_velocity, double gyro_variance,
                                const Vec3d& linear_acceleration, double accel_variance) {
  CdrWriter w;
  put_header(w, header);
  for (double q : {0.0, 0.0, 0.0, 1.0}) w.f64(q);
  std::array<double, 9> covariance{};
  covariance[0] = -1.0;  // no orientation estimate
  w.f64_array(covariance, true);
  const auto put_vector = [&w](const Vec3d& v, double variance) {
    for (int i = 0; i < 3; ++i) w.f64(v[i]);
    std::array<double, 9> diagonal{};
    diagonal[0] = diagonal[4] = diagonal[8] = variance;
    w.f64_array(diagonal, true);
  };
  put_vector(angular_velocity, gyro_variance);
  put_vector(linear_acceleration, accel_variance);
  return w.take();
}

}  // namespace silva::io
