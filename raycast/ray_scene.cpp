/// @file The Embree 3 ray-cast scene (see ray_scene.hpp).
#include "raycast/ray_scene.hpp"

#include <array>
#include <cmath>
#include <map>
#include <stdexcept>
#include <string>
#include <unordered_map>
#include <utility>

#include <embree3/rtcore.h>
#include <tbb/parallel_for.h>

#include "core/alpha_bits.hpp"
#include "core/surface_overlay.hpp"

namespace silva::raycast {

namespace {

/// Rays per Embree packet (rtcIntersect16).
constexpr size_t kPacket = 16;

/// One part of a mesh: Embree geometry `geomID` of the mesh's BVH.
struct PartInfo {
  const Mesh* mesh = nullptr;      ///< The mesh (uvs, indices).
  const MeshPart* part = nullptr;  ///< The part (role, material, mask, overlay).
  uint32_t first_triangle = 0;     ///< The part's first triangle in the mesh.
  bool cutoff = false;             ///< Instances of the mesh may carry a cut-off (the filter checks it).
  std::vector<std::array<Vec2f, 3>> corner_uvs;  ///< Masked part: its triangles' corner uvs, side by side for the filter.
  std::shared_ptr<const AlphaBits> mask_bits;  ///< Masked part: its mask's opacity bits (what the filter samples).
};

/// The BVH of one mesh and what its parts' filters read.
struct MeshEntry {
  RTCScene scene = nullptr;                      ///< One triangle geometry per part.
  std::vector<std::unique_ptr<PartInfo>> parts;  ///< Per part (= geomID); stable filter user data.
  bool cutoff_filter = false;                    ///< Every part runs the filter (some instance has a cut-off).
  int users = 0;                                 ///< Instances in the scene that draw it.
};

/// A placed instance: Embree geometry `geomID` of the top-level scene.
struct Placed {
  const Mesh* mesh = nullptr;                       ///< Its mesh (key of the mesh BVH).
  const MeshEntry* entry = nullptr;                 ///< Its mesh BVH's entry (parts by geomID).
  Affine3f object_to_world = Affine3f::Identity();  ///< Its transform.
  uint32_t instance_id = 0;                         ///< Packed instance id.
  double cutoff = std::numeric_limits<double>::infinity();  ///< Visible from eyes closer than this to anchor.
  Vec3d anchor = Vec3d::Zero();                     ///< Where cutoff is measured from.
  uint32_t tag = 0;                                 ///< RayInstance::tag.
};

/// The intersect context of a cast: Embree's, then what the filter needs (Embree passes it through).
struct CastContext {
  RTCIntersectContext rtc;                   ///< Must come first.
  const std::vector<Placed>* placed = nullptr;  ///< Instances by top-level geomID.
  Vec3d eye = Vec3d::Zero();                 ///< Where cut-offs are measured from.
  const Ray* rays = nullptr;  ///< CastOptions::exact_masks: the packet's rays by Embree ray id; else null.
};

/// Sets t and (b1, b2) to where `ray` meets the plane of triangle `tri` of the part placed as `inst`: the ray
/// parameter and the barycentrics, in double (Moller-Trumbore on the world-space corners, as the rasteriser's
/// barycentric planes), so they depend on the triangle and the ray alone, not on which of Embree's SIMD kernels
/// found the hit; leaves them when the ray runs parallel to the plane.
void exact_intersection(const PartInfo& p, const Placed& inst, uint32_t tri, const Ray& ray, double& t, double& b1,
                        double& b2) {
  const uint32_t* idx = &p.mesh->indices[size_t(p.first_triangle + tri) * 3];
  const Eigen::Matrix<double, 3, 4> m = inst.object_to_world.cast<double>();
  const auto corner = [&](int c) { return Vec3d(m.leftCols<3>() * p.mesh->positions[idx[c]].cast<double>() + m.col(3)); };
  const Vec3d p0 = corner(0), e1 = corner(1) - p0, e2 = corner(2) - p0;
  const Vec3d pv = ray.direction.cross(e2), s = ray.origin - p0, qv = s.cross(e1);
  const double det = e1.dot(pv);
  if (det == 0.0) return;
  t = e2.dot(qv) / det;
  b1 = s.dot(pv) / det;
  b2 = ray.direction.dot(qv) / det;
}

/// True when the part's alpha mask is opaque at barycentrics (b1, b2) of its triangle t (nearest
/// texel, repeat wrap, as the rasteriser samples it; read from the mask's bits).
bool mask_opaque(const PartInfo& p, uint32_t t, double b1, double b2) {
  const std::array<Vec2f, 3>& uv = p.corner_uvs[t];
  const double u = double(uv[0].x()) + b1 * double(uv[1].x() - uv[0].x()) + b2 * double(uv[2].x() - uv[0].x());
  const double v = double(uv[0].y()) + b1 * double(uv[1].y() - uv[0].y()) + b2 * double(uv[2].y() - uv[0].y());
  return p.mask_bits->opaque(float(u), float(v));
}

/// Intersection filter: rejects hits on transparent texels of a masked part and hits on instances
/// cut off from the cast's eye.
void hit_filter(const RTCFilterFunctionNArguments* args) {
  const auto* part = static_cast<const PartInfo*>(args->geometryUserPtr);
  const auto* ctx = reinterpret_cast<const CastContext*>(args->context);
  for (unsigned i = 0; i < args->N; ++i) {
    if (args->valid[i] != -1) continue;
    if (part->cutoff) {
      const Placed& inst = (*ctx->placed)[RTCHitN_instID(args->hit, args->N, i, 0)];
      if (std::isfinite(inst.cutoff) && (inst.anchor - ctx->eye).norm() > inst.cutoff) {
        args->valid[i] = 0;
        continue;
      }
    }
    if (!part->part->mask) continue;
    const uint32_t t = RTCHitN_primID(args->hit, args->N, i);
    double b1 = RTCHitN_u(args->hit, args->N, i), b2 = RTCHitN_v(args->hit, args->N, i), plane_t = 0.0;
    if (ctx->rays)
      exact_intersection(*part, (*ctx->placed)[RTCHitN_instID(args->hit, args->N, i, 0)], t,
                         ctx->rays[RTCRayN_id(args->ray, args->N, i)], plane_t, b1, b2);
    if (!mask_opaque(*part, t, b1, b2)) args->valid[i] = 0;
  }
}

}  // namespace

struct RayScene::Impl {
  RTCDevice device = nullptr;
  RTCScene top = nullptr;
  std::unordered_map<const Mesh*, MeshEntry> meshes;
  std::vector<Placed> placed;                         // by top-level geomID
  std::map<uint64_t, std::vector<unsigned>> groups;   // key -> top-level geomIDs
  /// Opacity bits by mask, shared by every part that uses the mask; each entry keeps its mask alive,
  /// so a cached address is never reused by another mask.
  std::unordered_map<const AlphaMask*, std::pair<std::shared_ptr<const AlphaMask>, std::shared_ptr<const AlphaBits>>>
      mask_bits;

