#pragma once
/// @file The rasteriser's entry point: scene + camera in, visibility buffer / G-buffer / shadow map out.
#include <cstdint>
#include <memory>
#include <span>

#include "core/aabb.hpp"
#include "core/camera.hpp"
#include "render/gbuffer.hpp"
#include "render/render_options.hpp"
#include "render/scene.hpp"
#include "render/visibility.hpp"

namespace silva::render {

/// Renders views of scenes. Owns the thread-local scratch, bins and buffers, so repeated frames
/// reuse their memory; keep one per thread of control (calls on one Renderer must not overlap).
/// Work runs on TBB in the caller's task_arena; output is bit-identical for any thread count and
/// any SIMD target.
class Renderer {
 public:
  /// An empty renderer; buffers grow on first use.
  Renderer();
  /// Frees the buffers.
  ~Renderer();
  Renderer(const Renderer&) = delete;
  Renderer& operator=(const Renderer&) = delete;

  /// Visibility pass + resolve: fills `out` (resized when its size differs from the camera's).
  void render_gbuffer(const Scene& scene, const Camera& camera, const RenderOptions& options, GBuffer& out,
                      RenderStats* stats = nullptr);
  /// Visibility pass only; the returned buffer lives until the next camera pass of this renderer.
  const VisibilityBuffer& render_visibility(const Scene& scene, const Camera& camera, const RenderOptions& options,
                                            RenderStats* stats = nullptr);
  /// LOD drawn per instance by the last camera pass (kCulled for culled instances).
  std::span<const uint32_t> instance_lods() const;
  /// Depth-only orthographic sun pass over `region` (all faces cast; see ShadowMap in gbuffer.hpp).
  ShadowMap render_shadow_map(const Scene& scene, const Vec3d& direction_to_sun, const AABB& region, int resolution,
                              const RenderOptions& options, RenderStats* stats = nullptr);
  /// As above, filling `out` in place to reuse its depth storage.
  void render_shadow_map(const Scene& scene, const Vec3d& direction_to_sun, const AABB& region, int resolution,
                         const RenderOptions& options, ShadowMap& out, RenderStats* stats = nullptr);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

/// One shadow map with a temporary Renderer (convenience; a Renderer reuses its memory).
ShadowMap render_shadow_map(const Scene& scene, const Vec3d& direction_to_sun, const AABB& region, int resolution,
                            const RenderOptions& options);

}  // namespace silva::render
