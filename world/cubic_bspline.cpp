#include "world/cubic_bspline.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace silva::world {

CubicBSpline::CubicBSpline(std::vector<Eigen::Vector4d> control, double step)
    : control_(std::move(control)), step_(step) {
  if (control_.size() < 4 || !(step_ > 0)) throw std::invalid_argument("CubicBSpline needs 4 values and a step > 0");
}

CubicBSpline::Sample CubicBSpline::at(double t) const {
  const double x = std::clamp(t, 0.0, end()) / step_;
  const size_t j = std::min(size_t(x), control_.size() - 4);
  const double u = x - double(j), v = 1.0 - u;
  // The uniform cubic basis on segment j and its derivatives with respect to u.
  const double b[4] = {v * v * v / 6.0, (3.0 * u * u * u - 6.0 * u * u + 4.0) / 6.0,
                       (-3.0 * u * u * u + 3.0 * u * u + 3.0 * u + 1.0) / 6.0, u * u * u / 6.0};
  const double db[4] = {-v * v / 2.0, (3.0 * u * u - 4.0 * u) / 2.0, (-3.0 * u * u + 2.0 * u + 1.0) / 2.0, u * u / 2.0};
  const double ddb[4] = {v, 3.0 * u - 2.0, 1.0 - 3.0 * u, u};
  Sample s{Eigen::Vector4d::Zero(), Eigen::Vector4d::Zero(), Eigen::Vector4d::Zero()};
  for (int k = 0; k < 4; ++k) {
    const Eigen::Vector4d& c = control_[j + size_t(k)];
    s.value += b[k] * c;
    s.rate += db[k] / step_ * c;
    s.acceleration += ddb[k] / (step_ * step_) * c;
  }
  return s;
}

}  // namespace silva::world