  /// The opacity bits of `mask`, built on first use.
  std::shared_ptr<const AlphaBits> bits_of(const std::shared_ptr<const AlphaMask>& mask) {
    auto& entry = mask_bits[mask.get()];
    if (!entry.second) entry = {mask, std::make_shared<const AlphaBits>(AlphaBits::of(*mask))};
    return entry.second;
  }

  /// Throws with `what` when Embree reports an error.
  void check(const char* what) const {
    const RTCError e = rtcGetDeviceError(device);
    if (e != RTC_ERROR_NONE) throw std::runtime_error(std::string("ray caster: ") + what + " failed (Embree error " + std::to_string(int(e)) + ")");
  }

  /// Builds the BVH of `mesh`: a triangle geometry per part, filtered when masked or `cutoff`.
  MeshEntry build_mesh(const Mesh& mesh, bool cutoff) {
    MeshEntry e;
    e.cutoff_filter = cutoff;
    e.scene = rtcNewScene(device);
    rtcSetSceneFlags(e.scene, RTC_SCENE_FLAG_ROBUST);
    rtcSetSceneBuildQuality(e.scene, RTC_BUILD_QUALITY_HIGH);
    for (const MeshPart& part : mesh.parts) {
      RTCGeometry g = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
      auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                                            3 * sizeof(float), mesh.positions.size()));
      if (!v) check("vertex buffer");
      for (size_t k = 0; k < mesh.positions.size(); ++k)
        for (int c = 0; c < 3; ++c) v[3 * k + size_t(c)] = mesh.positions[k][c];
      const size_t tris = part.index_count / 3;
      auto* ix = static_cast<uint32_t*>(
          rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(uint32_t), tris));
      if (!ix) check("index buffer");
      std::copy_n(mesh.indices.begin() + part.first_index, part.index_count, ix);
      e.parts.push_back(std::make_unique<PartInfo>(PartInfo{&mesh, &part, part.first_index / 3, cutoff, {}, {}}));
      if (part.mask) {
        e.parts.back()->mask_bits = bits_of(part.mask);
        e.parts.back()->corner_uvs.resize(tris);
        for (size_t t = 0; t < tris; ++t)
          for (size_t c = 0; c < 3; ++c) e.parts.back()->corner_uvs[t][c] = mesh.uvs[ix[3 * t + c]];
      }
      rtcSetGeometryUserData(g, e.parts.back().get());
      if (part.mask || cutoff) rtcSetGeometryIntersectFilterFunction(g, hit_filter);
      rtcCommitGeometry(g);
      rtcAttachGeometry(e.scene, g);
      rtcReleaseGeometry(g);
    }
    rtcCommitScene(e.scene);
    check("mesh BVH build");
    return e;
  }

  /// The BVH entry of `mesh`, built (or rebuilt with the cut-off filter) as needed.
  MeshEntry& mesh_entry(const Mesh& mesh, bool cutoff) {
    auto it = meshes.find(&mesh);
    if (it != meshes.end() && (it->second.cutoff_filter || !cutoff)) return it->second;
    MeshEntry e = build_mesh(mesh, cutoff);
    if (it == meshes.end()) return meshes.emplace(&mesh, std::move(e)).first->second;
    // The mesh gains a cut-off: instances keep pointing at its old BVH, so repoint them.
    e.users = it->second.users;
    for (size_t id = 0; id < placed.size(); ++id)
      if (placed[id].mesh == &mesh) {
        RTCGeometry g = rtcGetGeometry(top, unsigned(id));
        rtcSetGeometryInstancedScene(g, e.scene);
        rtcCommitGeometry(g);
      }
    rtcReleaseScene(it->second.scene);
    it->second = std::move(e);
    return it->second;
  }

  /// Drops one user of `mesh`, releasing its BVH when none is left.
  void release_mesh(const Mesh* mesh) {
    auto it = meshes.find(mesh);
    if (it == meshes.end() || --it->second.users > 0) return;
    rtcReleaseScene(it->second.scene);
    meshes.erase(it);
    std::erase_if(mask_bits, [](const auto& kv) { return kv.second.second.use_count() == 1; });  // no part uses it
  }

  /// Fills `h` from an Embree hit of ray `ray` on triangle `prim`, with the distance and barycentrics
  /// recomputed by exact_intersection (Embree's float ones, `t`, `bu` and `bv`, differ in their last bits
  /// between its kernels: AVX-512, AVX2 and SSE4.2 machines would write different LiDAR ranges).
  void describe_hit(const Ray& ray, float t, unsigned inst_id, unsigned geom, unsigned prim, float bu, float bv,
                    bool normals, RayHit& h) const {
    const Placed& inst = placed[inst_id];
    const PartInfo& p = *inst.entry->parts[geom];
    const Mesh& mesh = *p.mesh;
    const uint32_t* idx = &mesh.indices[size_t(p.first_triangle + prim) * 3];
    double exact_t = t, b1 = bu, b2 = bv;
    exact_intersection(p, inst, prim, ray, exact_t, b1, b2);
    const double b0 = 1.0 - b1 - b2;
    const Mat3d lin = inst.object_to_world.block<3, 3>(0, 0).cast<double>();
    const Vec3d dir = ray.direction;
    h.hit = true;
    h.t = float(exact_t);
    const Vec3d pos = ray.origin + exact_t * dir;
    h.position = pos.cast<float>();
    const Vec3d p0 = mesh.positions[idx[0]].cast<double>(), p1 = mesh.positions[idx[1]].cast<double>(),
                p2 = mesh.positions[idx[2]].cast<double>();
    Vec3d ng = lin * (p1 - p0).cross(p2 - p0);  // uniform scale: the direction of the transformed normal
    ng = ng.norm() > 0.0 ? Vec3d(ng.normalized()) : Vec3d(-dir.normalized());
    if (ng.dot(dir) > 0.0) ng = -ng;
    h.geometric_normal = ng.cast<float>();
    if (normals) {
      Vec3d n = ng;
      if (!mesh.normals.empty()) {
        n = lin * (b0 * mesh.normals[idx[0]].cast<double>() + b1 * mesh.normals[idx[1]].cast<double>() +
                   b2 * mesh.normals[idx[2]].cast<double>());
        n = n.norm() > 0.0 ? Vec3d(n.normalized()) : ng;
        if (n.dot(dir) > 0.0) n = -n;
      }
      h.normal = n.cast<float>();
    }
    h.role = p.part->role;
    h.material = p.part->material;
    if (p.part->overlay && !mesh.uvs.empty()) {
      const float uvx = float(b0 * double(mesh.uvs[idx[0]].x()) + b1 * double(mesh.uvs[idx[1]].x()) +
                              b2 * double(mesh.uvs[idx[2]].x()));
      if (uvx < kOverlayMargin + kOverlayRagged) {
        const float edge = overlay_edge(uvx, h.position);
        if (edge < kOverlayMargin) h.material = p.part->overlay->material;
        if (overlay_weight(edge) >= 0.5f) h.role = p.part->overlay->role;
      }
    }
    h.instance_id = inst.instance_id;
    h.tag = inst.tag;
    h.triangle = p.first_triangle + prim;
  }

  /// A cast context for `options`.
  CastContext context(const CastOptions& options) const {
    CastContext ctx;
    rtcInitIntersectContext(&ctx.rtc);
    ctx.rtc.flags = RTC_INTERSECT_CONTEXT_FLAG_COHERENT;  // callers pack neighbouring rays into a packet
    ctx.placed = &placed;
    ctx.eye = options.eye;
    return ctx;
  }
};

