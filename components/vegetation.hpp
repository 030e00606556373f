#pragma once
/// @file Placed objects (trees, dead trees, stumps, shrubs, rocks, logs, grass, ferns).
#include <cstdint>

#include "core/ontology.hpp"
#include "ecs/entity.hpp"
#include "core/types.hpp"

namespace silva {

/// How an object came to stand where it is (thesis Fig 4.5: correct / adjusted placement).
enum class Placement : uint8_t { Correct = 0, Adjusted = 1 };

/// One placed object: an asset variant at a world position, turned by yaw, uniformly scaled.
/// Object-to-world: p_world = position + Rz(yaw) * (scale * p_object).
struct Vegetation {
  uint32_t asset = 0;          ///< Index into the asset library.
  Role role = Role::Obstacle;  ///< Class of the object node (the asset's role).
  Placement placement = Placement::Correct;  ///< Correct or adjusted by overlap resolution.
  Vec3f position = Vec3f::Zero();  ///< Ground contact point (world, metres, on the terrain).
  float yaw = 0;               ///< Rotation about +Z, radians.
  float scale = 1;             ///< Uniform scale.
  uint32_t instance_id = 0;    ///< Packed instance id (0 for ground vegetation: stuff).
};

/// Vegetation entity component: the chunk entity the object belongs to (despawned with it).
struct VegetationOf {
  ecs::Entity chunk;  ///< Owning chunk entity.
};

}  // namespace silva
