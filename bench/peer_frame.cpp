/// @file PeerFrame conversion and comparison (see peer_frame.hpp).
#include "bench/peer_frame.hpp"

#include <cmath>
#include <stdexcept>

namespace silva::bench {

void PeerFrame::resize(int w, int h) {
  width = w;
  height = h;
  const size_t n = size_t(w) * size_t(h);
  depth.assign(n, 0.0f);
  instance.assign(n, render::kNoInstance);
  triangle.assign(n, 0);
}

PeerFrame from_visibility(const render::VisibilityBuffer& v) {
  PeerFrame f;
  f.resize(v.width, v.height);
  for (size_t i = 0; i < v.size(); ++i) {
    if (v.instance[i] == render::kNoInstance) continue;
    f.depth[i] = 1.0f / v.depth[i];
    f.instance[i] = v.instance[i];
    f.triangle[i] = v.triangle[i];
  }
  return f;
}

Agreement compare(const PeerFrame& peer, const PeerFrame& reference, double depth_tolerance) {
  if (peer.width != reference.width || peer.height != reference.height)
    throw std::invalid_argument("compare: frames differ in size");
  size_t same_instance = 0, same_triangle = 0, both_hit = 0, same_depth = 0;
  for (size_t i = 0; i < reference.instance.size(); ++i) {
    const bool inst = peer.instance[i] == reference.instance[i];
    same_instance += inst;
    same_triangle += inst && peer.triangle[i] == reference.triangle[i];
    if (peer.instance[i] == render::kNoInstance || reference.instance[i] == render::kNoInstance) continue;
    ++both_hit;
    same_depth += std::abs(double(peer.depth[i]) - double(reference.depth[i])) <= depth_tolerance * double(reference.depth[i]);
  }
  const double n = double(reference.instance.size());
  return {double(same_instance) / n, double(same_triangle) / n, both_hit ? double(same_depth) / double(both_hit) : 1.0};
}

}  // namespace silva::bench
