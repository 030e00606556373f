#pragma once
/// @file Clearance of planned capture poses (CONTRACT.md "Capture sequences"): a camera keeps
/// captures.clearance from every solid collision proxy, and its eye keeps
/// captures.aerial_crown_clearance (aerial) or captures.ground_crown_clearance (ground) from every
/// tree crown. Pure functions of the placed objects.
#include <memory>
#include <mutex>
#include <vector>

#include "world/chunk_cache.hpp"
#include "world/chunk_content.hpp"
#include "world/world_context.hpp"

namespace silva::world {

struct PlacedProxy;

/// An asset's crown (its tree-canopy parts at full detail) in object space, scale 1: the largest
/// horizontal distance of a canopy vertex from the object's vertical axis, per height band.
struct CrownProfile {
  float z_min = 0;            ///< Bottom of the lowest band (m).
  float band = 0;             ///< Band height (m).
  std::vector<float> radius;  ///< Per band, bottom up; empty when the asset has no crown.
};

/// Farthest a built-in tree's crown reaches from its trunk axis at scale 1, metres (the widest
/// oaks are 28 m across): how far around a pose a probe looks for crowns.
inline constexpr double kMaxCrownReach = 15.0;

/// Crown profiles of a library's assets by asset index, each computed from the asset's
/// full-detail mesh when first asked (so only trees near an aerial pose have their meshes made).
class CrownProfiles {
 public:
  /// Profiles of `library`'s assets (which must outlive this).
  explicit CrownProfiles(const assets::AssetLibrary& library);
  /// The profile of asset `asset` (empty radius: no crown); thread-safe.
  const CrownProfile& operator[](size_t asset) const;

 private:
  const assets::AssetLibrary* library_;
  std::unique_ptr<std::once_flag[]> once_;
  mutable std::vector<CrownProfile> profiles_;
};

/// The solid objects and crowns near a point, gathered once so that a search over candidate
/// poses around it tests each candidate cheaply.
class ClearanceProbe {
 public:
  /// Objects of `chunks` that can come within the clearances of a camera less than `radius`
  /// horizontally from (x, y). `crowns` must outlive the probe.
  ClearanceProbe(const WorldContext& ctx, const CrownProfiles& crowns,
                 const std::vector<std::shared_ptr<const ChunkContent>>& chunks, double x, double y, double radius);
  /// Horizontal distance around a pose whose chunks a probe of search radius `radius` needs.
  static double reach(const WorldContext& ctx, double radius);
  /// The probe of search radius `radius` around (x, y) over the chunks it needs, taken from `chunks`.
  static ClearanceProbe around(const WorldContext& ctx, ChunkSource& chunks, const CrownProfiles& crowns, double x,
                               double y, double radius);
  /// True when a camera at `eye` keeps the clearances: a ground camera's column (from the ground
  /// to the eye) and an aerial camera's eye keep captures.clearance from every solid proxy, and the
  /// eye keeps captures.aerial_crown_clearance (aerial) or captures.ground_crown_clearance (ground)
  /// from every crown.
  bool clear(const Vec3d& eye, bool aerial) const;
  /// True when a walker's column (ground up to `eye`) keeps captures.clearance from every solid
  /// proxy; crowns are walked through (silva view's walk mode).
  bool column_clear(const Vec3d& eye) const;
  /// The first nearby object whose solid proxy meets a sphere of radius `radius` about `point`, if any.
  const Vegetation* solid_at(const Vec3d& point, double radius) const;
  /// Top of the canopy over (x, y): the highest crown band of a nearby tree whose crown reaches within
  /// `margin` horizontally of (x, y), in world z; -infinity when no crown does.
  double canopy_top(double x, double y, double margin) const;

 private:
  /// True when the camera shape (column or sphere) at `eye` keeps captures.clearance from every solid proxy.
  bool solids_clear(const Vec3d& eye, bool aerial) const;
  /// The first nearby object whose solid proxy meets `shape` (within `reach` horizontally of `centre`), if any.
  const Vegetation* touched_solid(const PlacedProxy& shape, const Vec3d& centre, double reach) const;
  /// True when a sphere of radius `r` about `eye` meets the crown of object `v`.
  bool near_crown(const Vegetation& v, const Vec3d& eye, double r) const;

  const WorldContext& ctx_;                  ///< Config, terrain and library.
  const CrownProfiles& crowns_;  ///< Crown profile per asset.
  std::vector<Vegetation> solids_;  ///< Nearby objects with a solid proxy.
  std::vector<Vegetation> crowned_;  ///< Nearby trees (objects that may have a crown).
};

}  // namespace silva::world
