/// @file Camera rays through pixel centres (see camera_rays.hpp).
#include "raycast/camera_rays.hpp"

#include <array>
#include <stdexcept>

#include <tbb/parallel_for.h>

namespace silva::raycast {

namespace {
/// Side of the square pixel blocks cast as one packet of 16 rays.
constexpr int kBlock = 4;
/// Rays made and cast together (a multiple of 16, so packets stay whole blocks).
constexpr size_t kBatch = 256;
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
                 std::span<RayHit> hits, bool exact_masks) {
  if (pixels.size() != hits.size()) throw std::invalid_argument("cast_pixels: pixels and hits differ in size");
  const uint32_t w = uint32_t(camera.width);
  CastOptions options;
  options.eye = camera.position();
  options.exact_masks = exact_masks;
  // Rays are made per batch on the stack, so a whole frame's rays are never held at once.
  const size_t batches = (pixels.size() + kBatch - 1) / kBatch;
  tbb::parallel_for(size_t(0), batches, [&](size_t b) {
    std::array<Ray, kBatch> rays;
    const size_t first = b * kBatch, n = std::min(kBatch, pixels.size() - first);
    for (size_t k = 0; k < n; ++k) {
      Ray& ray = rays[k];
      ray.origin = options.eye;
      ray.direction = camera.ray_direction(int(pixels[first + k] % w), int(pixels[first + k] / w));
      ray.t_near = camera.near;  // the direction has camera z = 1, so t is camera z
      ray.t_far = camera.far;
    }
    scene.cast(std::span<const Ray>(rays.data(), n), hits.subspan(first, n), options);
  });
}

}  // namespace silva::raycast
