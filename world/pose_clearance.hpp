#pragma once
/// @file Clearance of planned capture poses (CONTRACT.md "Capture sequences"): a camera keeps
/// captures.clearance from every solid collision proxy, and an aerial camera also keeps
/// captures.aerial_crown_clearance from every tree crown. Pure functions of the placed objects.
#include <memory>
#include <vector>

#include "world/chunk_content.hpp"
#include "world/world_context.hpp"

namespace silva::world {

/// An asset's crown (its tree-canopy parts at full detail) in object space, scale 1: the largest
/// horizontal distance of a canopy vertex from the object's vertical axis, per height band.
struct CrownProfile {
  float z_min = 0;            ///< Bottom of the lowest band (m).
  float band = 0;             ///< Band height (m).
  std::vector<float> radius;  ///< Per band, bottom up; empty when the asset has no crown.
};

/// Crown profiles of every asset of `library`, by asset index.
std::vector<CrownProfile> crown_profiles(const assets::AssetLibrary& library);

/// The solid objects and crowns near a point, gathered once so that a search over candidate
/// poses around it tests each candidate cheaply.
class ClearanceProbe {
 public:
  /// Objects of `chunks` that can come within the clearances of a camera less than `radius`
  /// horizontally from (x, y). `crowns` (from crown_profiles) must outlive the probe.
  ClearanceProbe(const WorldContext& ctx, const std::vector<CrownProfile>& crowns,
                 const std::vector<std::shared_ptr<const ChunkContent>>& chunks, double x, double y, double radius);
  /// Horizontal distance around a pose whose chunks a probe of search radius `radius` needs.
  static double reach(const WorldContext& ctx, const std::vector<CrownProfile>& crowns, double radius);
  /// True when a camera at `eye` keeps the clearances: a ground camera's column (from the ground
  /// to the eye) and an aerial camera's eye keep captures.clearance from every solid proxy, and an
  /// aerial eye keeps captures.aerial_crown_clearance from every crown.
  bool clear(const Vec3d& eye, bool aerial) const;

 private:
  /// True when a sphere of radius `r` about `eye` meets the crown of object `v`.
  bool near_crown(const Vegetation& v, const Vec3d& eye, double r) const;

  const WorldContext& ctx_;                  ///< Config, terrain and library.
  const std::vector<CrownProfile>& crowns_;  ///< Crown profile per asset.
  std::vector<Vegetation> solids_;  ///< Nearby objects with a solid proxy.
  std::vector<Vegetation> crowned_;  ///< Nearby objects with a crown.
};

}  // namespace silva::world