namespace {
/// set_default_device_config's value.
std::string& default_device_config() {
  static std::string config;
  return config;
}
}  // namespace

void set_default_device_config(std::string device_config) { default_device_config() = std::move(device_config); }

RayScene::RayScene(const std::string& device_config) : impl_(std::make_unique<Impl>()) {
  const std::string& config = device_config.empty() ? default_device_config() : device_config;
  impl_->device = rtcNewDevice(config.empty() ? nullptr : config.c_str());
  if (!impl_->device) throw std::runtime_error("ray caster: rtcNewDevice failed");
  impl_->top = rtcNewScene(impl_->device);
  rtcSetSceneFlags(impl_->top, RTC_SCENE_FLAG_ROBUST);
  impl_->check("scene creation");
}

RayScene::~RayScene() {
  if (impl_->top) rtcReleaseScene(impl_->top);
  for (auto& [mesh, e] : impl_->meshes) rtcReleaseScene(e.scene);
  if (impl_->device) rtcReleaseDevice(impl_->device);
}

void RayScene::add_group(uint64_t key, std::span<const RayInstance> instances) {
  remove_group(key);
  std::vector<unsigned>& ids = impl_->groups[key];
  for (const RayInstance& r : instances) {
    if (!r.mesh || r.mesh->indices.empty()) continue;
    MeshEntry& e = impl_->mesh_entry(*r.mesh, std::isfinite(r.cutoff));
    ++e.users;
    RTCGeometry g = rtcNewGeometry(impl_->device, RTC_GEOMETRY_TYPE_INSTANCE);
    rtcSetGeometryInstancedScene(g, e.scene);
    rtcSetGeometryTransform(g, 0, RTC_FORMAT_FLOAT3X4_COLUMN_MAJOR, r.object_to_world.data());
    rtcCommitGeometry(g);
    const unsigned id = rtcAttachGeometry(impl_->top, g);
    rtcReleaseGeometry(g);
    impl_->check("instance");
    if (impl_->placed.size() <= id) impl_->placed.resize(id + 1);
    impl_->placed[id] = Placed{r.mesh, &e, r.object_to_world, r.instance_id, r.cutoff, r.anchor.cast<double>(), r.tag};
    ids.push_back(id);
  }
}

