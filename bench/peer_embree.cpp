/// @file Embree 3 visibility peer (see peer_embree.hpp), on the raycast/ scene.
#include "bench/peer_embree.hpp"

#include <vector>

#include "core/stopwatch.hpp"
#include "raycast/camera_rays.hpp"
#include "raycast/ray_scene.hpp"

namespace silva::bench {

struct EmbreePeer::Impl {
  PeerView view;
  raycast::RayScene scene;
  double setup_ms = 0;
};

EmbreePeer::EmbreePeer(const PeerView& view) : impl_(std::make_unique<Impl>()) {
  impl_->view = view;
  const Stopwatch clock;
  const render::Scene& s = *view.scene;
  std::vector<raycast::RayInstance> instances(s.instances.size());
  for (size_t i = 0; i < s.instances.size(); ++i) {
    const render::Instance& inst = s.instances[i];
    instances[i].mesh = s.meshes[inst.mesh].lods[0];
    instances[i].object_to_world = inst.object_to_world;
    instances[i].instance_id = inst.instance_id;
    instances[i].tag = uint32_t(i);
  }
  impl_->scene.add_group(0, instances);
  impl_->scene.commit();
  impl_->setup_ms = 1000 * clock.seconds();
}

EmbreePeer::~EmbreePeer() = default;

void EmbreePeer::render(PeerFrame& out) const {
  const Camera& cam = *impl_->view.camera;
  if (out.width != cam.width || out.height != cam.height) out.resize(cam.width, cam.height);
  const std::vector<uint32_t> pixels = raycast::block_order(cam.width, cam.height);
  std::vector<raycast::RayHit> hits(pixels.size());
  raycast::cast_pixels(impl_->scene, cam, pixels, hits);
  std::fill(out.instance.begin(), out.instance.end(), render::kNoInstance);
  std::fill(out.depth.begin(), out.depth.end(), 0.0f);
  std::fill(out.triangle.begin(), out.triangle.end(), 0u);
  for (size_t k = 0; k < pixels.size(); ++k) {
    const raycast::RayHit& h = hits[k];
    if (!h.hit) continue;
    out.depth[pixels[k]] = h.t;
    out.instance[pixels[k]] = h.tag;
    out.triangle[pixels[k]] = h.triangle;
  }
}

double EmbreePeer::setup_ms() const { return impl_->setup_ms; }

}  // namespace silva::bench
