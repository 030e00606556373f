/// @file Embree 3 visibility peer (see peer_embree.hpp), on the raycast/ scene.
#include "bench/peer_embree.hpp"

#include <vector>

#include <tbb/parallel_for.h>

#include "core/stopwatch.hpp"
#include "raycast/ray_scene.hpp"

namespace silva::bench {

namespace {
/// Side of the square pixel blocks traced as one packet (kPacket^2 = 16 rays).
constexpr int kPacket = 4;
}  // namespace

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
  const int bw = (cam.width + kPacket - 1) / kPacket, bh = (cam.height + kPacket - 1) / kPacket;
  const Mat3d r = cam.camera_to_world.block<3, 3>(0, 0);
  const Vec3d o = cam.position();
  // Rays in 4x4 blocks, so each packet of 16 is one coherent block (pixels outside the image repeat the last).
  std::vector<raycast::Ray> rays(size_t(bw) * size_t(bh) * 16);
  std::vector<raycast::RayHit> hits(rays.size());
  tbb::parallel_for(0, bw * bh, [&](int b) {
    for (int k = 0; k < 16; ++k) {
      const int x = std::min(cam.width - 1, b % bw * kPacket + k % kPacket);
      const int y = std::min(cam.height - 1, b / bw * kPacket + k / kPacket);
      raycast::Ray& ray = rays[size_t(b) * 16 + size_t(k)];
      ray.origin = o;
      ray.direction = r * Vec3d((double(x) + 0.5 - cam.cx) / cam.fx, (double(y) + 0.5 - cam.cy) / cam.fy, 1.0);
      ray.t_near = cam.near;  // the direction has camera z = 1, so t is camera z
      ray.t_far = cam.far;
    }
  });
  impl_->scene.cast(rays, hits);
  std::fill(out.instance.begin(), out.instance.end(), render::kNoInstance);
  std::fill(out.depth.begin(), out.depth.end(), 0.0f);
  std::fill(out.triangle.begin(), out.triangle.end(), 0u);
  for (int b = 0; b < bw * bh; ++b)
    for (int k = 0; k < 16; ++k) {
      const int x = b % bw * kPacket + k % kPacket, y = b / bw * kPacket + k / kPacket;
      const raycast::RayHit& h = hits[size_t(b) * 16 + size_t(k)];
      if (x >= cam.width || y >= cam.height || !h.hit) continue;
      const size_t p = size_t(y) * size_t(cam.width) + size_t(x);
      out.depth[p] = h.t;
      out.instance[p] = h.tag;
      out.triangle[p] = h.triangle;
    }
}

double EmbreePeer::setup_ms() const { return impl_->setup_ms; }

}  // namespace silva::bench
