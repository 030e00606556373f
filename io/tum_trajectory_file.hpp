#pragma once
/// @file A user's timed camera trajectory in TUM form (config trajectory.file; CONTRACT.md "Capture sequences").
#include <filesystem>
#include <string>
#include <vector>

#include "core/timed_pose.hpp"

namespace silva::io {

/// Most poses a trajectory file may hold (an hour at 250 Hz).
inline constexpr size_t kMaxTrajectoryPoses = 900'000;
/// How far a quaternion's norm may be from 1.
inline constexpr double kUnitQuaternionTolerance = 1e-3;

/// Parses TUM trajectory text: per line "t x y z qx qy qz qw" (seconds, world metres, the unit quaternion of
/// camera_to_world), '#' lines and blank lines skipped; `source` names the file in errors. InputError naming the
/// line unless each has 8 finite numbers, times strictly increase, |q| is 1 within kUnitQuaternionTolerance and the
/// camera stays inside the world (|x|, |y| <= 100 km, |z| <= 10 km); and unless there are 2 ...
/// kMaxTrajectoryPoses poses spanning 0.1 ... 3600 s.
std::vector<TimedPose> parse_tum_trajectory(const std::string& text, const std::string& source);

/// Reads and parses a trajectory file (parse_tum_trajectory); InputError naming the path when it cannot be read.
std::vector<TimedPose> read_tum_trajectory(const std::filesystem::path& path);

}  // namespace silva::io
