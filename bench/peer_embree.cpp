/// @file Embree 3 visibility peer (see peer_embree.hpp).
#include "bench/peer_embree.hpp"

#include <stdexcept>
#include <string>
#include <vector>

#include <embree3/rtcore.h>
#include <tbb/blocked_range2d.h>
#include <tbb/parallel_for.h>

#include "core/stopwatch.hpp"

namespace silva::bench {

namespace {

/// Side of the square ray packets (kPacket^2 = 16 rays, rtcIntersect16).
constexpr int kPacket = 4;

/// What the alpha filter of one masked part needs.
struct MaskedPart {
  const Mesh* mesh = nullptr;       ///< The mesh (uvs, indices).
  uint32_t first_triangle = 0;      ///< The part's first triangle in the mesh.
  const AlphaMask* mask = nullptr;  ///< The part's mask.
};

/// Intersection filter: rejects hits where the part's mask is transparent (nearest texel, repeat).
void alpha_filter(const RTCFilterFunctionNArguments* args) {
  const auto* part = static_cast<const MaskedPart*>(args->geometryUserPtr);
  for (unsigned i = 0; i < args->N; ++i) {
    if (args->valid[i] != -1) continue;
    const uint32_t t = part->first_triangle + RTCHitN_primID(args->hit, args->N, i);
    const double b1 = RTCHitN_u(args->hit, args->N, i), b2 = RTCHitN_v(args->hit, args->N, i);
    const uint32_t* idx = &part->mesh->indices[size_t(t) * 3];
    const Vec2f &uv0 = part->mesh->uvs[idx[0]], &uv1 = part->mesh->uvs[idx[1]], &uv2 = part->mesh->uvs[idx[2]];
    const double u = double(uv0.x()) + b1 * double(uv1.x() - uv0.x()) + b2 * double(uv2.x() - uv0.x());
    const double v = double(uv0.y()) + b1 * double(uv1.y() - uv0.y()) + b2 * double(uv2.y() - uv0.y());
    if (!part->mask->opaque(float(u), float(v))) args->valid[i] = 0;
  }
}

/// Throws with Embree's last error when `ok` is false.
void check(RTCDevice device, bool ok, const char* what) {
  if (ok && rtcGetDeviceError(device) == RTC_ERROR_NONE) return;
  throw std::runtime_error(std::string("embree peer: ") + what + " failed");
}

}  // namespace

struct EmbreePeer::Impl {
  PeerView view;
  RTCDevice device = nullptr;
  std::vector<RTCScene> mesh_scenes;                   // one BVH per mesh
  std::vector<std::vector<uint32_t>> part_first;       // per mesh, per part (= geomID): first triangle
  std::vector<std::unique_ptr<MaskedPart>> masked;     // filter user data
  RTCScene top = nullptr;                              // instances (geomID = scene instance index)
  double setup_ms = 0;

