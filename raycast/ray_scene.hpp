#pragma once
/// @file An Embree 3 ray-cast scene of the streamed world: one BVH per full-detail mesh, instances on
/// top, alpha-masked parts through an intersection filter; instances come and go in groups (chunks).
#include <cstdint>
#include <functional>
#include <limits>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "core/material.hpp"
#include "core/mesh.hpp"
#include "core/ontology.hpp"
#include "core/types.hpp"

namespace silva::raycast {

/// One placed copy of a mesh, as the ray caster sees it.
struct RayInstance {
  const Mesh* mesh = nullptr;                        ///< Full-detail mesh; must outlive the group holding it.
  Affine3f object_to_world = Affine3f::Identity();   ///< [R|t], may include uniform scale.
  uint32_t instance_id = 0;                          ///< Packed instance id (0 = stuff).
  /// The instance is invisible to a cast whose eye lies farther than this from `anchor` (the
  /// renderer's ground-cover cut-off); infinity: always visible.
  double cutoff = std::numeric_limits<double>::infinity();
  Vec3f anchor = Vec3f::Zero();                      ///< Point `cutoff` is measured from.
  uint32_t tag = 0;                                  ///< The caller's own number, returned with its hits.
};

/// One ray: points origin + t * direction for t in [t_near, t_far].
struct Ray {
  Vec3d origin = Vec3d::Zero();     ///< Start (world metres).
  Vec3d direction = Vec3d::UnitX(); ///< Direction; t is in units of its length.
  double t_near = 0.0;              ///< Nearest t accepted.
  double t_far = std::numeric_limits<double>::infinity();  ///< Farthest t accepted.
};

/// The nearest surface a ray met, with the labels the rasteriser gives the same surface point.
struct RayHit {
  bool hit = false;                    ///< False: nothing within [t_near, t_far].
  float t = 0.0f;                      ///< Ray parameter of the hit.
  Vec3f position = Vec3f::Zero();      ///< World position.
  Vec3f normal = Vec3f::Zero();        ///< Unit interpolated normal (world), turned to face the ray.
  Vec3f geometric_normal = Vec3f::Zero();  ///< Unit triangle normal (world), turned to face the ray.
  Role role = Role::Background;        ///< Class role (the trail painted into the terrain included).
  Material material = Material::Ground;  ///< Surface material (the trail's where its overlay paints it).
  uint32_t instance_id = 0;            ///< Packed instance id of the hit instance (0 = stuff).
  uint32_t tag = 0;                    ///< RayInstance::tag of the hit instance.
  uint32_t triangle = 0;               ///< Triangle index within the instance's mesh.
};

/// What every cast of a batch shares.
struct CastOptions {
  Vec3d eye = Vec3d::Zero();  ///< Viewpoint the RayInstance cut-offs are measured from.
  bool normals = true;        ///< Fill RayHit::normal; false leaves it zero (the geometric normal is always filled).
  /// Alpha-test masked parts at barycentrics recomputed in double from the caller's ray, as precise
  /// as the rasteriser's, so both pick the same texel where a ray meets a texel edge; false: from
  /// Embree's float barycentrics (faster).
  bool exact_masks = false;
};

/// Sets the Embree device configuration of scenes made without one (empty, the start: Embree's own
/// defaults); call before any scene is made.
void set_default_device_config(std::string device_config);

/// The ray-cast scene. Groups of instances (one per chunk) are added and removed by key; commit()
/// rebuilds the top-level BVH, and a mesh's BVH is built when a group first uses it and released
/// when no group does. Casting is thread-safe after commit(); a ray's result depends only on the
/// committed instances, never on the thread count, nor on whether Embree runs its AVX-512 or AVX2
/// kernels (a hit's distance and barycentrics are recomputed in double).
class RayScene {
 public:
  /// An empty scene on a new Embree device, configured by `device_config` (Embree's
  /// rtcNewDevice string, e.g. "isa=avx2" to limit its kernels to AVX2; empty: the process's
  /// default, set_default_device_config).
  explicit RayScene(const std::string& device_config = {});
  /// Releases the BVHs and the device.
  ~RayScene();
  RayScene(const RayScene&) = delete;
  RayScene& operator=(const RayScene&) = delete;

  /// Adds the instances of group `key` (replacing an earlier group of that key).
  void add_group(uint64_t key, std::span<const RayInstance> instances);
  /// Removes group `key` (nothing when absent).
  void remove_group(uint64_t key);
  /// True when group `key` is in the scene.
  bool has_group(uint64_t key) const;
  /// Keys of the groups in the scene, ascending.
  std::vector<uint64_t> group_keys() const;
  /// Rebuilds the top-level BVH over the groups' instances; call before casting.
  void commit();

  /// Instances in the scene.
  size_t instance_count() const;
  /// Distinct meshes with a BVH.
  size_t mesh_count() const;

  /// Casts one ray.
  RayHit cast(const Ray& ray, const CastOptions& options = {}) const;
  /// Casts `rays` into `hits` (same size) in parallel on TBB, in packets of 16 consecutive rays.
  void cast(std::span<const Ray> rays, std::span<RayHit> hits, const CastOptions& options = {}) const;

  /// Makes ray i of a batch.
  using RayMaker = std::function<Ray(size_t)>;
  /// Receives ray i's hit (a miss has hit == false).
  using HitTaker = std::function<void(size_t, const Ray&, const RayHit&)>;
  /// Casts rays 0 .. count-1, made by `make` when their packet (16 consecutive indices) is cast and
  /// handed with their hits to `take`, in parallel on TBB with no array of rays or hits: `make` and
  /// `take` run concurrently for different i. Rays that travel together belong in one packet.
  void cast_each(size_t count, const RayMaker& make, const HitTaker& take, const CastOptions& options = {}) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace silva::raycast