void RayScene::remove_group(uint64_t key) {
  const auto it = impl_->groups.find(key);
  if (it == impl_->groups.end()) return;
  for (const unsigned id : it->second) {
    rtcDetachGeometry(impl_->top, id);
    impl_->release_mesh(impl_->placed[id].mesh);
    impl_->placed[id] = Placed{};
  }
  impl_->groups.erase(it);
}

bool RayScene::has_group(uint64_t key) const { return impl_->groups.count(key) != 0; }

std::vector<uint64_t> RayScene::group_keys() const {
  std::vector<uint64_t> keys;
  for (const auto& [key, ids] : impl_->groups) keys.push_back(key);
  return keys;
}

void RayScene::commit() {
  rtcCommitScene(impl_->top);
  impl_->check("top-level BVH build");
}

size_t RayScene::instance_count() const {
  size_t n = 0;
  for (const auto& [key, ids] : impl_->groups) n += ids.size();
  return n;
}

size_t RayScene::mesh_count() const { return impl_->meshes.size(); }

RayHit RayScene::cast(const Ray& ray, const CastOptions& options) const {
  RayHit h;
  cast(std::span<const Ray>(&ray, 1), std::span<RayHit>(&h, 1), options);
  return h;
}

void RayScene::cast(std::span<const Ray> rays, std::span<RayHit> hits, const CastOptions& options) const {
  if (rays.size() != hits.size()) throw std::invalid_argument("ray caster: rays and hits differ in size");
  cast_each(
      rays.size(), [&](size_t i) { return rays[i]; }, [&](size_t i, const Ray&, const RayHit& h) { hits[i] = h; },
      options);
}

