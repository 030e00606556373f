#include "io/tum_trajectory_file.hpp"

#include <cmath>
#include <sstream>

#include <Eigen/Geometry>

#include "core/error.hpp"
#include "core/input_limits.hpp"
#include "io/printf_string.hpp"

namespace silva::io {

namespace {

/// The pose of one data line, or InputError naming `where` (file and line).
TimedPose parse_pose(const std::string& line, const std::string& where) {
  std::istringstream in(line);
  double v[8];
  for (double& x : v)
    if (!(in >> x) || !std::isfinite(x)) throw InputError(where + ": want 't x y z qx qy qz qw', 8 finite numbers");
  std::string rest;
  if (in >> rest) throw InputError(where + ": want 't x y z qx qy qz qw', 8 finite numbers; found more");
  Eigen::Quaterniond q(v[7], v[4], v[5], v[6]);
  const double norm = q.norm();
  if (std::abs(norm - 1.0) > kUnitQuaternionTolerance)
    throw InputError(where + printf_string(": quaternion (qx qy qz qw) has norm %.6g; TUM poses need unit "
                                           "quaternions (norm 1 within %g)", norm, kUnitQuaternionTolerance));
  if (std::max(std::abs(v[1]), std::abs(v[2])) > limits::kMaxPoseCoordinate || std::abs(v[3]) > limits::kMaxPoseHeight)
    throw InputError(where + ": puts the camera outside the world (|x|, |y| <= 100000 m, |z| <= 10000 m)");
  q.normalize();
  return {v[0], Vec3d(v[1], v[2], v[3]), q.toRotationMatrix()};
}

}  // namespace

std::vector<TimedPose> parse_tum_trajectory(const std::string& text, const std::string& source) {
  std::istringstream in(text);
  std::vector<TimedPose> poses;
  int line_number = 0;
  for (std::string line; std::getline(in, line);) {
    ++line_number;
    const size_t first = line.find_first_not_of(" \t\r");
    if (first == std::string::npos || line[first] == '#') continue;
    const std::string where = source + ": line " + std::to_string(line_number);
    TimedPose pose = parse_pose(line, where);
    if (!poses.empty() && !(pose.t > poses.back().t))
      throw InputError(where + printf_string(": time %.9g s is not after the previous line's %.9g s (times must "
                                             "strictly increase)", pose.t, poses.back().t));
    if (poses.size() == kMaxTrajectoryPoses)
      throw InputError(source + ": more than " + std::to_string(kMaxTrajectoryPoses) + " poses");
    poses.push_back(pose);
  }
  if (poses.size() < 2) throw InputError(source + ": a trajectory needs at least 2 poses, found " + std::to_string(poses.size()));
  const double span = poses.back().t - poses.front().t;
  if (!(span >= 0.1 && span <= 3600))
    throw InputError(source + printf_string(": spans %.9g s; a trajectory spans 0.1 ... 3600 s", span));
  return poses;
}

std::vector<TimedPose> read_tum_trajectory(const std::filesystem::path& path) {
  return parse_tum_trajectory(limits::read_input_file(path, "trajectory file"), path.string());
}

}  // namespace silva::io
