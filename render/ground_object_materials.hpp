#pragma once
/// @file Procedural albedo of forest-floor objects: rocks (moss on up-facing faces, lichen
/// patches), fallen bark (moss on top), broken wood, moss cushions and leaf litter. Moss follows
/// the world normal, so it sits on top of an object however it was placed.
#include "render/materials.hpp"

namespace silva::render {

/// Rock: grey with speckle and mineral banding, lichen patches by noise, moss where the normal faces up.
Vec3f rock_albedo(const SurfacePoint& s);

/// Bark of logs, stumps and fallen sticks: furrows along the grain (uv.y), moss on upward faces.
Vec3f log_bark_albedo(const SurfacePoint& s);

/// Pale splintered wood of broken ends, with fibre grain.
Vec3f broken_wood_albedo(const SurfacePoint& s);

/// Moss cushions: yellow-green with fine mottling and a per-instance tint.
Vec3f moss_albedo(const SurfacePoint& s);

/// Fallen leaves: browns, ochres and dark decayed patches.
Vec3f leaf_litter_albedo(const SurfacePoint& s);

/// Bare soil: dark humus with paler mineral patches, crumbs and a few small stones (3D noise, so
/// the torn faces of root plates show no streaks).
Vec3f soil_albedo(const SurfacePoint& s);

}  // namespace silva::render
