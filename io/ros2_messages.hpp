#pragma once
/// @file The ROS 2 messages a Silva bag holds (sensor_msgs Image, CameraInfo, PointCloud2; tf2_msgs TFMessage;
/// nav_msgs Odometry, sensor_msgs Imu): their ros2msg definitions, as rosbag2 stores them in an MCAP schema, and their CDR encoding.
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "core/camera.hpp"
#include "core/types.hpp"

namespace silva::io {

/// A message type a Silva bag uses.
enum class RosType { Image, CameraInfo, PointCloud2, TFMessage, Odometry, Imu };

/// The full type name, e.g. "sensor_msgs/msg/Image".
const std::string& ros_type_name(RosType type);

/// The ros2msg schema text: the type's definition, then each type it uses after a line of 80 '=' and
/// "MSG: <package>/<Type>", as rosbag2 writes them into MCAP schemas.
const std::string& ros_type_definition(RosType type);

/// A std_msgs/Header: stamp in nanoseconds and frame id.
struct RosHeader {
  uint64_t stamp_ns = 0;  ///< Seconds and nanoseconds of builtin_interfaces/Time, as one count.
  std::string frame_id;   ///< The frame the data is expressed in.
};

/// One geometry_msgs/TransformStamped: the pose of `child` in `parent`.
struct RosTransform {
  std::string parent, child;  ///< Frame ids (header.frame_id, child_frame_id).
  Mat4d parent_from_child = Mat4d::Identity();  ///< Rigid transform taking child coordinates into parent's.
};

/// A LiDAR return as the bag's PointCloud2 carries it.
struct RosPoint {
  float x = 0, y = 0, z = 0;  ///< Metres in the sensor frame.
  float intensity = 0;        ///< 0 ... 1.
  float time = 0;             ///< Seconds after the sweep began.
  uint16_t ring = 0;          ///< Beam index, 0 = lowest elevation.
  uint16_t label = 0;         ///< Ontology class id.
  uint16_t instance = 0;      ///< The scan's instance index (lidar_labels), 0 = none.
};

/// Bytes per point of encode_point_cloud (x, y, z, intensity, time float32; ring, label, instance uint16; padding).
inline constexpr uint32_t kRosPointStep = 32;

/// sensor_msgs/Image of `height` rows of `step` bytes.
std::vector<uint8_t> encode_image(const RosHeader& header, uint32_t width, uint32_t height, const std::string& encoding,
                                  uint32_t step, std::span<const uint8_t> data);

/// sensor_msgs/CameraInfo of a Silva pinhole camera: plumb_bob with zero distortion, R = I, P = [K | t] with
/// t = (-fx · baseline_m, 0, 0) (a rectified pair's right camera; 0 for the left or only one); the principal point
/// moved by -0.5 px (ROS puts pixel centres at integer coordinates, Silva at +0.5).
std::vector<uint8_t> encode_camera_info(const RosHeader& header, const Camera& camera, double baseline_m = 0.0);

/// sensor_msgs/PointCloud2 of one unorganised scan (height 1), fields x y z intensity time ring label instance.
std::vector<uint8_t> encode_point_cloud(const RosHeader& header, std::span<const RosPoint> points);

/// tf2_msgs/TFMessage of `transforms`, all stamped `stamp_ns`.
std::vector<uint8_t> encode_tf(uint64_t stamp_ns, std::span<const RosTransform> transforms);

/// nav_msgs/Odometry: the pose of `child_frame` in header.frame_id; twist and both covariances zero.
std::vector<uint8_t> encode_odometry(const RosHeader& header, const std::string& child_frame, const Mat4d& pose);

/// sensor_msgs/Imu of one reading: orientation unknown (orientation_covariance[0] = -1, REP 145), the angular
/// velocity and linear acceleration with diagonal covariances of the variances given per axis.
std::vector<uint8_t> encode_imu(const RosHeader& header, const Vec3d& angular_velocity, double gyro_variance,
                                const Vec3d& linear_acceleration, double accel_variance);

}  // namespace silva::io
