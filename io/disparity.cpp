#include "io/disparity.hpp"

#include <cmath>

namespace silva::io {

std::vector<uint16_t> kitti_disparity(std::span<const float> depth, double fx, double baseline_m) {
  std::vector<uint16_t> out(depth.size(), 0);
  const double scaled = 256.0 * fx * baseline_m;
  for (size_t i = 0; i < depth.size(); ++i) {
    if (!(depth[i] > 0)) continue;
    const double v = std::round(scaled / double(depth[i]));
    if (v >= 1 && v <= 65535) out[i] = uint16_t(v);
  }
  return out;
}

}  // namespace silva::io
