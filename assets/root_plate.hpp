#pragma once
/// @file The root plate of a wind-thrown tree: the disc of soil and roots the falling trunk tore out
/// of the ground, standing on edge at the trunk's base.
#include "assets/mesh_builder.hpp"
#include "core/rng.hpp"

namespace silva::assets {

/// Where and how large a root plate is.
struct RootPlateSize {
  float front_x = 0;       ///< x of the plate's front face (the old forest floor, facing +x along the trunk).
  float radius = 1;        ///< Mean radius of its outline (m).
  float trunk_radius = 0;  ///< Radius of the trunk at its base (m): sets the roots' thickness.
};

/// Bounds of the outline's radius relative to RootPlateSize::radius (the lobes of the soil disc).
inline constexpr float kRootPlateMinLobe = 0.7f, kRootPlateMaxLobe = 1.3f;

/// Adds a root plate facing +x: a lumpy, lobed lens of soil (Material::Soil) whose front face is the
/// old forest floor (moss or litter), soil-caked roots leaving its rim and curving back and down,
/// torn root ends on its back face, and soil clods fallen at its foot. Every part is Role::Obstacle.
void add_root_plate(MeshBuilder& b, Rng& rng, const RootPlateSize& size);

}  // namespace silva::assets