  /// Builds the BVH of one mesh: a triangle geometry per part.
  RTCScene build_mesh(const Mesh& mesh, std::vector<uint32_t>& first) {
    RTCScene s = rtcNewScene(device);
    for (const MeshPart& part : mesh.parts) {
      RTCGeometry g = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
      auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                                            3 * sizeof(float), mesh.positions.size()));
      check(device, v != nullptr, "vertex buffer");
      for (size_t k = 0; k < mesh.positions.size(); ++k)
        for (int c = 0; c < 3; ++c) v[3 * k + size_t(c)] = mesh.positions[k][c];
      const size_t tris = part.index_count / 3;
      auto* ix = static_cast<uint32_t*>(
          rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(uint32_t), tris));
      check(device, ix != nullptr, "index buffer");
      std::copy_n(mesh.indices.begin() + part.first_index, part.index_count, ix);
      if (part.mask) {
        masked.push_back(std::make_unique<MaskedPart>(MaskedPart{&mesh, part.first_index / 3, part.mask.get()}));
        rtcSetGeometryUserData(g, masked.back().get());
        rtcSetGeometryIntersectFilterFunction(g, alpha_filter);
      }
      rtcCommitGeometry(g);
      rtcAttachGeometry(s, g);
      rtcReleaseGeometry(g);
      first.push_back(part.first_index / 3);
    }
    rtcCommitScene(s);
    check(device, true, "mesh BVH build");
    return s;
  }

  /// Builds every BVH.
  void build() {
    const Stopwatch clock;
    device = rtcNewDevice(nullptr);
    if (!device) throw std::runtime_error("embree peer: rtcNewDevice failed");
    const render::Scene& scene = *view.scene;
    part_first.resize(scene.meshes.size());
    for (size_t m = 0; m < scene.meshes.size(); ++m) mesh_scenes.push_back(build_mesh(*scene.meshes[m].lods[0], part_first[m]));
    top = rtcNewScene(device);
    for (size_t i = 0; i < scene.instances.size(); ++i) {
      const render::Instance& inst = scene.instances[i];
      RTCGeometry g = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_INSTANCE);
      rtcSetGeometryInstancedScene(g, mesh_scenes[inst.mesh]);
      rtcSetGeometryTransform(g, 0, RTC_FORMAT_FLOAT3X4_COLUMN_MAJOR, inst.object_to_world.data());
      rtcCommitGeometry(g);
      rtcAttachGeometryByID(top, g, unsigned(i));
      rtcReleaseGeometry(g);
    }
    rtcCommitScene(top);
    check(device, true, "top-level BVH build");
    setup_ms = 1000 * clock.seconds();
  }

  /// Traces the rays of one kPacket x kPacket block whose upper-left pixel is (x0, y0).
  void trace_packet(int x0, int y0, RTCIntersectContext& ctx, PeerFrame& out) const {
    const Camera& cam = *view.camera;
    const Mat3d r = cam.camera_to_world.block<3, 3>(0, 0);
    const Vec3d o = cam.position();
    RTCRayHit16 rh;
    alignas(64) int valid[16];
    for (int k = 0; k < 16; ++k) {
      const int x = x0 + k % kPacket, y = y0 + k / kPacket;
      valid[k] = x < cam.width && y < cam.height ? -1 : 0;
      const Vec3d d = r * Vec3d((double(x) + 0.5 - cam.cx) / cam.fx, (double(y) + 0.5 - cam.cy) / cam.fy, 1.0);
      rh.ray.org_x[k] = float(o.x());
      rh.ray.org_y[k] = float(o.y());
      rh.ray.org_z[k] = float(o.z());
      rh.ray.dir_x[k] = float(d.x());
      rh.ray.dir_y[k] = float(d.y());
      rh.ray.dir_z[k] = float(d.z());
      rh.ray.tnear[k] = float(cam.near);  // the direction has camera z = 1, so t is camera z
      rh.ray.tfar[k] = float(cam.far);
      rh.ray.time[k] = 0.0f;
      rh.ray.mask[k] = ~0u;
      rh.ray.id[k] = unsigned(k);
      rh.ray.flags[k] = 0;
      rh.hit.geomID[k] = RTC_INVALID_GEOMETRY_ID;
      rh.hit.instID[0][k] = RTC_INVALID_GEOMETRY_ID;
    }
    rtcIntersect16(valid, top, &ctx, &rh);
    for (int k = 0; k < 16; ++k) {
      if (!valid[k] || rh.hit.geomID[k] == RTC_INVALID_GEOMETRY_ID) continue;
      const size_t p = size_t(y0 + k / kPacket) * size_t(cam.width) + size_t(x0 + k % kPacket);
      const unsigned inst = rh.hit.instID[0][k];
      out.depth[p] = rh.ray.tfar[k];
      out.instance[p] = inst;
      out.triangle[p] = part_first[view.scene->instances[inst].mesh][rh.hit.geomID[k]] + rh.hit.primID[k];
    }
  }
};

EmbreePeer::EmbreePeer(const PeerView& view) : impl_(std::make_unique<Impl>()) {
  impl_->view = view;
  impl_->build();
}

EmbreePeer::~EmbreePeer() {
  if (impl_->top) rtcReleaseScene(impl_->top);
  for (RTCScene s : impl_->mesh_scenes) rtcReleaseScene(s);
  if (impl_->device) rtcReleaseDevice(impl_->device);
}

void EmbreePeer::render(PeerFrame& out) const {
  const Camera& cam = *impl_->view.camera;
  if (out.width != cam.width || out.height != cam.height) out.resize(cam.width, cam.height);
  std::fill(out.instance.begin(), out.instance.end(), render::kNoInstance);
  std::fill(out.depth.begin(), out.depth.end(), 0.0f);
  std::fill(out.triangle.begin(), out.triangle.end(), 0u);
  const int bw = (cam.width + kPacket - 1) / kPacket, bh = (cam.height + kPacket - 1) / kPacket;
  tbb::parallel_for(tbb::blocked_range2d<int>(0, bh, 4, 0, bw, 8), [&](const tbb::blocked_range2d<int>& r) {
    RTCIntersectContext ctx;
    rtcInitIntersectContext(&ctx);
    ctx.flags = RTC_INTERSECT_CONTEXT_FLAG_COHERENT;
    for (int by = r.rows().begin(); by < r.rows().end(); ++by)
      for (int bx = r.cols().begin(); bx < r.cols().end(); ++bx) impl_->trace_packet(bx * kPacket, by * kPacket, ctx, out);
  });
}

double EmbreePeer::setup_ms() const { return impl_->setup_ms; }

}  // namespace silva::bench
