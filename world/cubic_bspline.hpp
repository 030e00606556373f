#pragma once
/// @file A uniform cubic B-spline in time: C2-smooth curves through noisy or kinked samples, with
/// exact first and second derivatives (the trajectory's velocity and acceleration).
#include <vector>

#include <Eigen/Core>

namespace silva::world {

/// Uniform cubic B-spline of 4-vectors over control values spaced `step` seconds apart; control value i
/// sits at time (i - 1) * step, so with n values the curve is defined on [0, (n - 3) * step].
class CubicBSpline {
 public:
  /// Value and its first and second time derivatives at one time.
  struct Sample {
    Eigen::Vector4d value;         ///< Curve value.
    Eigen::Vector4d rate;          ///< d/dt.
    Eigen::Vector4d acceleration;  ///< d²/dt².
  };
  /// A spline over `control` (at least 4 values), `step` > 0 seconds apart.
  CubicBSpline(std::vector<Eigen::Vector4d> control, double step);
  /// The curve at time t, clamped to its domain.
  Sample at(double t) const;
  /// Last time of the domain, (n - 3) * step.
  double end() const { return double(control_.size() - 3) * step_; }

 private:
  std::vector<Eigen::Vector4d> control_;
  double step_;
};

}  // namespace silva::world
