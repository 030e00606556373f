/// @file Camera rays through pixel centres (see camera_rays.hpp).
#include "raycast/camera_rays.hpp"

#include <stdexcept>

#include <tbb/parallel_for.h>

namespace silva::raycast {

namespace {
/// Side of the square pixel blocks cast as one packet of 16 rays.
constexpr int kBlock = 4;
}  // namespace

std::vector<uint32_t> block_order(int width, int height) {
  std::vector<uint32_t> order;
  order.reserve(size_t(width) * size_t(height));
  for (int by = 0; by < height; by += kBlock)
    for (int bx = 0; bx < width; bx += kBlock)
      for (int y = by; y < std::min(height, by + kBlock); ++y)
        for (int x = bx; x < std::min(width, bx + kBlock); ++x) order.push_back(uint32_t(y) * uint32_t(width) + uint32_t(x));
  return order;
}

void cast_pixels(const RayScene& scene, const Camera& camera, std::span<const uint32_t> pixels,
                 std::span<RayHit> hits) {
  if (pixels.size() != hits.size()) throw std::invalid_argument("cast_pixels: pixels and hits differ in size");
  const Vec3d origin = camera.position();
  const uint32_t w = uint32_t(camera.width);
  std::vector<Ray> rays(pixels.size());
  tbb::parallel_for(size_t(0), pixels.size(), [&](size_t k) {
    Ray& ray = rays[k];
    ray.origin = origin;
    ray.direction = camera.ray_direction(int(pixels[k] % w), int(pixels[k] / w));
    ray.t_near = camera.near;  // the direction has camera z = 1, so t is camera z
    ray.t_far = camera.far;
  });
  CastOptions options;
  options.eye = origin;
  scene.cast(rays, hits, options);
}

}  // namespace silva::raycast
