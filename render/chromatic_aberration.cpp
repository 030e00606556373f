#include "render/chromatic_aberration.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

namespace silva::render {

void apply_chromatic_aberration(const LinearFrame& in, const Camera& camera, float k, LinearFrame& out) {
  out.resize(in.width, in.height);
  const float cx = float(camera.cx), cy = float(camera.cy);
  tbb::parallel_for(tbb::blocked_range<int>(0, in.height), [&](const tbb::blocked_range<int>& rows) {
    for (int v = rows.begin(); v < rows.end(); ++v)
      for (int u = 0; u < in.width; ++u) {
        const float dx = float(u) + 0.5f - cx, dy = float(v) + 0.5f - cy;
        const Vec3f red = in.bilinear(cx + dx * (1.0f - k), cy + dy * (1.0f - k));
        const Vec3f blue = in.bilinear(cx + dx * (1.0f + k), cy + dy * (1.0f + k));
        out.rgb[size_t(v) * size_t(in.width) + size_t(u)] = Vec3f(red.x(), in.at(u, v).y(), blue.z());
      }
  });
}

}  // namespace silva::render
