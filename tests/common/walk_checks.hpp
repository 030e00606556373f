#pragma once
/// @file A check shared by the walk tests: a state's velocity, acceleration and turn rate are the derivatives of the
/// walk's pose.
#include <gtest/gtest.h>

#include "world/trajectory.hpp"

namespace silva::test {

/// Expects walk.at(t)'s velocity, acceleration and angular velocity (camera axes) to match central differences
/// of the walk's position, velocity and rotation over ±1e-5 s.
inline void expect_exact_derivatives(const world::Trajectory& walk, double t) {
  const double h = 1e-5;
  const world::RigState s = walk.at(t), before = walk.at(t - h), after = walk.at(t + h);
  EXPECT_LT(((after.position - before.position) / (2 * h) - s.velocity).norm(), 1e-6) << t;
  EXPECT_LT(((after.velocity - before.velocity) / (2 * h) - s.acceleration).norm(), 1e-4) << t;
  // R(t + h) = R(t) exp(h [w]x) to first order, w in the camera's axes.
  const Mat3d turn = (s.rotation.transpose() * after.rotation - s.rotation.transpose() * before.rotation) / (2 * h);
  EXPECT_LT((Vec3d(turn(2, 1), turn(0, 2), turn(1, 0)) - s.angular_velocity).norm(), 1e-6) << t;
}

}  // namespace silva::test