void RayScene::cast_each(size_t count, const RayMaker& make, const HitTaker& take, const CastOptions& options) const {
  const size_t packets = (count + kPacket - 1) / kPacket;
  tbb::parallel_for(size_t(0), packets, [&](size_t k) {
    CastContext ctx = impl_->context(options);
    const size_t first = k * kPacket, n = std::min(kPacket, count - first);
    std::array<Ray, kPacket> rays;
    if (options.exact_masks) ctx.rays = rays.data();
    RTCRayHit16 rh;
    alignas(64) int valid[kPacket];
    for (size_t j = 0; j < kPacket; ++j) {
      valid[j] = j < n ? -1 : 0;
      if (j < n) rays[j] = make(first + j);
      const Ray& r = rays[std::min(j, n - 1)];
      rh.ray.org_x[j] = float(r.origin.x());
      rh.ray.org_y[j] = float(r.origin.y());
      rh.ray.org_z[j] = float(r.origin.z());
      rh.ray.dir_x[j] = float(r.direction.x());
      rh.ray.dir_y[j] = float(r.direction.y());
      rh.ray.dir_z[j] = float(r.direction.z());
      rh.ray.tnear[j] = float(r.t_near);
      rh.ray.tfar[j] = std::isfinite(r.t_far) ? float(r.t_far) : std::numeric_limits<float>::infinity();
      rh.ray.time[j] = 0.0f;
      rh.ray.mask[j] = ~0u;
      rh.ray.id[j] = unsigned(j);
      rh.ray.flags[j] = 0;
      rh.hit.geomID[j] = RTC_INVALID_GEOMETRY_ID;
      rh.hit.instID[0][j] = RTC_INVALID_GEOMETRY_ID;
    }
    rtcIntersect16(valid, impl_->top, &ctx.rtc, &rh);
    for (size_t j = 0; j < n; ++j) {
      RayHit h;
      if (rh.hit.geomID[j] != RTC_INVALID_GEOMETRY_ID)
        impl_->describe_hit(rays[j], rh.ray.tfar[j], rh.hit.instID[0][j], rh.hit.geomID[j], rh.hit.primID[j],
                            rh.hit.u[j], rh.hit.v[j], options.normals, h);
      take(first + j, rays[j], h);
    }
  });
}

}  // namespace silva::raycast
